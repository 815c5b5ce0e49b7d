// GL error reporting: a KHR_debug callback that names the pass in progress, a counter the
// headless path turns into exit code 3, and framebuffer status by name.
#pragma once

#include <string>

#include "gl/gl.h"

namespace sl {

// Installs the debug-output callback (when the context offers KHR_debug) and resets the count.
// `raisesStudentErrors`: the caller turns errors raised while a student's program draws into one
// ShaderError line (throwGlFailure), so the callback does not print them too (headless paths).
void installGlDebugOutput(bool raisesStudentErrors = false);

// The pass in progress, named in every error message. Scoped: restores the previous name.
class PassScope {
  public:
    explicit PassScope(const char* name);
    ~PassScope();
    PassScope(const PassScope&) = delete;
    PassScope& operator=(const PassScope&) = delete;

  private:
    const char* previous_;
};

// Errors seen since the last reset, from the callback and from glGetError polls.
int glErrorCount();
void resetGlErrorCount();
std::string lastGlError();

// The student's files behind the program in use ("" for ours, or none): set by Program::use.
// A GL error raised while a student's program draws (two sampler types on one texture unit, an
// output the framebuffer cannot take) is the shader's fault, not the platform's.
void setProgramInUse(const std::string& studentFiles);
// The student's files that were in use at the first GL error since the last reset, or "".
std::string glErrorShaderFiles();
// Throws when `failed`: a ShaderError naming the student's files when one of their programs
// raised the errors (exit 2, ERROR in check), else std::runtime_error("WHAT raised a GL error").
void throwGlFailure(bool failed, const std::string& what);

// Polls glGetError, reports each error with file, line and pass. Returns false on error.
bool checkGlErrors(const char* file, int line);
#define SL_CHECK_GL() ::sl::checkGlErrors(__FILE__, __LINE__)

const char* framebufferStatusName(GLenum status);
// Checks the bound draw framebuffer; on failure reports "<what>: <STATUS NAME>" and returns it.
std::string checkFramebufferComplete(const char* what);

}  // namespace sl
