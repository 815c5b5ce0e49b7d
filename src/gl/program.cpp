#include "gl/program.h"

#include <algorithm>
#include <iostream>
#include <map>
#include <set>
#include <vector>

#include "gl/glsl_for_driver.h"
#include "gl/shader_library.h"

namespace sl {

namespace {

// Calls f(name, type) for every active uniform of `program` (an array by its "name[0]").
template <class F>
void forEachActiveUniform(GLuint program, F f) {
    GLint count = 0, longest = 0;
    glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
    glGetProgramiv(program, GL_ACTIVE_UNIFORM_MAX_LENGTH, &longest);
    std::vector<char> buffer(std::size_t(std::max(longest, 1)) + 1, '\0');
    for (GLint i = 0; i < count; ++i) {
        GLint size = 0;
        GLenum type = 0;
        glGetActiveUniform(program, GLuint(i), GLsizei(buffer.size()), nullptr, &size, &type,
                           buffer.data());
        f(std::string(buffer.data()), type);
    }
}

const char* glslTypeName(GLenum type) {
    switch (type) {
        case GL_FLOAT:
            return "float";
        case GL_FLOAT_VEC2:
            return "vec2";
        case GL_FLOAT_VEC3:
            return "vec3";
        case GL_FLOAT_VEC4:
            return "vec4";
        case GL_INT:
            return "int";
        case GL_INT_VEC2:
            return "ivec2";
        case GL_INT_VEC3:
            return "ivec3";
        case GL_INT_VEC4:
            return "ivec4";
        case GL_UNSIGNED_INT:
            return "uint";
        case GL_UNSIGNED_INT_VEC2:
            return "uvec2";
        case GL_UNSIGNED_INT_VEC3:
            return "uvec3";
        case GL_UNSIGNED_INT_VEC4:
            return "uvec4";
        case GL_BOOL:
            return "bool";
        case GL_BOOL_VEC2:
            return "bvec2";
        case GL_BOOL_VEC3:
            return "bvec3";
        case GL_BOOL_VEC4:
            return "bvec4";
        case GL_FLOAT_MAT2:
            return "mat2";
        case GL_FLOAT_MAT3:
            return "mat3";
        case GL_FLOAT_MAT4:
            return "mat4";
        case GL_FLOAT_MAT2x3:
            return "mat2x3";
        case GL_FLOAT_MAT2x4:
            return "mat2x4";
        case GL_FLOAT_MAT3x2:
            return "mat3x2";
        case GL_FLOAT_MAT3x4:
            return "mat3x4";
        case GL_FLOAT_MAT4x2:
            return "mat4x2";
        case GL_FLOAT_MAT4x3:
            return "mat4x3";
        case GL_DOUBLE:
            return "double";
        default:
            return nullptr;  // samplers and the rest
    }
}

// What glUniform* accepts for each setter (the GL spec's table): glUniform1i also sets bools
// and samplers; the float setters also set bools of the same size.
bool fits(GLenum type, const char*& wanted, int setter) {
    switch (setter) {
        case 0:
            wanted = "int (or a sampler)";
            return type == GL_INT || type == GL_BOOL || glslTypeName(type) == nullptr;
        case 1:
            wanted = "float";
            return type == GL_FLOAT || type == GL_BOOL;
        case 2:
            wanted = "vec3";
            return type == GL_FLOAT_VEC3 || type == GL_BOOL_VEC3;
        case 3:
            wanted = "vec4";
            return type == GL_FLOAT_VEC4 || type == GL_BOOL_VEC4;
        case 4:
            wanted = "mat3";
            return type == GL_FLOAT_MAT3;
        default:
            wanted = "mat4";
            return type == GL_FLOAT_MAT4;
    }
}

// The GLSL name of a sampler type; nullptr for a type that is not a sampler.
const char* samplerTypeName(GLenum type) {
    switch (type) {
        case GL_SAMPLER_2D:
            return "sampler2D";
        case GL_SAMPLER_3D:
            return "sampler3D";
        case GL_SAMPLER_CUBE:
            return "samplerCube";
        case GL_SAMPLER_2D_SHADOW:
            return "sampler2DShadow";
        case GL_SAMPLER_2D_ARRAY:
            return "sampler2DArray";
        case GL_SAMPLER_2D_ARRAY_SHADOW:
            return "sampler2DArrayShadow";
        case GL_SAMPLER_CUBE_SHADOW:
            return "samplerCubeShadow";
        case GL_INT_SAMPLER_2D:
            return "isampler2D";
        case GL_UNSIGNED_INT_SAMPLER_2D:
            return "usampler2D";
#ifdef GL_SAMPLER_1D
        case GL_SAMPLER_1D:
            return "sampler1D";
        case GL_SAMPLER_1D_SHADOW:
            return "sampler1DShadow";
        case GL_SAMPLER_2D_RECT:
            return "sampler2DRect";
        case GL_SAMPLER_2D_RECT_SHADOW:
            return "sampler2DRectShadow";
#endif
        default:
            return nullptr;
    }
}

}  // namespace

void Program::checkSamplerUnits() {
    struct Sampler {
        std::string name;
        const char* type;
    };
    std::map<GLint, Sampler> byUnit;  // the first sampler seen on each unit
    std::string clash;
    forEachActiveUniform(handle_.id(), [&](std::string name, GLenum type) {
        const char* typeName = samplerTypeName(type);
        if (!typeName || !clash.empty()) return;
        GLint loc = glGetUniformLocation(handle_.id(), name.c_str());
        if (loc < 0) return;
        GLint unit = 0;
        glGetUniformiv(handle_.id(), loc, &unit);
        if (name.size() > 3 && name.compare(name.size() - 3, 3, "[0]") == 0)
            name.resize(name.size() - 3);
        auto [it, fresh] = byUnit.emplace(unit, Sampler{name, typeName});
        if (!fresh && std::string(it->second.type) != typeName)
            clash = std::string(it->second.type) + " '" + it->second.name + "' and " + typeName +
                    " '" + name + "' both read texture unit " + std::to_string(unit);
    });
    if (!clash.empty())
        throw ShaderError((origin_.empty() ? name_ : origin_) + ": " + clash +
                          ": GL forbids samplers of different types on one unit (the draw is "
                          "INVALID_OPERATION; Mesa draws anyway): give each its own unit or "
                          "remove the unused one");
}

GLint Program::location(const char* uniform) {
    auto it = locations_.find(uniform);
    if (it != locations_.end()) return it->second;
    GLint loc = glGetUniformLocation(handle_.id(), uniform);
    locations_.emplace(uniform, loc);
    // Once per program and uniform in a process: a reload builds a new Program, and the same
    // note on every reload would bury what changed.
    static std::set<std::string> said;
    const bool ignored =
        loc < 0 && reportMissing_ && (reportOnly_.empty() || reportOnly_.count(uniform));
    if (ignored) ignored_.insert(uniform);
    if (ignored && said.insert(name_ + "/" + uniform).second)
        std::cerr << "shadowlab: note: " << name_ << " (your shader) has no active uniform '"
                  << uniform << "'; the value the stage sets is ignored" << std::endl;
    return loc;
}

std::vector<std::string> Program::uniformsNeverSet() {
    std::vector<std::string> out;
    if (!reportMissing_ || !handle_) return out;
    forEachActiveUniform(handle_.id(), [&](std::string name, GLenum) {
        if (name.size() > 3 && name.compare(name.size() - 3, 3, "[0]") == 0)
            name.resize(name.size() - 3);
        if (name.rfind("gl_", 0) != 0 && !locations_.count(name) && !reportOnly_.count(name) &&
            !addedByTranslation(name))
            out.push_back(name);
    });
    return out;
}

GLenum Program::declaredType(GLint location) {
    if (types_.empty()) {  // every active uniform once: name -> location -> type
        forEachActiveUniform(handle_.id(), [&](const std::string& name, GLenum type) {
            GLint loc = glGetUniformLocation(handle_.id(), name.c_str());
            if (loc >= 0) types_[loc] = type;
        });
        types_[-1] = 0;  // marks the table as filled
    }
    auto it = types_.find(location);
    return it == types_.end() ? 0 : it->second;
}

GLint Program::typedLocation(const char* uniform, Setter setter) {
    GLint loc = location(uniform);
    if (loc < 0) return loc;
    GLenum type = declaredType(loc);
    const char* wanted = "";
    if (type != 0 && !fits(type, wanted, static_cast<int>(setter))) {
        const char* declared = glslTypeName(type);
        throw ShaderError((origin_.empty() ? name_ : origin_) + ": uniform '" + uniform +
                          "' is declared " + (declared ? declared : "a sampler") +
                          ", but the stage sets a " + wanted + " (declare it as " + wanted + ")");
    }
    return loc;
}

}  // namespace sl
