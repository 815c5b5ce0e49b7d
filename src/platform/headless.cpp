#include "platform/headless.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace sl {

Image HeadlessContext::read() const {
    Image img(width_, height_);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    std::vector<std::uint8_t> bottomUp(img.rgba.size());
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
    std::size_t row = std::size_t(width_) * 4;
    for (int j = 0; j < height_; ++j)  // GL's row 0 is the bottom; PNG's is the top
        std::copy_n(&bottomUp[std::size_t(height_ - 1 - j) * row], row,
                    &img.rgba[std::size_t(j) * row]);
    return img;
}

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
