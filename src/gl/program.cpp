#include "gl/program.h"

namespace sl {

GLint Program::location(const char* uniform) {
    auto it = locations_.find(uniform);
    if (it != locations_.end()) return it->second;
    GLint loc = glGetUniformLocation(handle_.id(), uniform);
    locations_.emplace(uniform, loc);
    return loc;
}

}  // namespace sl
