// A headless GL context for tests, CI and grading. The platform owns the context only: it
// hands the renderer a framebuffer to draw into and reads the pixels back.
#pragma once

#include <memory>
#include <string>

#include "gl/shader_library.h"
#include "io/image.h"

namespace sl {

enum class Backend { OSMesa, Egl, Auto };

class HeadlessContext {
  public:
    virtual ~HeadlessContext() = default;
    // The framebuffer the renderer should draw into (0 for OSMesa's own buffer).
    virtual GLuint framebuffer() const = 0;
    virtual const char* backendName() const = 0;
    // Makes this context current again (another one may have been since), and says whether it is.
    virtual bool makeCurrent() = 0;
    // Whether the context is gone (the browser lost its WebGL context: every call since is a
    // no-op, a compile fails without a log, a read gives zeros). What it drew since is nobody's
    // work: never the student's. A desktop context is never lost.
    virtual bool lost() const { return false; }
    int width() const { return width_; }
    int height() const { return height_; }
    // Reads the framebuffer back, row 0 at the top.
    Image read() const;

  protected:
    int width_ = 0, height_ = 0;
};

// Auto picks the backend named by the environment variable SHADOWLAB_BACKEND (osmesa|egl) when
// set, else OSMesa when this build has it and it works, else EGL.
// Creates a context of the profile the tree needs (core 3.3+ or compatibility) and a
// width x height RGBA8 + depth24/stencil8 target; GL entry points are loaded. Throws
// std::runtime_error with a one-line reason on failure.
std::unique_ptr<HeadlessContext> createHeadlessContext(Backend backend, GlslTree tree, int width,
                                                       int height);

// Implemented per backend.
std::unique_ptr<HeadlessContext> createOSMesaContext(GlslTree tree, int width, int height);
std::unique_ptr<HeadlessContext> createEglContext(GlslTree tree, int width, int height);
bool osmesaAvailable();

}  // namespace sl
