#include <iostream>

#include "app/commands.h"
#include "scene/scene_json.h"

namespace sl {

int guarded(const std::function<int()>& body) {
    try {
        return body();
    } catch (const UsageError& e) {
        std::cerr << "shadowlab: " << e.what() << "\n";
        return kBadInput;
    } catch (const SceneError& e) {
        std::cerr << "shadowlab: scene error: " << e.what() << "\n";
        return kBadInput;
    } catch (const ShaderError& e) {
        std::cerr << "shadowlab: shader error: " << e.what();
        if (std::string(e.what()).back() != '\n') std::cerr << "\n";
        return kBadInput;
    } catch (const std::invalid_argument& e) {
        std::cerr << "shadowlab: " << e.what() << "\n";
        return kBadInput;
    } catch (const std::exception& e) {
        std::cerr << "shadowlab: GL or platform failure: " << e.what() << "\n";
        return kGlFailure;
    }
}

}  // namespace sl
