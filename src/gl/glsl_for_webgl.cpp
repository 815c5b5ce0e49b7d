// WebGL 2 compiles ESSL 3.00: the checked GLSL (gl/glsl_standard.h) translated mechanically, as
// `glslangValidator -G --aml --amb` and `spirv-cross --es --version 300` do (the same sources,
// Debian's, compiled to WebAssembly: scripts/web_sources.py). The translation keeps every name
// and expression; only types gain precisions and vertex inputs lose the locations glslang gave
// them (glBindAttribLocation decides them, as on the desktop).
#include <SPIRV/GlslangToSpv.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <spirv_glsl.hpp>
#include <string>
#include <vector>

#include "gl/glsl_for_driver.h"
#include "gl/glsl_standard.h"
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

}  // namespace

std::string glslForDriver(const GlslSource& source, ShaderKind kind) {
    const bool vertex = kind == ShaderKind::Vertex;
    try {
        spirv_cross::CompilerGLSL compiler(
            toSpirv(source, vertex ? EShLangVertex : EShLangFragment));
        auto options = compiler.get_common_options();
        options.es = true;
        options.version = 300;
        compiler.set_common_options(options);
        compiler.build_combined_image_samplers();  // as the tool does for GLSL targets
        if (vertex)
            for (const auto& input : compiler.get_shader_resources().stage_inputs)
                compiler.unset_decoration(input.id, spv::DecorationLocation);
        return compiler.compile();
    } catch (const spirv_cross::CompilerError& e) {
        throw ShaderError(fileName(source) +
                          ": error: SPIRV-Cross could not translate it to ESSL "
                          "3.00: " +
                          e.what());
    }
}

}  // namespace sl
