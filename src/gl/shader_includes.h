// A stage file's source with its `#include "x.glsl"` lines expanded: each name found through
// the library (the student's overlay first, never outside the two folders), `#line` directives
// so a driver's message names the file and line it came from, and bounds on what one file may
// pull in (an include bomb or a device stops at once).
#pragma once

#include <string>

#include "gl/glsl_standard.h"
#include "gl/shader_library.h"

namespace sl {

// `relative` (a stage file, "margin/lit.frag") with its includes expanded: files[k] is the file
// behind source-string number k. Throws ShaderError naming the file and line.
GlslSource expandIncludes(const ShaderLibrary& lib, GlslTree tree, const std::string& relative);

// Matches `#include "name"` (spaces allowed around each part); the name may be empty.
bool matchInclude(const std::string& line, std::string& name);

}  // namespace sl
