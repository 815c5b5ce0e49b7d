// OSMesa: Mesa renders into a buffer in our memory. glad's header comes first and stands in
// for GL/gl.h, which GL/osmesa.h would otherwise pull in.
#include "platform/headless.h"

#ifdef SHADOWLAB_HAVE_OSMESA
// Mesa 22 declares OSMesa's functions GLAPIENTRY, Mesa 25 APIENTRY; glad defines neither.
#ifndef APIENTRY
#define APIENTRY GLAD_API_PTR
#endif
#ifndef GLAPIENTRY
#define GLAPIENTRY APIENTRY
#endif
#include <GL/osmesa.h>

#include <stdexcept>
#include <vector>

#include "gl/loader.h"

namespace sl {

namespace {

class OSMesaContextImpl : public HeadlessContext {
  public:
    OSMesaContextImpl(OSMesaContext ctx, int w, int h)
        : ctx_(ctx), pixels_(std::size_t(w) * h * 4) {
        width_ = w;
        height_ = h;
        if (!OSMesaMakeCurrent(ctx_, pixels_.data(), GL_UNSIGNED_BYTE, w, h))
            throw std::runtime_error("OSMesaMakeCurrent failed for a " + std::to_string(w) + "x" +
                                     std::to_string(h) + " buffer");
    }
    ~OSMesaContextImpl() override { OSMesaDestroyContext(ctx_); }
    GLuint framebuffer() const override { return 0; }
    const char* backendName() const override { return "osmesa"; }
    bool makeCurrent() override {
        return OSMesaMakeCurrent(ctx_, pixels_.data(), GL_UNSIGNED_BYTE, width_, height_);
    }

  private:
    OSMesaContext ctx_;
    std::vector<unsigned char> pixels_;
};

}  // namespace

bool osmesaAvailable() {
    return true;
}

std::unique_ptr<HeadlessContext> createOSMesaContext(GlslTree tree, int width, int height) {
    bool core = tree == GlslTree::Core;
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           24,
                           OSMESA_STENCIL_BITS,
                           8,
                           OSMESA_PROFILE,
                           core ? OSMESA_CORE_PROFILE : OSMESA_COMPAT_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           core ? 3 : 2,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           core ? 3 : 1,
                           0};
    OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!ctx)
        throw std::runtime_error(std::string("OSMesa could not create a ") +
                                 (core ? "core 3.3" : "compatibility") + " profile context");
    auto context = std::make_unique<OSMesaContextImpl>(ctx, width, height);
    OSMesaPixelStore(OSMESA_Y_UP, 1);
    if (!loadGl(reinterpret_cast<GlProcLoader>(&OSMesaGetProcAddress)))
        throw std::runtime_error("could not load GL entry points through OSMesaGetProcAddress");
    return context;
}

}  // namespace sl

#else

#include <stdexcept>

namespace sl {

bool osmesaAvailable() {
    return false;
}

std::unique_ptr<HeadlessContext> createOSMesaContext(GlslTree, int, int) {
    throw std::runtime_error(
        "this build has no OSMesa (configured with SHADOWLAB_WITH_OSMESA=OFF); "
        "use --backend egl");
}

}  // namespace sl

#endif
