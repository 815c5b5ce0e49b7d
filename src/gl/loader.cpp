#include "gl/loader.h"

#include "gl/gl.h"

namespace sl {

bool loadGl(GlProcLoader loader) {
    return SHADOWLAB_GLAD_LOAD(loader) != 0;  // glad 0.1 or 2: cmake/glad.cmake
}

}  // namespace sl
