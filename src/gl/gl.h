// The one way this project includes OpenGL: glad's generated loader (built from Debian's
// python3-glad at configure time). Never include GL/gl.h directly in renderer code.
#pragma once

#include <glad/gl.h>
