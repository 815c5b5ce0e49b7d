// The browser edition's acceptance (cmake/web.cmake builds this file instead of
// glsl_standard.cpp, which links glslang): the shipped tree the page runs was checked by
// glslang at build time and translated to ESSL 3.00 (scripts/web_shaders.py), so what reaches
// here must be that translation. No syntax trees: the source rules (grading's notes) do not
// run in the browser.
#include <string>

#include "gl/glsl_standard.h"
#include "gl/shader_library.h"

namespace sl {

namespace {

void requireTranslated(const GlslSource& source) {
    const std::string expected = "#version 300 es";
    if (source.text.compare(0, expected.size(), expected) != 0)
        throw ShaderError((source.files.empty() ? std::string("shader") : source.files[0]) +
                          ":1: error: the browser runs the build's ESSL 3.00 translation "
                          "(scripts/web_shaders.py), which starts with '" +
                          expected + "'");
}

}  // namespace

StageTrees requireStandardGlsl(GlslTree, const GlslSource& vertex, const GlslSource& fragment) {
    requireTranslated(vertex);
    requireTranslated(fragment);
    return {};
}

}  // namespace sl
