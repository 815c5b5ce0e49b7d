// A linked GLSL program with cached uniform locations and typed setters.
#pragma once

#include <glm/glm.hpp>
#include <string>
#include <unordered_map>

#include "gl/handles.h"

namespace sl {

class Program {
public:
    Program() = default;
    Program(ProgramHandle handle, std::string name) : handle_(std::move(handle)), name_(std::move(name)) {}

    GLuint id() const { return handle_.id(); }
    const std::string& name() const { return name_; }
    explicit operator bool() const { return bool(handle_); }
    void use() const { glUseProgram(handle_.id()); }

    // -1 when the program has no active uniform of that name (setting it is then a no-op, as GL does).
    GLint location(const char* uniform);
    bool has(const char* uniform) { return location(uniform) >= 0; }
    // A student's program: say once per name on stderr when a uniform the stage sets is not
    // active in it (a typo, or unused), instead of ignoring it silently.
    void reportMissingUniforms(bool on) { reportMissing_ = on; }

    void set(const char* u, int v) { glUniform1i(location(u), v); }
    void set(const char* u, float v) { glUniform1f(location(u), v); }
    void set(const char* u, const glm::vec3& v) { glUniform3fv(location(u), 1, &v[0]); }
    void set(const char* u, const glm::vec4& v) { glUniform4fv(location(u), 1, &v[0]); }
    void set(const char* u, const glm::mat3& m) { glUniformMatrix3fv(location(u), 1, GL_FALSE, &m[0][0]); }
    void set(const char* u, const glm::mat4& m) { glUniformMatrix4fv(location(u), 1, GL_FALSE, &m[0][0]); }

private:
    ProgramHandle handle_;
    std::string name_;
    std::unordered_map<std::string, GLint> locations_;
    bool reportMissing_ = false;
};

}  // namespace sl
