#include "gl/shader_compile.h"

#include <sstream>

namespace sl {

namespace {

// Reads unsigned digits at `i`; false when there are none.
bool digits(const std::string& s, std::size_t& i, std::size_t& value) {
    std::size_t start = i;
    value = 0;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') {
        if (value < 100000000) value = value * 10 + std::size_t(s[i] - '0');
        ++i;
    }
    return i > start;
}

}  // namespace

// Rewrites Mesa's first "S:L(C)" in each line into "file:L:C" (one linear pass per line).
std::string mapLog(const std::string& log, const std::vector<std::string>& files) {
    std::ostringstream out;
    std::istringstream in(log);
    std::string line;
    while (std::getline(in, line)) {
        for (std::size_t i = 0; i < line.size(); ++i) {
            if (line[i] < '0' || line[i] > '9' ||
                (i > 0 && line[i - 1] >= '0' && line[i - 1] <= '9'))
                continue;
            std::size_t j = i, s = 0, l = 0, c = 0;
            if (!digits(line, j, s) || j >= line.size() || line[j] != ':') continue;
            std::size_t lineStart = ++j;
            if (!digits(line, j, l) || j >= line.size() || line[j] != '(') continue;
            ++j;
            if (!digits(line, j, c) || j >= line.size() || line[j] != ')') continue;
            std::string file =
                s < files.size() ? printableName(files[s]) : "source " + std::to_string(s);
            line = line.substr(0, i) + file + ":" +
                   line.substr(lineStart, line.find('(', lineStart) - lineStart) + ":" +
                   std::to_string(c) + line.substr(j + 1);
            break;
        }
        if (!line.empty()) out << line << "\n";
    }
    return out.str();
}

ProgramHandle linkShaders(const VertexShader& vs, const FragmentShader& fs, const GlslSource& vert,
                          const GlslSource& frag) {
    ProgramHandle program = ProgramHandle::create();
    glAttachShader(program.id(), vs.id());
    glAttachShader(program.id(), fs.id());
    glBindAttribLocation(program.id(), kPositionAttribute, "position");
    glBindAttribLocation(program.id(), kNormalAttribute, "normal");
    glLinkProgram(program.id());
    GLint ok = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &length);
        std::string log(std::max(length, 1), '\0');
        glGetProgramInfoLog(program.id(), length, nullptr, log.data());
        throw ShaderError(printableName(vert.files[0]) + " + " + printableName(frag.files[0]) +
                          ": program did not link:\n" + mapLog(log.c_str(), vert.files));
    }
    glDetachShader(program.id(), vs.id());
    glDetachShader(program.id(), fs.id());
    return program;
}

// Every active vertex input must be one the meshes feed (position, normal): another name would
// read an attribute array nobody enables. The student's fault, named as such (not a GL error).
void requireKnownAttributes(GLuint program, const std::string& vertexFile) {
    GLint count = 0, longest = 0;
    glGetProgramiv(program, GL_ACTIVE_ATTRIBUTES, &count);
    glGetProgramiv(program, GL_ACTIVE_ATTRIBUTE_MAX_LENGTH, &longest);
    std::vector<char> name(std::size_t(std::max(longest, 1)) + 1, '\0');
    for (GLint i = 0; i < count; ++i) {
        GLint size = 0;
        GLenum type = 0;
        GLsizei length = 0;
        glGetActiveAttrib(program, GLuint(i), GLsizei(name.size()), &length, &size, &type,
                          name.data());
        std::string attribute(name.data(), std::size_t(std::max(length, 0)));
        if (attribute.rfind("gl_", 0) == 0) continue;  // built-ins (gl_Vertex, gl_Normal)
        if (attribute == "position" || attribute == "normal") continue;
        throw ShaderError(vertexFile + ": vertex input '" + attribute +
                          "' is not supplied by the meshes (they supply 'position' and 'normal')");
    }
}

}  // namespace sl
