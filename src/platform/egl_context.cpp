// EGL without a window: Mesa's surfaceless platform (EGL_MESA_platform_surfaceless) on the
// software device, desktop GL, rendering into a framebuffer object we own. This is the headless
// path for Mesa 25.1 and later, which no longer ship OSMesa.
#include "platform/headless.h"

#ifdef SHADOWLAB_HAVE_EGL

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <stdexcept>
#include <string>

#include "gl/debug.h"
#include "gl/handles.h"
#include "gl/loader.h"
#include "platform/framebuffer_target.h"

namespace sl {

namespace {

std::string eglFailure(const char* what) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04X", eglGetError());
    return std::string("EGL: ") + what + " failed (error " + code + ")";
}

// The display is opened and initialised once per process and never terminated: Mesa's EGL does
// not survive eglTerminate followed by a second eglInitialize in one process cleanly, and tests
// create many contexts.
EGLDisplay surfacelessDisplay() {
    static EGLDisplay display = [] {
        auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
            eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (!getPlatformDisplay)
            throw std::runtime_error(
                "EGL: eglGetPlatformDisplayEXT is missing (no EGL_EXT_platform_base)");
        EGLDisplay d =
            getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (d == EGL_NO_DISPLAY) throw std::runtime_error(eglFailure("the surfaceless display"));
        EGLint major = 0, minor = 0;
        if (!eglInitialize(d, &major, &minor))
            throw std::runtime_error(eglFailure("eglInitialize"));
        return d;
    }();
    return display;
}

class EglContextImpl : public HeadlessContext {
  public:
    EglContextImpl(EGLDisplay display, EGLContext context, int w, int h)
        : display_(display), context_(context) {
        width_ = w;
        height_ = h;
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
            std::string why = eglFailure("eglMakeCurrent without a surface");
            eglDestroyContext(display_, context_);
            throw std::runtime_error(why);
        }
    }
    // Called once the GL entry points are loaded: the colour and depth/stencil target.
    void createTarget() {
        target_ = createFramebufferTarget(width_, height_, "EGL target framebuffer");
    }
    ~EglContextImpl() override {
        // GL objects go while their context is still current; then the context itself.
        target_ = FramebufferTarget();
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
    }
    GLuint framebuffer() const override { return target_.fbo.id(); }
    const char* backendName() const override { return "egl"; }
    bool makeCurrent() override {
        return eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_);
    }

  private:
    EGLDisplay display_;
    EGLContext context_;
    FramebufferTarget target_;
};

}  // namespace

std::unique_ptr<HeadlessContext> createEglContext(GlslTree tree, int width, int height) {
    EGLDisplay display = surfacelessDisplay();
    if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error(eglFailure("eglBindAPI(OpenGL)"));
    // No surface will be made, so any surface type will do (a zero mask matches every config).
    const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, 0,
                                    EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!eglChooseConfig(display, configAttribs, &config, 1, &count) || count < 1)
        throw std::runtime_error(eglFailure("eglChooseConfig for desktop OpenGL"));
    bool core = tree == GlslTree::Core;
    const EGLint coreAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                  3,
                                  EGL_CONTEXT_MINOR_VERSION,
                                  3,
                                  EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                  EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                  EGL_NONE};
    const EGLint compatAttribs[] = {EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                    EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT, EGL_NONE};
    EGLContext context =
        eglCreateContext(display, config, EGL_NO_CONTEXT, core ? coreAttribs : compatAttribs);
    if (context == EGL_NO_CONTEXT)
        throw std::runtime_error(
            eglFailure(core ? "a core 3.3 context" : "a compatibility context"));
    auto result = std::make_unique<EglContextImpl>(display, context, width, height);
    if (!loadGl(reinterpret_cast<GlProcLoader>(&eglGetProcAddress)))
        throw std::runtime_error("could not load GL entry points through eglGetProcAddress");
    result->createTarget();
    return result;
}

}  // namespace sl

#else

#include <stdexcept>

namespace sl {

std::unique_ptr<HeadlessContext> createEglContext(GlslTree, int, int) {
    throw std::runtime_error(
        "this build has no EGL (libegl-dev was not found at configure time); "
        "use --backend osmesa");
}

}  // namespace sl

#endif
