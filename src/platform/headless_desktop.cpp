// The desktop's headless backends: OSMesa or EGL, as the environment or the build picks.
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "platform/headless.h"

namespace sl {

std::unique_ptr<HeadlessContext> createHeadlessContext(Backend backend, GlslTree tree, int width,
                                                       int height) {
    if (backend == Backend::Auto) {  // a grader can pin the backend for every run
        const char* pinned = std::getenv("SHADOWLAB_BACKEND");
        std::string p = pinned ? pinned : "";
        if (p == "osmesa") backend = Backend::OSMesa;
        if (p == "egl") backend = Backend::Egl;
    }
    if (backend == Backend::OSMesa) return createOSMesaContext(tree, width, height);
    if (backend == Backend::Egl) return createEglContext(tree, width, height);
    // Auto: OSMesa where this build has it and it works, else EGL's surfaceless platform.
    if (osmesaAvailable()) {
        try {
            return createOSMesaContext(tree, width, height);
        } catch (const std::runtime_error& osmesa) {
            try {
                return createEglContext(tree, width, height);
            } catch (const std::runtime_error& egl) {
                throw std::runtime_error(std::string(osmesa.what()) + "; and " + egl.what());
            }
        }
    }
    return createEglContext(tree, width, height);
}

}  // namespace sl
