#include <iostream>

#include "app/commands.h"
#include "io/files.h"
#include "io/usage_error.h"
#include "scene/scene_json.h"

namespace sl {

// Messages may quote a file (a scene's keys, a path): control characters are shown as '?'.
int guarded(const std::function<int()>& body) {
    try {
        return body();
    } catch (const UsageError& e) {
        std::cerr << "shadowlab: " << printable(e.what()) << "\n";
        return kBadInput;
    } catch (const SceneError& e) {
        std::cerr << "shadowlab: scene error: " << printable(e.what()) << "\n";
        return kBadInput;
    } catch (const ShaderError& e) {
        std::cerr << "shadowlab: shader error: " << e.what();  // already printable
        if (std::string(e.what()).back() != '\n') std::cerr << "\n";
        return kBadInput;
    } catch (const std::invalid_argument& e) {
        std::cerr << "shadowlab: " << printable(e.what()) << "\n";
        return kBadInput;
    } catch (const DiskFullError& e) {  // the machine's, said as it is
        std::cerr << "shadowlab: " << printable(e.what()) << "\n";
        return kGlFailure;
    } catch (const std::exception& e) {
        std::cerr << "shadowlab: GL or platform failure: " << printable(e.what()) << "\n";
        return kGlFailure;
    }
}

}  // namespace sl
