#include "gl/loader.h"

#include "gl/gl.h"

namespace sl {

bool loadGl(GlProcLoader loader) {
    return gladLoadGL(reinterpret_cast<GLADloadfunc>(loader)) != 0;
}

}  // namespace sl
