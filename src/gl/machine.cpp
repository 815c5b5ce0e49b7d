#include "gl/machine.h"

#include "gl/gl.h"
#include "io/box.h"

namespace sl {

std::string machineLine() {
    auto text = [](GLenum name) {
        const GLubyte* s = glGetString(name);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    int cores = boxCores();
    return std::to_string(cores) + (cores == 1 ? " core, " : " cores, ") + text(GL_RENDERER) +
           ", GL " + text(GL_VERSION);
}

}  // namespace sl
