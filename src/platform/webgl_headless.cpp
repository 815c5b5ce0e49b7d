// The browser's headless context: a framebuffer object of the check's size in the page's own
// WebGL 2 context (one context a page: the check's renders and the lecture's picture share it,
// each pass setting the state it needs). What `check` measures in the page is drawn here.
#include <emscripten/html5.h>

#include <stdexcept>
#include <string>

#include "platform/framebuffer_target.h"
#include "platform/headless.h"

namespace sl {

namespace {

class WebGlTarget : public HeadlessContext {
  public:
    WebGlTarget(EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context, int w, int h) : context_(context) {
        width_ = w;
        height_ = h;
        target_ = createFramebufferTarget(w, h, "the check's framebuffer");
    }
    GLuint framebuffer() const override { return target_.fbo.id(); }
    const char* backendName() const override { return "webgl"; }
    bool makeCurrent() override {
        return emscripten_webgl_make_context_current(context_) == EMSCRIPTEN_RESULT_SUCCESS;
    }
    bool lost() const override { return emscripten_is_webgl_context_lost(context_); }

  private:
    EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context_;
    FramebufferTarget target_;
};

}  // namespace

std::unique_ptr<HeadlessContext> createHeadlessContext(Backend, GlslTree tree, int width,
                                                       int height) {
    if (tree != GlslTree::Core)
        throw std::runtime_error("the browser runs the core tree only (GLSL 3.30 as ESSL 3.00)");
    EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context = emscripten_webgl_get_current_context();
    if (context <= 0) throw std::runtime_error("no WebGL 2 context: the page made none");
    if (emscripten_is_webgl_context_lost(context))
        throw std::runtime_error("the WebGL context was lost (reload the page)");
    return std::make_unique<WebGlTarget>(context, width, height);
}

}  // namespace sl
