// Shader programs loaded from files: shaders_<tree>/<stage>/<pass>.vert|.frag, with a student's
// overlay folder whose files replace ours of the same relative name. `#include "x.glsl"` is
// resolved here (paths relative to the tree root, overlay first, never outside the two folders) and
// driver messages are mapped back to the file and line they came from. A reload that fails keeps
// the last good program.
#pragma once

#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "gl/program.h"

namespace sl {

struct SourceRule;     // gl/source_rules.h
struct ProgramSource;  // gl/source_rules.h
struct GlslSource;     // gl/glsl_standard.h

enum class GlslTree { Core, Legacy };
const char* treeName(GlslTree t);  // "core" | "legacy"

// Compile, link, missing-file or sandbox errors; what() is the full, file-and-line message,
// with control characters and bytes that are not UTF-8 replaced (it quotes students' files).
class ShaderError : public std::runtime_error {
  public:
    explicit ShaderError(const std::string& message);
};

// Vertex attribute locations shared by every program and by the meshes.
enum AttributeLocation : GLuint { kPositionAttribute = 0, kNormalAttribute = 1 };

class ShaderLibrary {
  public:
    // `treeRoot`: the folder of our shaders for this tree; `overlay`: a student's folder or "".
    ShaderLibrary(GlslTree tree, std::string treeRoot, std::string overlay);

    GlslTree tree() const { return tree_; }
    const std::string& overlay() const { return overlay_; }

    // The program for stage/pass, built on first use. Throws ShaderError when it cannot be
    // built and no earlier good version exists.
    Program& program(const std::string& stage, const std::string& pass);

    // What the driver compiled for each program of `stage` built so far, {file, text} per stage
    // file (gl/glsl_for_driver.h): the expanded GLSL on desktop, its ESSL 3.00 in the browser.
    std::vector<std::pair<std::string, std::string>> driverTexts(const std::string& stage) const;

    // The uniforms the built programs of `stage` (its folder) were given but do not read.
    std::set<std::string> ignoredUniforms(const std::string& stage) const;

    // Rebuilds programs whose files changed on disk (all of them when `force`). A failed
    // rebuild keeps the previous program; its message is returned (empty vector: all good).
    // `stages` given: only the programs of those stages (the window adopts what its trial passed).
    std::vector<std::string> reload(bool force, const std::set<std::string>* stages = nullptr);

    // Where a relative shader path is found: the overlay's file if it has one, else ours.
    // Only files inside the overlay and our tree, after resolving ".." and symbolic links:
    // `refused` says why another path is not read.
    struct Found {
        std::string shown;    // the path as messages name it (overlay or tree + relative)
        std::string real;     // resolved, inside the sandbox; "" when missing or refused
        std::string refused;  // why the path is not allowed ("" when it is)
    };
    Found find(const std::string& relative) const;

    // The overlay's files (relative names, sorted) read by the programs of `stage` built so far:
    // pass files and includes, what a report row lists as the student's.
    std::vector<std::string> overlayFiles(const std::string& stage) const;

    // One note per uniform a student's pass of `stage` declares and uses but the stage never
    // sets in that pass (asked after a frame): "pass rgb/shadow (your shader) uses uniform
    // 'margin', which the stage never sets in that pass: it keeps its initial value (0)".
    std::vector<std::string> unsetUniformNotes(const std::string& stage);
    std::string resolve(const std::string& relative) const;  // find(relative).shown

    // What `rules` find in the student's files of the programs of `stage` built so far
    // (gl/source_rules.h), each finding once. Kept per program and by the rules' address: pass
    // the stage's own (StageDefinition::sourceRules), which live as long as the program.
    std::vector<std::string> sourceNotes(const std::string& stage,
                                         const std::vector<SourceRule>& rules) const;

    // The stage/pass program checked by the standard alone (gl/glsl_standard.h), no GL context
    // needed: glslang's syntax trees and files, as the source rules read them. Throws
    // ShaderError as program() would.
    ProgramSource standardProgram(const std::string& stage, const std::string& pass) const;

  private:
    struct Entry {
        Program program;
        std::vector<std::string> files;  // every file read, for change detection
        std::vector<long long> stamps;
        std::shared_ptr<const ProgramSource> source;                   // what the source rules read
        std::vector<std::pair<std::string, std::string>> driverTexts;  // {file, what was compiled}
        // sourceNotes' findings by the rules asked (a stage's rules live as long as the program):
        // every row of a stage asks again.
        mutable std::map<const void*, std::vector<std::string>> findings;
    };
    Entry build(const std::string& stage, const std::string& pass) const;
    // Watches the uniforms our version of the pass declares that the student's own (changed)
    // pass files drop (gl/shader_notes.cpp).
    void watchOurUniforms(Program& program, const std::string& stage, const std::string& pass,
                          const std::string& vertFile, const std::string& fragFile) const;
    // Expands the pass's two files into `vert` and `frag` and checks them by the standard.
    ProgramSource checkedSource(const std::string& stage, const std::string& pass, GlslSource& vert,
                                GlslSource& frag) const;

    GlslTree tree_;
    std::string root_;
    std::string overlay_;
    std::string realRoot_, realOverlay_;  // resolved once: the sandbox's two folders
    std::map<std::string, Entry> programs_;
};

}  // namespace sl
