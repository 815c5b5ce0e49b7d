#include "gl/debug.h"

#include <cstdio>
#include <stdexcept>

#include "gl/shader_library.h"

namespace sl {

namespace {
const char* g_pass = "setup";
int g_errors = 0;
std::string g_lastError;
std::string g_programFiles;  // the student's files behind the program in use, or ""
std::string g_errorFiles;    // g_programFiles at the first error since the reset
bool g_raisesStudentErrors = false;

void report(const std::string& message) {
    if (++g_errors == 1) g_errorFiles = g_programFiles;
    g_lastError = message;
    // A student's program on a headless path: the ShaderError that follows is the one line.
    if (g_programFiles.empty() || !g_raisesStudentErrors)
        std::fprintf(stderr, "shadowlab: GL error in pass '%s': %s\n", g_pass, message.c_str());
}

void GLAD_API_PTR onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity,
                                 GLsizei length, const GLchar* message, const void* user) {
    // Only real errors count; performance and portability notes from llvmpipe are noise here.
    // Compile and link failures are the shader library's to report (as ShaderError, with file
    // and line, exit 2): counted here too they printed twice and made the window exit 3.
    if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
    if (type == GL_DEBUG_TYPE_ERROR) report(message ? message : "(no message)");
}

const char* errorName(GLenum e) {
    switch (e) {
        case GL_INVALID_ENUM:
            return "GL_INVALID_ENUM";
        case GL_INVALID_VALUE:
            return "GL_INVALID_VALUE";
        case GL_INVALID_OPERATION:
            return "GL_INVALID_OPERATION";
        case GL_INVALID_FRAMEBUFFER_OPERATION:
            return "GL_INVALID_FRAMEBUFFER_OPERATION";
        case GL_OUT_OF_MEMORY:
            return "GL_OUT_OF_MEMORY";
        default:
            return "unknown GL error";
    }
}
}  // namespace

PassScope::PassScope(const char* name) : previous_(g_pass) {
    g_pass = name;
}
PassScope::~PassScope() {
    g_pass = previous_;
}

void installGlDebugOutput(bool raisesStudentErrors) {
    g_raisesStudentErrors = raisesStudentErrors;
    resetGlErrorCount();
    if (GLAD_GL_KHR_debug || GLAD_GL_VERSION_4_3) {
        glEnable(GL_DEBUG_OUTPUT);
        glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);  // errors arrive inside the call that caused them
        glDebugMessageCallback(onDebugMessage, nullptr);
    }
}

int glErrorCount() {
    return g_errors;
}
void resetGlErrorCount() {
    g_errors = 0;
    g_errorFiles.clear();
}
std::string lastGlError() {
    return g_lastError;
}

void setProgramInUse(const std::string& studentFiles) {
    g_programFiles = studentFiles;
}
std::string glErrorShaderFiles() {
    return g_errors > 0 ? g_errorFiles : std::string();
}

void throwGlFailure(bool failed, const std::string& what) {
    if (!failed) return;
    if (!glErrorShaderFiles().empty())
        throw ShaderError(glErrorShaderFiles() + ": drawing with this shader raised " +
                          lastGlError() +
                          " (it breaks a GL rule at draw time, e.g. two sampler types on one "
                          "texture unit)");
    throw std::runtime_error(what + " raised " + std::to_string(g_errors) +
                             " GL error(s); last: " + lastGlError());
}

bool checkGlErrors(const char* file, int line) {
    bool ok = true;
    for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError()) {
        // The callback already counted this one when it is installed in this context (check's
        // contexts have none); count it once.
        if (!((GLAD_GL_KHR_debug || GLAD_GL_VERSION_4_3) && glIsEnabled(GL_DEBUG_OUTPUT)))
            report(std::string(errorName(e)) + " at " + file + ":" + std::to_string(line));
        ok = false;
    }
    return ok;
}

const char* framebufferStatusName(GLenum status) {
    switch (status) {
        case GL_FRAMEBUFFER_COMPLETE:
            return "GL_FRAMEBUFFER_COMPLETE";
        case GL_FRAMEBUFFER_UNDEFINED:
            return "GL_FRAMEBUFFER_UNDEFINED";
        case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT:
            return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
        case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
            return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
        case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER:
            return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER";
        case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER:
            return "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER";
        case GL_FRAMEBUFFER_UNSUPPORTED:
            return "GL_FRAMEBUFFER_UNSUPPORTED";
        case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE:
            return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
        case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS:
            return "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS";
        default:
            return "unknown framebuffer status";
    }
}

std::string checkFramebufferComplete(const char* what) {
    GLenum status = glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER);
    if (status == GL_FRAMEBUFFER_COMPLETE) return {};
    std::string msg = std::string(what) + ": " + framebufferStatusName(status);
    report("framebuffer incomplete: " + msg);
    return msg;
}

}  // namespace sl
