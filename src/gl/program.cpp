#include "gl/program.h"

#include <iostream>
#include <set>

namespace sl {

GLint Program::location(const char* uniform) {
    auto it = locations_.find(uniform);
    if (it != locations_.end()) return it->second;
    GLint loc = glGetUniformLocation(handle_.id(), uniform);
    locations_.emplace(uniform, loc);
    // Once per program and uniform in a process: a reload builds a new Program, and the same
    // note on every reload would bury what changed.
    static std::set<std::string> said;
    if (loc < 0 && reportMissing_ && said.insert(name_ + "/" + uniform).second)
        std::cerr << "shadowlab: note: " << name_ << " (your shader) has no active uniform '"
                  << uniform << "'; the value the stage sets is ignored" << std::endl;
    return loc;
}

}  // namespace sl
