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

// The texture bound to the unit of the current program's first 2D depth-compare sampler (0: none).
GLuint comparedTexture(GLuint program) {
    GLint count = 0;
    glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
    for (GLint i = 0; i < count; ++i) {
        char name[256];
        GLint size = 0;
        GLenum type = 0;
        glGetActiveUniform(program, GLuint(i), sizeof name, nullptr, &size, &type, name);
        if (type != GL_SAMPLER_2D_SHADOW) continue;
        GLint unit = 0, active = 0, texture = 0;
        glGetUniformiv(program, glGetUniformLocation(program, name), &unit);
        glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
        glActiveTexture(GLenum(GL_TEXTURE0 + unit));
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture);
        glActiveTexture(GLenum(active));
        return GLuint(texture);
    }
    return 0;
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

void beforeDraw() {
    GLint program = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    if (!program) return;
    GLint range = glGetUniformLocation(GLuint(program), kDepthReferenceRange);
    if (range < 0) return;  // no depth compare in this program
    auto found = depthTextures().find(comparedTexture(GLuint(program)));
    bool fixedPoint = found == depthTextures().end() || found->second;
    if (fixedPoint)
        glUniform2f(range, 0.0f, 1.0f);
    else
        glUniform2f(range, -FLT_MAX, FLT_MAX);
}

}  // namespace sl::es3
