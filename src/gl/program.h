// A linked GLSL program with cached uniform locations and typed setters.
#pragma once

#include <glm/glm.hpp>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "gl/debug.h"
#include "gl/handles.h"

namespace sl {

// No program (fixed function): a GL error after this is not a student's shader's.
inline void useNoProgram() {
    glUseProgram(0);
    setProgramInUse("");
}

class Program {
  public:
    Program() = default;
    Program(ProgramHandle handle, std::string name)
        : handle_(std::move(handle)), name_(std::move(name)) {}

    GLuint id() const { return handle_.id(); }
    const std::string& name() const { return name_; }
    explicit operator bool() const { return bool(handle_); }
    void use() const {
        glUseProgram(handle_.id());
        setProgramInUse(studentFiles_);  // a GL error while it draws is then theirs
    }

    // -1 when the program has no active uniform of that name (setting it is then a no-op, as GL
    // does).
    GLint location(const char* uniform);
    bool has(const char* uniform) { return location(uniform) >= 0; }
    // A student's program: say once per name on stderr when a uniform the stage sets is not
    // active in it (a typo, or unused), instead of ignoring it silently. `only`: the names worth
    // a note (ours declares them); empty: every name.
    void reportMissingUniforms(std::set<std::string> only = {}) {
        reportMissing_ = true;
        reportOnly_ = std::move(only);
    }

    // A student's program (reportMissingUniforms called): the uniforms active in it that
    // nothing has set so far and that ours does not declare, array suffixes dropped. Asked
    // after a frame, these are what the stage never sets: they keep their initial value.
    std::vector<std::string> uniformsNeverSet();

    // The uniforms the stage set that this student's program does not read (see above).
    const std::set<std::string>& ignoredUniforms() const { return ignored_; }

    // The files it was built from, named when a uniform's declared type does not fit.
    void setOrigin(std::string files) { origin_ = std::move(files); }
    // The student's files in it ("" when every file is ours), named by a GL error in a draw.
    void setStudentFiles(std::string files) { studentFiles_ = std::move(files); }

    // Each setter checks the uniform's declared type first: `uniform int margin;` set with a
    // float is a ShaderError naming the files (the shader's fault), not a GL error.
    void set(const char* u, int v) { glUniform1i(typedLocation(u, Setter::Int), v); }
    void set(const char* u, float v) { glUniform1f(typedLocation(u, Setter::Float), v); }
    void set(const char* u, const glm::vec3& v) {
        glUniform3fv(typedLocation(u, Setter::Vec3), 1, &v[0]);
    }
    void set(const char* u, const glm::vec4& v) {
        glUniform4fv(typedLocation(u, Setter::Vec4), 1, &v[0]);
    }
    void set(const char* u, const glm::mat3& m) {
        glUniformMatrix3fv(typedLocation(u, Setter::Mat3), 1, GL_FALSE, &m[0][0]);
    }
    void set(const char* u, const glm::mat4& m) {
        glUniformMatrix4fv(typedLocation(u, Setter::Mat4), 1, GL_FALSE, &m[0][0]);
    }

    // GL's rule, checked by us because Mesa waives it: two active samplers of different types
    // (sampler2D and sampler2DShadow) on one texture unit make every draw INVALID_OPERATION.
    // Asked right before a draw, once the stage has set the units; a ShaderError naming the
    // files and both uniforms.
    void checkSamplerUnits();

  private:
    enum class Setter { Int, Float, Vec3, Vec4, Mat3, Mat4 };
    GLint typedLocation(const char* uniform, Setter setter);
    GLenum declaredType(GLint location);

    ProgramHandle handle_;
    std::string name_;
    std::string origin_;
    std::string studentFiles_;
    std::unordered_map<std::string, GLint> locations_;
    std::unordered_map<GLint, GLenum> types_;  // by location, filled on first use
    bool reportMissing_ = false;
    std::set<std::string> reportOnly_;
    std::set<std::string> ignored_;
};

}  // namespace sl
