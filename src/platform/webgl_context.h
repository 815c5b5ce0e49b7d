// The browser edition's GL context: a WebGL 2 context on a page's canvas, made with emscripten's
// HTML5 API (no port that downloads). The platform owns the context only, as for OSMesa and EGL.
#pragma once

#include <string>

namespace sl {

// Creates a WebGL 2 context (depth 24, stencil 8, no antialiasing, the drawing buffer kept for
// screenshots) on the canvas named by `selector` ("#canvas") and makes it current. Returns ""
// or a one-line reason.
std::string createWebGl2Context(const char* selector);

}  // namespace sl
