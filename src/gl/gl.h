// The one way this project includes OpenGL: glad's generated loader (built from Debian's
// python3-glad at configure time; the wrapper from cmake/glad.cmake names glad 0.1's or 2's
// header). Never include GL/gl.h directly in renderer code.
#pragma once

#include <shadowlab_glad.h>
