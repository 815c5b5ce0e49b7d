// Building a GL program from checked sources: each shader compiled (the driver's log mapped back
// to the student's file and line), the two linked with the meshes' attribute locations, and the
// program's inputs held to what the meshes feed. The student's faults are ShaderErrors.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "gl/glsl_standard.h"
#include "gl/handles.h"
#include "gl/shader_library.h"
#include "io/files.h"

namespace sl {

// Rewrites Mesa's first "S:L(C)" in each line into "file:L:C" (`files[S]`).
std::string mapLog(const std::string& log, const std::vector<std::string>& files);

// Compiles `driverText` (gl/glsl_for_driver.h: `src` itself, or its translation).
template <class ShaderHandle>
ShaderHandle compileShader(const GlslSource& src, const std::string& driverText, const char* kind) {
    ShaderHandle shader = ShaderHandle::create();
    const char* text = driverText.c_str();
    glShaderSource(shader.id(), 1, &text, nullptr);
    glCompileShader(shader.id());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetShaderiv(shader.id(), GL_INFO_LOG_LENGTH, &length);
        std::string log(std::max(length, 1), '\0');
        glGetShaderInfoLog(shader.id(), length, nullptr, log.data());
        throw ShaderError(printableName(src.files[0]) + ": " + kind + " shader did not compile:\n" +
                          mapLog(log.c_str(), src.files));
    }
    return shader;
}

// Links the two shaders (attributes at kPositionAttribute, kNormalAttribute); a failure names
// both files with the driver's log mapped to them.
ProgramHandle linkShaders(const VertexShader& vs, const FragmentShader& fs, const GlslSource& vert,
                          const GlslSource& frag);

// Every active vertex input must be one the meshes feed (position, normal): another name would
// read an attribute array nobody enables. The student's fault, named as such (not a GL error).
void requireKnownAttributes(GLuint program, const std::string& vertexFile);

}  // namespace sl
