#include "gl/program.h"

#include <iostream>

namespace sl {

GLint Program::location(const char* uniform) {
    auto it = locations_.find(uniform);
    if (it != locations_.end()) return it->second;
    GLint loc = glGetUniformLocation(handle_.id(), uniform);
    locations_.emplace(uniform, loc);
    if (loc < 0 && reportMissing_)
        std::cerr << "shadowlab: note: " << name_ << " (your shader) has no active uniform '"
                  << uniform << "'; the value the stage sets is ignored\n";
    return loc;
}

}  // namespace sl
