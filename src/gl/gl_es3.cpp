// The browser edition's GL state behind gl_es3.h: which textures hold a fixed-point depth format,
// and the depth compare's reference range each draw's program gets.
#include <cfloat>
#include <map>

#include "gl/gl.h"

namespace sl::es3 {

namespace {

// By texture name: whether level 0 holds a fixed-point depth format (16 or 24 bits).
std::map<GLuint, bool>& depthTextures() {
    static std::map<GLuint, bool> textures;
    return textures;
}

// Where a program takes its compare's reference range and its first 2D depth-compare sampler
// (-1: none), found once a link (an active-uniform walk per draw cost the page's frames).
struct CompareSlots {
    GLint range = -1;
    GLint sampler = -1;
};

std::map<GLuint, CompareSlots>& linkedPrograms() {
    static std::map<GLuint, CompareSlots> programs;
    return programs;
}

CompareSlots compareSlotsOf(GLuint program) {
    CompareSlots slots;
    slots.range = glGetUniformLocation(program, kDepthReferenceRange);
    GLint count = 0;
    glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
    for (GLint i = 0; slots.range >= 0 && i < count; ++i) {
        char name[256];
        GLint size = 0;
        GLenum type = 0;
        glGetActiveUniform(program, GLuint(i), sizeof name, nullptr, &size, &type, name);
        if (type != GL_SAMPLER_2D_SHADOW) continue;
        slots.sampler = glGetUniformLocation(program, name);
        break;
    }
    return slots;
}

// The texture bound to the unit the sampler at `location` reads (its unit may change per draw).
GLuint textureOfSampler(GLuint program, GLint location) {
    GLint unit = 0, active = 0, texture = 0;
    glGetUniformiv(program, location, &unit);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture);
    glActiveTexture(GLenum(active));
    return GLuint(texture);
}

}  // namespace

void noteTexImage(GLenum target, GLint internal) {
    if (target != GL_TEXTURE_2D) return;
    GLint bound = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
    depthTextures()[GLuint(bound)] = internal == GL_DEPTH_COMPONENT16 ||
                                     internal == GL_DEPTH_COMPONENT24 ||
                                     internal == GL_DEPTH24_STENCIL8;
}

void forgetProgram(GLuint program) {
    linkedPrograms().erase(program);
}

void beforeDraw() {
    GLint program = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    if (!program) return;
    auto found = linkedPrograms().find(GLuint(program));
    if (found == linkedPrograms().end())
        found = linkedPrograms().emplace(GLuint(program), compareSlotsOf(GLuint(program))).first;
    const CompareSlots& slots = found->second;
    if (slots.range < 0) return;  // no depth compare in this program
    const GLuint compared =
        slots.sampler < 0 ? 0 : textureOfSampler(GLuint(program), slots.sampler);
    auto depth = depthTextures().find(compared);
    bool fixedPoint = depth == depthTextures().end() || depth->second;
    if (fixedPoint)
        glUniform2f(slots.range, 0.0f, 1.0f);
    else
        glUniform2f(slots.range, -FLT_MAX, FLT_MAX);
}

}  // namespace sl::es3
