// A colour (RGBA8) and depth/stencil (24/8) target of a headless context's size in a framebuffer
// object of our own: what EGL's surfaceless contexts and the browser's check draw into.
#pragma once

#include "gl/handles.h"

namespace sl {

struct FramebufferTarget {
    Renderbuffer colour, depthStencil;
    Framebuffer fbo;
};

// Makes the target in the current context and leaves it bound (a new context draws into its
// target, as OSMesa's does into its buffer); throws std::runtime_error naming `what` when the
// framebuffer is incomplete.
FramebufferTarget createFramebufferTarget(int width, int height, const char* what);

}  // namespace sl
