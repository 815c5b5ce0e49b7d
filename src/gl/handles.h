// Move-only owners of GL objects. Every glGen*/glCreate* in the project lives here: a handle is
// created by its constructor, deleted by its destructor, and can be moved but never copied, so
// an object has exactly one owner and cannot leak or be deleted twice.
#pragma once

#include <utility>

#include "gl/gl.h"

namespace sl {

template <class Traits>
class GlHandle {
  public:
    GlHandle() = default;
    static GlHandle create() {
        GlHandle h;
        h.id_ = Traits::make();
        return h;
    }
    ~GlHandle() { reset(); }
    GlHandle(GlHandle&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
    GlHandle& operator=(GlHandle&& o) noexcept {
        if (this != &o) {
            reset();
            id_ = std::exchange(o.id_, 0);
        }
        return *this;
    }
    GlHandle(const GlHandle&) = delete;
    GlHandle& operator=(const GlHandle&) = delete;

    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset() {
        if (id_) Traits::destroy(id_);
        id_ = 0;
    }

  private:
    GLuint id_ = 0;
};

// Traits for each kind of object: how to make one and how to delete it.
#define SL_GL_GEN_TRAITS(Name, gen, del)                \
    struct Name##Traits {                               \
        static GLuint make() {                          \
            GLuint id = 0;                              \
            gen(1, &id);                                \
            return id;                                  \
        }                                               \
        static void destroy(GLuint id) { del(1, &id); } \
    };                                                  \
    using Name = GlHandle<Name##Traits>;

SL_GL_GEN_TRAITS(Buffer, glGenBuffers, glDeleteBuffers)
SL_GL_GEN_TRAITS(VertexArray, glGenVertexArrays, glDeleteVertexArrays)
SL_GL_GEN_TRAITS(Texture, glGenTextures, glDeleteTextures)
SL_GL_GEN_TRAITS(Framebuffer, glGenFramebuffers, glDeleteFramebuffers)
SL_GL_GEN_TRAITS(Renderbuffer, glGenRenderbuffers, glDeleteRenderbuffers)
SL_GL_GEN_TRAITS(Sampler, glGenSamplers, glDeleteSamplers)
#undef SL_GL_GEN_TRAITS

struct ProgramTraits {
    static GLuint make() { return glCreateProgram(); }
    static void destroy(GLuint id) { glDeleteProgram(id); }
};
using ProgramHandle = GlHandle<ProgramTraits>;

template <GLenum kind>
struct ShaderTraits {
    static GLuint make() { return glCreateShader(kind); }
    static void destroy(GLuint id) { glDeleteShader(id); }
};
using VertexShader = GlHandle<ShaderTraits<GL_VERTEX_SHADER>>;
using FragmentShader = GlHandle<ShaderTraits<GL_FRAGMENT_SHADER>>;

}  // namespace sl
