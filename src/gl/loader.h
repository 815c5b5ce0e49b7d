// Loads GL entry points through the platform's GetProcAddress (OSMesa, freeglut, EGL).
#pragma once

#include "gl/gl.h"

namespace sl {

using GlProcLoader = void (*(*)(const char*))();
bool loadGl(GlProcLoader loader);

}  // namespace sl
