// Scoped GL state: each pass sets what it needs through these and the destructor puts back what
// was there, so nothing leaks from one pass into the next.
#pragma once

#include <array>

#include "gl/gl.h"

namespace sl {

class ScopedEnable {
  public:
    ScopedEnable(GLenum cap, bool on) : cap_(cap), was_(glIsEnabled(cap)) { apply(on); }
    ~ScopedEnable() { apply(was_); }
    ScopedEnable(const ScopedEnable&) = delete;
    ScopedEnable& operator=(const ScopedEnable&) = delete;

  private:
    void apply(bool on) { on ? glEnable(cap_) : glDisable(cap_); }
    GLenum cap_;
    bool was_;
};

class ScopedFramebuffer {
  public:
    ScopedFramebuffer(GLuint fbo, int width, int height) {
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw_);
        glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_);
        glGetIntegerv(GL_VIEWPORT, viewport_.data());
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glViewport(0, 0, width, height);
    }
    ~ScopedFramebuffer() {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, draw_);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, read_);
        glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    }
    ScopedFramebuffer(const ScopedFramebuffer&) = delete;
    ScopedFramebuffer& operator=(const ScopedFramebuffer&) = delete;

  private:
    GLint draw_ = 0, read_ = 0;
    std::array<GLint, 4> viewport_{};
};

// Draws only inside the box (x, y, width, height); nothing is clipped when `on` is false.
class ScopedScissor {
  public:
    ScopedScissor(bool on, int x, int y, int width, int height) : enable_(GL_SCISSOR_TEST, on) {
        glGetIntegerv(GL_SCISSOR_BOX, box_.data());
        if (on) glScissor(x, y, width, height);
    }
    ~ScopedScissor() { glScissor(box_[0], box_[1], box_[2], box_[3]); }
    ScopedScissor(const ScopedScissor&) = delete;
    ScopedScissor& operator=(const ScopedScissor&) = delete;

  private:
    ScopedEnable enable_;
    std::array<GLint, 4> box_{};
};

class ScopedPolygonOffset {
  public:
    ScopedPolygonOffset(float factor, float units)
        : enable_(GL_POLYGON_OFFSET_FILL, factor != 0 || units != 0) {
        glGetFloatv(GL_POLYGON_OFFSET_FACTOR, &factor_);
        glGetFloatv(GL_POLYGON_OFFSET_UNITS, &units_);
        glPolygonOffset(factor, units);
    }
    ~ScopedPolygonOffset() { glPolygonOffset(factor_, units_); }
    ScopedPolygonOffset(const ScopedPolygonOffset&) = delete;
    ScopedPolygonOffset& operator=(const ScopedPolygonOffset&) = delete;

  private:
    ScopedEnable enable_;
    GLfloat factor_ = 0, units_ = 0;
};

class ScopedCullFace {
  public:
    // face = GL_NONE disables culling.
    explicit ScopedCullFace(GLenum face) : enable_(GL_CULL_FACE, face != GL_NONE) {
        glGetIntegerv(GL_CULL_FACE_MODE, &mode_);
        if (face != GL_NONE) glCullFace(face);
    }
    ~ScopedCullFace() { glCullFace(static_cast<GLenum>(mode_)); }
    ScopedCullFace(const ScopedCullFace&) = delete;
    ScopedCullFace& operator=(const ScopedCullFace&) = delete;

  private:
    ScopedEnable enable_;
    GLint mode_ = GL_BACK;
};

class ScopedColorMask {
  public:
    explicit ScopedColorMask(bool write) {
        glGetBooleanv(GL_COLOR_WRITEMASK, mask_.data());
        GLboolean w = write ? GL_TRUE : GL_FALSE;
        glColorMask(w, w, w, w);
    }
    ~ScopedColorMask() { glColorMask(mask_[0], mask_[1], mask_[2], mask_[3]); }
    ScopedColorMask(const ScopedColorMask&) = delete;
    ScopedColorMask& operator=(const ScopedColorMask&) = delete;

  private:
    std::array<GLboolean, 4> mask_{};
};

// What this GL lacks (gl/gl_es3.h; docs/web.md): WebGL refuses a near value above the far one
// (glDepthRange(1, 0): INVALID_OPERATION) and has no border clamp (GL_CLAMP_TO_BORDER).
#ifdef SHADOWLAB_GL_ES
constexpr bool kDepthRangeFlips = false;
constexpr bool kBorderClamp = false;
#else
constexpr bool kDepthRangeFlips = true;
constexpr bool kBorderClamp = true;
#endif

class ScopedDepthRange {
  public:
    ScopedDepthRange(double nearValue, double farValue) {
        glGetDoublev(GL_DEPTH_RANGE, range_.data());
        glDepthRange(nearValue, farValue);
    }
    ~ScopedDepthRange() { glDepthRange(range_[0], range_[1]); }
    ScopedDepthRange(const ScopedDepthRange&) = delete;
    ScopedDepthRange& operator=(const ScopedDepthRange&) = delete;

  private:
    std::array<GLdouble, 2> range_{};
};

class ScopedDepthFunc {
  public:
    explicit ScopedDepthFunc(GLenum func) {
        glGetIntegerv(GL_DEPTH_FUNC, &func_);
        glDepthFunc(func);
    }
    ~ScopedDepthFunc() { glDepthFunc(static_cast<GLenum>(func_)); }
    ScopedDepthFunc(const ScopedDepthFunc&) = delete;
    ScopedDepthFunc& operator=(const ScopedDepthFunc&) = delete;

  private:
    GLint func_ = GL_LESS;
};

}  // namespace sl
