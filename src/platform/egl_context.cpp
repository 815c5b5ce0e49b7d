// EGL backend placeholder until the surfaceless backend lands (issue 7).
#include <stdexcept>

#include "platform/headless.h"

namespace sl {

std::unique_ptr<HeadlessContext> createEglContext(GlslTree, int, int) {
    throw std::runtime_error("the EGL backend is not built yet; use --backend osmesa");
}

}  // namespace sl
