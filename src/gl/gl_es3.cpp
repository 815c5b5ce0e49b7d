// The browser edition's GL state behind gl_es3.h: which textures hold a fixed-point depth format,
// the depth compare's reference range each draw's program gets, and the loop budget's probe.
#include <algorithm>
#include <cfloat>
#include <map>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/loop_guard.h"
#include "io/files.h"

namespace sl::es3 {

namespace {

// By texture name: whether level 0 holds a fixed-point depth format (16 or 24 bits).
std::map<GLuint, bool>& depthTextures() {
    static std::map<GLuint, bool> textures;
    return textures;
}

// What a draw needs of its program, found once when it links (an active-uniform walk per draw
// cost the page's frames): where it takes its compare's reference range and its first 2D
// depth-compare sampler (-1: none), and the loop probe's uniform with the file it names (-1 and
// "": no probe in its fragment shader).
struct LinkedProgram {
    GLint range = -1;
    GLint sampler = -1;
    GLint probe = -1;
    std::string file;
};

std::map<GLuint, LinkedProgram>& linkedPrograms() {
    static std::map<GLuint, LinkedProgram> programs;
    return programs;
}

// The first 2D depth-compare sampler among the program's active uniforms (-1: none).
GLint compareSampler(GLuint program) {
    GLint count = 0;
    glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
    for (GLint i = 0; i < count; ++i) {
        char name[256];
        GLint size = 0;
        GLenum type = 0;
        glGetActiveUniform(program, GLuint(i), sizeof name, nullptr, &size, &type, name);
        if (type == GL_SAMPLER_2D_SHADOW) return glGetUniformLocation(program, name);
    }
    return -1;
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

GLuint currentProgram() {
    GLint program = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    return GLuint(program);
}

// The file a shader's translation names on its loop-budget line ("" when it has none).
std::string guardedFile(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_SHADER_SOURCE_LENGTH, &length);
    std::string text(std::size_t(std::max(length, 1)), '\0');
    glGetShaderSource(shader, length, nullptr, text.data());
    const std::size_t at = text.find(kLoopGuardLine);
    if (at == std::string::npos) return "";
    const std::size_t from = at + std::string(kLoopGuardLine).size();
    return text.substr(from, text.find('\n', from) - from);
}

// The state a probe draw changes, kept and put back as it was.
struct DrawState {
    GLint drawFramebuffer = 0, readFramebuffer = 0, renderbuffer = 0, viewport[4] = {};
    GLboolean colorMask[4] = {}, depthTest = 0, stencilTest = 0, blend = 0, scissor = 0;
    GLfloat clear[4] = {};
    DrawState() {
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer);
        glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer);
        glGetIntegerv(GL_RENDERBUFFER_BINDING, &renderbuffer);
        glGetIntegerv(GL_VIEWPORT, viewport);
        glGetBooleanv(GL_COLOR_WRITEMASK, colorMask);
        glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
        depthTest = glIsEnabled(GL_DEPTH_TEST);
        stencilTest = glIsEnabled(GL_STENCIL_TEST);
        blend = glIsEnabled(GL_BLEND);
        scissor = glIsEnabled(GL_SCISSOR_TEST);
    }
    void restore() const {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(drawFramebuffer));
        glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(readFramebuffer));
        glBindRenderbuffer(GL_RENDERBUFFER, GLuint(renderbuffer));
        glColorMask(colorMask[0], colorMask[1], colorMask[2], colorMask[3]);
        glClearColor(clear[0], clear[1], clear[2], clear[3]);
        const auto set = [](GLenum cap, GLboolean on) { on ? glEnable(cap) : glDisable(cap); };
        set(GL_DEPTH_TEST, depthTest);
        set(GL_STENCIL_TEST, stencilTest);
        set(GL_BLEND, blend);
        set(GL_SCISSOR_TEST, scissor);
    }
};

// The probe's own colour target, at least `width` x `height`, bound to GL_FRAMEBUFFER.
void bindProbeTarget(GLsizei width, GLsizei height) {
    static GLuint framebuffer = 0, colour = 0;
    static GLsizei w = 0, h = 0;
    if (!framebuffer) {
        glGenFramebuffers(1, &framebuffer);
        glGenRenderbuffers(1, &colour);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    if (width > w || height > h) {
        w = std::max(w, width);
        h = std::max(h, height);
        glBindRenderbuffer(GL_RENDERBUFFER, colour);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, w, h);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
    }
}

// The file the fragment shader's translation names on its loop-budget line ("" when none).
std::string fragmentFile(GLuint program) {
    GLuint shaders[2] = {};
    GLsizei count = 0;
    glGetAttachedShaders(program, 2, &count, shaders);
    for (GLsizei i = 0; i < count; ++i) {
        GLint type = 0;
        glGetShaderiv(shaders[i], GL_SHADER_TYPE, &type);
        if (type == GL_FRAGMENT_SHADER) return guardedFile(shaders[i]);
    }
    return "";
}

// The draw, every test off, into the probe's target: only fragments whose budget ran out write
// (the translation's probe), so one non-zero pixel is a loop the budget stopped.
void probeLoops(const LinkedProgram& linked, const std::function<void()>& draw) {
    const DrawState state;
    const GLint* v = state.viewport;
    bindProbeTarget(v[0] + v[2], v[1] + v[3]);
    for (GLenum cap : {GL_DEPTH_TEST, GL_STENCIL_TEST, GL_BLEND, GL_SCISSOR_TEST}) glDisable(cap);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glUniform1i(linked.probe, 1);
    draw();
    glUniform1i(linked.probe, 0);
    std::vector<unsigned char> pixels(std::size_t(v[2]) * std::size_t(v[3]) * 4);
    glReadPixels(v[0], v[1], v[2], v[3], GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    state.restore();
    for (std::size_t i = 0; i < pixels.size(); i += 4)
        if (pixels[i]) throw LoopBudgetSpent(printableName(linked.file));
}

// The compare's reference range for the texture the program compares with: [0, 1] for a
// fixed-point depth texture, unbounded for a float one.
void setReferenceRange(GLuint program, const LinkedProgram& linked) {
    if (linked.range < 0) return;  // no depth compare in this program
    const GLuint compared = linked.sampler < 0 ? 0 : textureOfSampler(program, linked.sampler);
    auto depth = depthTextures().find(compared);
    bool fixedPoint = depth == depthTextures().end() || depth->second;
    if (fixedPoint)
        glUniform2f(linked.range, 0.0f, 1.0f);
    else
        glUniform2f(linked.range, -FLT_MAX, FLT_MAX);
}

}  // namespace

void noteLinked(GLuint program) {
    linkedPrograms().erase(program);
    GLint linked = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    if (!linked) return;
    LinkedProgram record;
    record.range = glGetUniformLocation(program, kDepthReferenceRange);
    if (record.range >= 0) record.sampler = compareSampler(program);
    record.probe = glGetUniformLocation(program, kLoopProbe);
    if (record.probe >= 0) record.file = fragmentFile(program);
    linkedPrograms()[program] = std::move(record);
}

void noteTexImage(GLenum target, GLint internal) {
    if (target != GL_TEXTURE_2D) return;
    GLint bound = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
    depthTextures()[GLuint(bound)] = internal == GL_DEPTH_COMPONENT16 ||
                                     internal == GL_DEPTH_COMPONENT24 ||
                                     internal == GL_DEPTH24_STENCIL8;
}

void draw(const std::function<void()>& drawCall) {
    const GLuint program = currentProgram();
    auto found = linkedPrograms().find(program);
    if (found != linkedPrograms().end()) {
        setReferenceRange(program, found->second);
        if (found->second.probe >= 0) probeLoops(found->second, drawCall);
    }
    drawCall();
}

}  // namespace sl::es3
