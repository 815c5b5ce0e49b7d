#include "render/mirror_pass.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "gl/debug.h"
#include "gl/state.h"

namespace sl {

namespace {

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Radius of the sphere around an object's centre that holds all of it.
float boundingRadius(const Object& o) {
    switch (o.kind) {
        case PrimitiveKind::Box:
            return 0.5f * glm::length(o.size);
        case PrimitiveKind::Sphere:
            return o.radius;
        case PrimitiveKind::Quad:
            return 0.5f * std::hypot(o.width, o.height);
    }
    return 0.0f;
}

}  // namespace

std::optional<Mirror> drawableMirror(const Mirror& m, std::string* reason) {
    auto fail = [&](const char* why) -> std::optional<Mirror> {
        if (reason) *reason = why;
        return std::nullopt;
    };
    if (!finite(m.center) || !finite(m.normal) || !finite(m.up) || !std::isfinite(m.width) ||
        !std::isfinite(m.height))
        return fail("the mirror has a non-finite centre, normal, up or size");
    if (!(m.width > 0.0f) || !(m.height > 0.0f)) return fail("the mirror has zero width or height");
    float n = glm::length(m.normal);
    if (!(n > 1e-12f)) return fail("the mirror's normal is zero");
    Mirror out = m;
    out.normal = m.normal / n;
    glm::vec3 up = m.up - glm::dot(m.up, out.normal) * out.normal;  // Gram-Schmidt
    float u = glm::length(up);
    if (!(u > 1e-6f * glm::length(m.up))) return fail("the mirror's up is parallel to its normal");
    out.up = up / u;
    return out;
}

float sceneReachInFront(const Scene& scene, const Mirror& mirror) {
    glm::vec3 n = glm::normalize(mirror.normal);
    float reach = 0.0f;
    for (const Object& o : scene.objects)
        reach = std::max(reach, glm::dot(o.center - mirror.center, n) + boundingRadius(o));
    // A little slack so the farthest point is not exactly on the far plane.
    return std::max(reach * 1.01f, 1e-3f);
}

glm::ivec2 mirrorTextureSize(int requested, glm::ivec2 footprint, int maxSide) {
    glm::ivec2 size = requested > 0 ? glm::ivec2(std::max(requested, 16)) : footprint;
    maxSide = std::max(maxSide, 1);
    return {std::clamp(size.x, 1, maxSide), std::clamp(size.y, 1, maxSide)};
}

glm::vec4 mirrorPlaneInView(const Mirror& mirror, const glm::mat4& view) {
    glm::vec3 n = glm::normalize(glm::mat3(view) * glm::normalize(mirror.normal));
    glm::vec3 p = glm::vec3(view * glm::vec4(mirror.center, 1.0f));
    return {n, -glm::dot(n, p)};
}

int stencilBits(GLuint fbo) {
    GLint previous = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo);
    GLenum attachment = fbo == 0 ? GL_STENCIL : GL_STENCIL_ATTACHMENT;
    GLint type = GL_NONE, bits = 0;
    glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, attachment,
                                          GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    // Asking an attachment that holds nothing for its size is an error: ask only when it exists.
    if (type != GL_NONE)
        glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, attachment,
                                              GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, &bits);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, previous);
    return bits;
}

void MirrorTarget::ensure(int width, int height) {
    if (fbo_ && width == width_ && height == height_) return;
    GLint maxTexture = 0, maxRenderbuffer = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTexture);
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxRenderbuffer);
    int limit = std::min(maxTexture, maxRenderbuffer);
    if (width < 1 || height < 1 || width > limit || height > limit)
        throw std::invalid_argument("mirror texture " + std::to_string(width) + "x" +
                                    std::to_string(height) + " is outside 1 to " +
                                    std::to_string(limit) + " (this driver's limit)");
    colour_ = Texture::create();
    depth_ = Renderbuffer::create();
    fbo_ = Framebuffer::create();
    width_ = width;
    height_ = height;

    glBindTexture(GL_TEXTURE_2D, colour_.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    // About one texel per pixel of the mirror on screen: bilinear, no mipmaps needed.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);

    glBindRenderbuffer(GL_RENDERBUFFER, depth_.id());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);

    ScopedFramebuffer bind(fbo_.id(), width, height);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_.id(), 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
    glDrawBuffer(GL_COLOR_ATTACHMENT0);
    std::string incomplete = checkFramebufferComplete("mirror framebuffer");
    if (!incomplete.empty()) {
        fbo_.reset();
        throw std::runtime_error(incomplete);
    }
}

ScopedFrontFace::ScopedFrontFace(GLenum mode) {
    glGetIntegerv(GL_FRONT_FACE, &mode_);
    glFrontFace(mode);
}
ScopedFrontFace::~ScopedFrontFace() {
    glFrontFace(static_cast<GLenum>(mode_));
}

ScopedStencil::ScopedStencil(GLenum func, GLint ref, GLenum fail, GLenum depthFail, GLenum pass)
    : enabled_(glIsEnabled(GL_STENCIL_TEST)) {
    const GLenum names[7] = {GL_STENCIL_FUNC,           GL_STENCIL_REF,  GL_STENCIL_VALUE_MASK,
                             GL_STENCIL_WRITEMASK,      GL_STENCIL_FAIL, GL_STENCIL_PASS_DEPTH_FAIL,
                             GL_STENCIL_PASS_DEPTH_PASS};
    for (int k = 0; k < 7; ++k) glGetIntegerv(names[k], &saved_[k]);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(func, ref, 0xFF);
    glStencilMask(0xFF);
    glStencilOp(fail, depthFail, pass);
}

ScopedStencil::~ScopedStencil() {
    glStencilFunc(static_cast<GLenum>(saved_[0]), saved_[1], static_cast<GLuint>(saved_[2]));
    glStencilMask(static_cast<GLuint>(saved_[3]));
    glStencilOp(static_cast<GLenum>(saved_[4]), static_cast<GLenum>(saved_[5]),
                static_cast<GLenum>(saved_[6]));
    enabled_ ? glEnable(GL_STENCIL_TEST) : glDisable(GL_STENCIL_TEST);
}

ScopedDepthMask::ScopedDepthMask(bool write) {
    glGetBooleanv(GL_DEPTH_WRITEMASK, &saved_);
    glDepthMask(write ? GL_TRUE : GL_FALSE);
}

ScopedBlend::ScopedBlend(GLenum src, GLenum dst) : enabled_(glIsEnabled(GL_BLEND)) {
    glGetIntegerv(GL_BLEND_SRC_RGB, &saved_[0]);
    glGetIntegerv(GL_BLEND_DST_RGB, &saved_[1]);
    glGetIntegerv(GL_BLEND_SRC_ALPHA, &saved_[2]);
    glGetIntegerv(GL_BLEND_DST_ALPHA, &saved_[3]);
    glEnable(GL_BLEND);
    glBlendFunc(src, dst);
}

ScopedBlend::~ScopedBlend() {
    glBlendFuncSeparate(static_cast<GLenum>(saved_[0]), static_cast<GLenum>(saved_[1]),
                        static_cast<GLenum>(saved_[2]), static_cast<GLenum>(saved_[3]));
    enabled_ ? glEnable(GL_BLEND) : glDisable(GL_BLEND);
}

}  // namespace sl
