// Loads GL entry points through the platform's GetProcAddress (OSMesa, freeglut, EGL).
// Deliberately free of GL headers, so platform files can include their own.
#pragma once

namespace sl {

using GlProcLoader = void (*(*)(const char*))();
bool loadGl(GlProcLoader loader);

}  // namespace sl
