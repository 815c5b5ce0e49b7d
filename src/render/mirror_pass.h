// Pieces of the mirror stage that are not the lesson itself: the render-to-texture target (a
// colour texture and a depth renderbuffer in one framebuffer object), the sizes and planes the
// passes need, and the scoped state the stencil method changes beyond gl/state.h.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "gl/handles.h"
#include "math/mirror_math.h"

namespace sl {

// The mirror as the passes draw it: finite, with area, unit normal, unit up made perpendicular
// to the normal. nullopt, with `reason` set, when it cannot be drawn at all (zero size, zero
// normal, up parallel to the normal, not finite): then the stage draws no mirror.
std::optional<Mirror> drawableMirror(const Mirror& mirror, std::string* reason = nullptr);

// How far in front of the mirror's plane the scene reaches (each object's bounding sphere):
// far' = near' + this. Objects wholly behind the mirror do not count. Always > 0.
float sceneReachInFront(const Scene& scene, const Mirror& mirror);

// The mirror texture's size: the footprint on screen when `requested` is 0, else requested x
// requested (values 1..15 count as 16); every side clamped to [1, maxSide].
glm::ivec2 mirrorTextureSize(int requested, glm::ivec2 footprint, int maxSide);

// The mirror's plane in the eye space of `view`, (a, b, c, d) with a x + b y + c z + d = 0 and
// (a, b, c) the mirror's normal: what obliqueNearPlane takes.
glm::vec4 mirrorPlaneInView(const Mirror& mirror, const glm::mat4& view);

// Stencil bits of the framebuffer `fbo` (0 = the default framebuffer), 0 when it has none.
int stencilBits(GLuint fbo);

// The render-to-texture target: an RGBA8 colour texture (linear filtering, clamped) and a
// 24-bit depth renderbuffer attached to one framebuffer object.
class MirrorTarget {
  public:
    // (Re)allocates when the size changed. Throws std::runtime_error when the framebuffer is
    // incomplete or the size is beyond the driver's limits.
    void ensure(int width, int height);
    GLuint framebuffer() const { return fbo_.id(); }
    GLuint texture() const { return colour_.id(); }
    int width() const { return width_; }
    int height() const { return height_; }
    std::size_t bytes() const { return std::size_t(width_) * height_ * (4 + 4); }

  private:
    Texture colour_;
    Renderbuffer depth_;
    Framebuffer fbo_;
    int width_ = 0, height_ = 0;
};

// glFrontFace, put back on destruction. A reflection has determinant -1: it turns
// counter-clockwise triangles clockwise, so mirrored geometry is drawn with GL_CW in front.
class ScopedFrontFace {
  public:
    explicit ScopedFrontFace(GLenum mode);
    ~ScopedFrontFace();
    ScopedFrontFace(const ScopedFrontFace&) = delete;
    ScopedFrontFace& operator=(const ScopedFrontFace&) = delete;

  private:
    GLint mode_ = GL_CCW;
};

// Stencil test on, with the front-and-back function and operations given; everything
// (enable, function, reference, masks, operations) is put back on destruction.
class ScopedStencil {
  public:
    ScopedStencil(GLenum func, GLint ref, GLenum fail, GLenum depthFail, GLenum pass);
    ~ScopedStencil();
    ScopedStencil(const ScopedStencil&) = delete;
    ScopedStencil& operator=(const ScopedStencil&) = delete;

  private:
    bool enabled_ = false;
    std::array<GLint, 7> saved_{};  // func, ref, value mask, write mask, fail, zfail, zpass
};

class ScopedDepthMask {
  public:
    explicit ScopedDepthMask(bool write);
    ~ScopedDepthMask() { glDepthMask(saved_); }
    ScopedDepthMask(const ScopedDepthMask&) = delete;
    ScopedDepthMask& operator=(const ScopedDepthMask&) = delete;

  private:
    GLboolean saved_ = GL_TRUE;
};

// Blending on with (src, dst) factors for colour and alpha; put back on destruction.
class ScopedBlend {
  public:
    ScopedBlend(GLenum src, GLenum dst);
    ~ScopedBlend();
    ScopedBlend(const ScopedBlend&) = delete;
    ScopedBlend& operator=(const ScopedBlend&) = delete;

  private:
    bool enabled_ = false;
    std::array<GLint, 4> saved_{};  // src rgb, dst rgb, src alpha, dst alpha
};

}  // namespace sl
