#include "eval/job_errors.h"

#include "gl/shader_library.h"
#include "scene/scene_json.h"
#include "stages/expectations.h"

namespace sl {

const JobErrorKinds& renderJobErrors() {
    static const JobErrorKinds kinds{[](const std::exception_ptr& error) -> std::string {
                                         try {
                                             std::rethrow_exception(error);
                                         } catch (const ShaderError&) {
                                             return "shader";
                                         } catch (const SceneError&) {
                                             return "scene";
                                         } catch (const ExpectationError&) {
                                             return "expectation";
                                         } catch (...) {
                                             return "";
                                         }
                                     },
                                     [](const std::string& kind, const std::string& what) {
                                         if (kind == "shader") throw ShaderError(what);
                                         if (kind == "scene") throw SceneError(what);
                                         if (kind == "expectation") throw ExpectationError(what);
                                     }};
    return kinds;
}

}  // namespace sl
