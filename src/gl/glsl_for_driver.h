// The text a driver compiles for one checked stage file (gl/glsl_standard.h accepted it first).
// Desktop OpenGL compiles the GLSL itself (glsl_for_desktop.cpp); WebGL 2 compiles a mechanical
// translation to ESSL 3.00 (glsl_for_webgl.cpp: glslang -> SPIR-V -> SPIRV-Cross, as the
// spirv-cross tool does), which the browser edition shows beside the original. Which one is
// linked is the build's choice (CMakeLists.txt or cmake/web.cmake); the library never asks.
#pragma once

#include <string>

namespace sl {

struct GlslSource;  // gl/glsl_standard.h

enum class ShaderKind { Vertex, Fragment };

// Throws ShaderError (naming the stage file) where the translation fails.
std::string glslForDriver(const GlslSource& source, ShaderKind kind);

// Whether the translation declared `uniform` itself (the GL layer sets it; no stage does).
bool addedByTranslation(const std::string& uniform);

}  // namespace sl
