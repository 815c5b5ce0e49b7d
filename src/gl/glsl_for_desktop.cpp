// Desktop OpenGL compiles the checked GLSL as it is (gl/glsl_for_driver.h).
#include "gl/glsl_for_driver.h"
#include "gl/glsl_standard.h"

namespace sl {

std::string glslForDriver(const GlslSource& source, ShaderKind) {
    return source.text;
}

bool addedByTranslation(const std::string&) {
    return false;
}

}  // namespace sl
