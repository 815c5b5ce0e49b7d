#include "platform/framebuffer_target.h"

#include <stdexcept>
#include <string>

#include "gl/debug.h"

namespace sl {

FramebufferTarget createFramebufferTarget(int width, int height, const char* what) {
    FramebufferTarget t;
    t.colour = Renderbuffer::create();
    glBindRenderbuffer(GL_RENDERBUFFER, t.colour.id());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    t.depthStencil = Renderbuffer::create();
    glBindRenderbuffer(GL_RENDERBUFFER, t.depthStencil.id());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    t.fbo = Framebuffer::create();
    glBindFramebuffer(GL_FRAMEBUFFER, t.fbo.id());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, t.colour.id());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                              t.depthStencil.id());
    std::string incomplete = checkFramebufferComplete(what);
    if (!incomplete.empty()) throw std::runtime_error(incomplete);
    return t;
}

}  // namespace sl
