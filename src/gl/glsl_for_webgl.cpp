// WebGL 2 compiles ESSL 3.00: the checked GLSL (gl/glsl_standard.h) translated mechanically, as
// `glslangValidator -G --aml --amb` and `spirv-cross --es --version 300` do (the same sources,
// Debian's, compiled to WebAssembly: scripts/web_sources.py). The translation keeps every name
// and expression; only types gain precisions, vertex inputs lose the locations glslang gave them
// (glBindAttribLocation decides them, as on the desktop), a depth compare's reference is
// clamped as the GL specification clamps it (EsslWriter below) and loops count into the page's
// loop budget (gl/loop_guard.h).
#include "gl/gl.h"

#include <SPIRV/GlslangToSpv.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <spirv_glsl.hpp>
#include <string>
#include <vector>

#include "gl/glsl_for_driver.h"
#include "gl/glsl_standard.h"
#include "gl/loop_guard.h"
#include "gl/shader_library.h"

namespace sl {

namespace {

std::string fileName(const GlslSource& source) {
    return source.files.empty() ? std::string("shader") : source.files[0];
}

// glslang -> SPIR-V for OpenGL (glslangValidator -G, auto-mapped locations and bindings).
std::vector<unsigned> toSpirv(const GlslSource& source, EShLanguage language) {
    glslang::TShader shader(language);
    const char* text = source.text.c_str();
    shader.setStrings(&text, 1);
    shader.setEnvInput(glslang::EShSourceGlsl, language, glslang::EShClientOpenGL, 100);
    shader.setEnvClient(glslang::EShClientOpenGL, glslang::EShTargetOpenGL_450);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
    shader.setAutoMapLocations(true);
    shader.setAutoMapBindings(true);
    const auto messages = EShMessages(EShMsgDefault | EShMsgSpvRules);
    glslang::TProgram program;
    if (shader.parse(GetDefaultResources(), 100, false, messages)) {
        program.addShader(&shader);
        if (program.link(messages) && program.mapIO()) {
            std::vector<unsigned> spirv;
            glslang::GlslangToSpv(*program.getIntermediate(language), spirv);
            return spirv;
        }
    }
    throw ShaderError(fileName(source) + ": error: glslang could not translate it for WebGL:\n" +
                      shader.getInfoLog() + program.getInfoLog());
}

// SPIRV-Cross's ESSL writer, with every 2D depth compare's reference clamped to the range the GL
// layer sets before each draw (es3::kDepthReferenceRange, gl/gl_es3.h): [0, 1] for a fixed-point
// map, as ES 3.0 and desktop GL require and SwiftShader omits. Within the range the clamp gives
// the reference itself, so nothing else changes.
class EsslWriter : public spirv_cross::CompilerGLSL {
  public:
    using CompilerGLSL::CompilerGLSL;
    bool clampsDepthReference() const { return clamps_; }

  protected:
    std::string to_function_args(const TextureFunctionArguments& args, bool* forward) override {
        const spirv_cross::SPIRType& image = *args.base.imgtype;
        if (!args.dref || args.base.is_gather || image.image.dim != spv::Dim2D ||
            image.image.arrayed)
            return CompilerGLSL::to_function_args(args, forward);
        clamps_ = true;
        const std::string range = es3::kDepthReferenceRange;
        const std::string ref = to_enclosed_expression(args.dref);
        std::string clamped;
        if (args.base.is_proj) {  // the reference is divided by q after: clamp it times q
            const std::string q = to_enclosed_expression(args.coord) + ".z";
            const std::string lo = range + ".x * " + q, hi = range + ".y * " + q;
            clamped =
                "clamp(" + ref + ", min(" + lo + ", " + hi + "), max(" + lo + ", " + hi + "))";
        } else {
            clamped = "clamp(" + ref + ", " + range + ".x, " + range + ".y)";
        }
        TextureFunctionArguments within = args;
        within.dref = ir.increase_bound_by(1);
        set<spirv_cross::SPIRExpression>(within.dref, clamped, expression_type_id(args.dref), true);
        return CompilerGLSL::to_function_args(within, forward);
    }

  private:
    bool clamps_ = false;
};

// The range's declaration after the #version line, where a shader clamps with it.
std::string withDepthReferenceRange(std::string essl) {
    std::size_t line = essl.find('\n') + 1;
    return essl.insert(line, std::string("uniform highp vec2 ") + es3::kDepthReferenceRange +
                                 ";  // shadowlab: docs/web.md, the depth compare\n");
}

}  // namespace

std::string glslForDriver(const GlslSource& source, ShaderKind kind) {
    const bool vertex = kind == ShaderKind::Vertex;
    try {
        EsslWriter compiler(toSpirv(source, vertex ? EShLangVertex : EShLangFragment));
        auto options = compiler.get_common_options();
        options.es = true;
        options.version = 300;
        compiler.set_common_options(options);
        compiler.build_combined_image_samplers();  // as the tool does for GLSL targets
        if (vertex)
            for (const auto& input : compiler.get_shader_resources().stage_inputs)
                compiler.unset_decoration(input.id, spv::DecorationLocation);
        std::string essl = guardLoops(compiler.compile(), !vertex, fileName(source));
        return compiler.clampsDepthReference() ? withDepthReferenceRange(std::move(essl)) : essl;
    } catch (const spirv_cross::CompilerError& e) {
        throw ShaderError(fileName(source) +
                          ": error: SPIRV-Cross could not translate it to ESSL "
                          "3.00: " +
                          e.what());
    }
}

bool addedByTranslation(const std::string& uniform) {
    return uniform == es3::kDepthReferenceRange || uniform == kLoopProbe;
}

}  // namespace sl
