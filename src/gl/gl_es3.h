// OpenGL ES 3.0 (WebGL 2) behind the names the renderer calls: the browser edition's GL header
// (cmake/web.cmake writes its <shadowlab_glad.h> to include this file instead of glad's). The
// handful of desktop calls the passes make are mapped here to their ES 3.0 equivalents, so no
// stage or pass branches on the platform. Every difference is listed in docs/web.md.
#pragma once

#include <GLES3/gl3.h>

#include <functional>
#include <stdexcept>
#include <string>

#define SHADOWLAB_GL_ES 1

typedef double GLdouble;

// No debug-output callback in WebGL: glGetError is polled (gl/debug.cpp checks these first).
#define GLAD_GL_KHR_debug 0
#define GLAD_GL_VERSION_4_3 0
#define GLAD_API_PTR
#define GL_DEBUG_OUTPUT 0x92E0
#define GL_DEBUG_OUTPUT_SYNCHRONOUS 0x8242
#define GL_DEBUG_SOURCE_SHADER_COMPILER 0x8248
#define GL_DEBUG_TYPE_ERROR 0x824C
typedef void (*GLDEBUGPROC)(GLenum, GLenum, GLuint, GLenum, GLsizei, const GLchar*, const void*);
inline void glDebugMessageCallback(GLDEBUGPROC, const void*) {}

// Desktop-only names the passes use, with their desktop values (never sent to WebGL as is).
#define GL_CLAMP_TO_BORDER 0x812D
#define GL_TEXTURE_BORDER_COLOR 0x1004
#define GL_DOUBLE 0x140A                              // a uniform type ES never reports
#define GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER 0x8CDB  // framebuffer statuses ES never returns
#define GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER 0x8CDC
#define GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS 0x8DA8

namespace sl::es3 {

// ES 3.0 (3.8.16) and desktop GL clamp a depth compare's reference to [0, 1] for a fixed-point
// depth texture; SwiftShader keeps such a texture as float and does not, so a receiver beyond the
// light's far plane came out shadowed. The translation (gl/glsl_for_webgl.cpp) clamps every 2D
// compare's reference to the uniform kDepthReferenceRange; before each draw it is set from the
// depth texture the program compares with: [0, 1] for a fixed-point one, unbounded for a float
// one (gl_es3.cpp). docs/web.md.
constexpr const char* kDepthReferenceRange = "sl_depthReference";
void noteTexImage(GLenum target, GLint internal);

// A loop that never ends (gl/loop_guard.h): before each draw whose fragment shader carries the
// loop budget's probe, the draw runs with the probe on into a target of its own, and a fragment
// whose budget ran out throws LoopBudgetSpent naming the file, so a stopped loop costs the
// budget once, not twice; docs/web.md.
//
// noteLinked records what a draw needs of a program (the compare's range and sampler, the probe
// and its file) once per link; draw sets the range, probes, then calls `drawCall` (gl_es3.cpp).
void noteLinked(GLuint program);
void draw(const std::function<void()>& drawCall);

// ES 3.0 has no border clamp: the edge texel is read instead, which the shadow pass keeps at the
// border's value (kBorderClamp, render/shadow_map.cpp); docs/web.md.
inline void texParameteri(GLenum target, GLenum name, GLint value) {
    glTexParameteri(target, name, value == GL_CLAMP_TO_BORDER ? GL_CLAMP_TO_EDGE : value);
}
inline void texParameterfv(GLenum target, GLenum name, const GLfloat* values) {
    if (name != GL_TEXTURE_BORDER_COLOR) glTexParameterfv(target, name, values);
}
// RGB8 is not colour-renderable in ES 3.0; RGBA8 keeps the same 8 bits a channel.
inline void texImage2D(GLenum target, GLint level, GLint internal, GLsizei w, GLsizei h,
                       GLint border, GLenum format, GLenum type, const void* pixels) {
    if (internal == GL_RGB8 && !pixels) {
        internal = GL_RGBA8;
        format = GL_RGBA;
    }
    glTexImage2D(target, level, internal, w, h, border, format, type, pixels);
    if (level == 0) noteTexImage(target, internal);
}
inline void drawBuffer(GLenum buffer) {
    glDrawBuffers(1, &buffer);
}
// WebGL refuses near > far (INVALID_OPERATION), so the flipped light projection of the bias
// lesson cannot be built this way: said in words, not left as a GL error code.
inline void depthRange(GLdouble nearValue, GLdouble farValue) {
    if (nearValue > farValue)
        throw std::runtime_error("glDepthRange(" + std::to_string(nearValue).substr(0, 3) + ", " +
                                 std::to_string(farValue).substr(0, 3) +
                                 "): WebGL refuses a near value above the far one "
                                 "(INVALID_OPERATION); this setting runs in the native program "
                                 "(docs/web.md)");
    glDepthRangef(static_cast<GLfloat>(nearValue), static_cast<GLfloat>(farValue));
}
inline void clearDepth(GLdouble value) {
    glClearDepthf(static_cast<GLfloat>(value));
}
inline void linkProgram(GLuint program) {
    glLinkProgram(program);
    noteLinked(program);
}
inline void drawArrays(GLenum mode, GLint first, GLsizei count) {
    draw([=] { glDrawArrays(mode, first, count); });
}
inline void drawElements(GLenum mode, GLsizei count, GLenum type, const void* indices) {
    draw([=] { glDrawElements(mode, count, type, indices); });
}
inline void getDoublev(GLenum name, GLdouble* out) {
    GLfloat values[16] = {};
    glGetFloatv(name, values);
    int count = name == GL_DEPTH_RANGE ? 2 : 1;
    for (int i = 0; i < count; ++i) out[i] = values[i];
}

}  // namespace sl::es3

#define glTexParameteri sl::es3::texParameteri
#define glTexParameterfv sl::es3::texParameterfv
#define glTexImage2D sl::es3::texImage2D
#define glDrawBuffer sl::es3::drawBuffer
#define glDepthRange sl::es3::depthRange
#define glClearDepth sl::es3::clearDepth
#define glGetDoublev sl::es3::getDoublev
#define glDrawArrays sl::es3::drawArrays
#define glDrawElements sl::es3::drawElements
#define glLinkProgram sl::es3::linkProgram
