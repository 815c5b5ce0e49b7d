// Acceptance by the standard: every program is checked by Khronos' reference front end (glslang)
// before a driver compiles it, so what the GLSL standard forbids is an error on every driver
// alike (NVIDIA's compiler takes GLSL 1.20 `in`, Cg's `saturate`, mismatched varyings; Mesa does
// not). Errors are ShaderErrors (gl/shader_library.h) naming the file and line, with glslang's own
// message.
#pragma once

#include <string>
#include <vector>

namespace sl {

enum class GlslTree;  // gl/shader_library.h

// One stage file with its includes expanded: source-string number k of `text` (`#line N k`, as
// the loader writes it) is files[k]; files[0] is the stage file itself.
struct GlslSource {
    std::string text;
    std::vector<std::string> files;
};

// glslang's syntax tree of each stage as glslang prints it (EShMsgAST): the input of the source
// rules (gl/source_rules.h). Lines read "S:L  <indent>node", S a source-string number.
struct StageTrees {
    std::string vertex, fragment;
};

// Checks a vertex + fragment program against the standard for the tree's context:
// - each stage file declares a #version the tree's context guarantees (legacy: OpenGL 2.1,
//   GLSL 1.10 or 1.20; core: OpenGL 3.3 core, GLSL 1.40, 1.50 or 3.30 core);
// - each stage parses with glslang for its declared version;
// - glslang links the two (types and qualifiers of the interface agree);
// - every input the fragment stage reads is an output the vertex stage declares.
// Deprecated but legal GLSL (`varying`, `gl_FragColor`, `texture2D` in 1.20) passes: glslang
// reports it as a warning, never an error. Throws ShaderError ("FILE:LINE: error: MESSAGE").
// Returns both stages' syntax trees.
StageTrees requireStandardGlsl(GlslTree tree, const GlslSource& vertex, const GlslSource& fragment);

}  // namespace sl
