// Source rules: parser-based rubrics (as in Andujar et al.'s GLSL grading tool at UPC) that read
// what a stage's shaders say where a picture cannot show it. A rule is data of the stage
// (StageDefinition::sourceRules); a finding is a note on the row for the instructor, not a score.
// The rules read glslang's syntax tree of a built program (gl/glsl_syntax.h) through a small
// data-flow analysis: which inputs (uniforms, vertex attributes, built-ins) each value depends on,
// through variables, functions and the vertex -> fragment interface.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "gl/glsl_standard.h"

namespace sl {

// Inputs that stand for one thing, under the names a shader may read it by.
// The input every screen-space derivative (dFdx, dFdy, fwidth) carries besides its argument's:
// the surface's slope on screen, of which `normalize(cross(dFdx(p), dFdy(p)))` is the normal. Not
// an identifier, so no shader's own name is taken for it.
inline constexpr const char* kScreenDerivative = "dFdx()";

struct NameGroup {
    std::string label;               // "the normal"
    std::vector<std::string> names;  // "normal", "gl_Normal"
};

struct SourceRule {
    enum class Kind {
        // A comparison that reads `sampler` (the shadow test) must depend on every group.
        ComparisonDependsOn,
        // A comparison of a value made only of the groups' inputs against a constant is flagged.
        ConstantComparison,
    };
    Kind kind = Kind::ConstantComparison;
    std::string pass;  // the pass whose program is read; "" every pass of the stage
    std::string sampler;
    std::vector<NameGroup> groups;
    std::string why;  // what a finding means, for the note

    static SourceRule comparisonDependsOn(std::string pass, std::string sampler,
                                          std::vector<NameGroup> groups, std::string why);
    static SourceRule constantComparison(std::vector<NameGroup> groups, std::string why);
};

// One built program: its pass, glslang's trees and the file behind each source-string number.
struct ProgramSource {
    std::string pass;
    StageTrees trees;
    std::vector<std::string> vertexFiles, fragmentFiles;
    std::function<bool(const std::string& file)> students;  // whether a file is the student's
};

// The findings of `rules` on `program`, each one line naming the student's file and line.
// A rule looks only at the student's files: our shaders are never a finding.
std::vector<std::string> sourceFindings(const std::vector<SourceRule>& rules,
                                        const ProgramSource& program);

}  // namespace sl
