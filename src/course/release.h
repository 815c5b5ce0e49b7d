// The student release (docs/assignment.md, "Solution markers"): the due stages' files with each
// solution region replaced by its stub, the assignment's public part and a README for students;
// and the student edition, every shipped shader with every marked region stubbed.
#pragma once

#include <string>
#include <vector>

#include "course/assignment.h"
#include "course/solution_markers.h"

namespace sl {

// Where the marked solution shaders come from: the shipped trees, or an instructor's own
// (`--solutions DIR`: DIR/shaders_core/<stage>/..., DIR/shaders_legacy/<stage>/..., the layout
// of the shipped data).
struct SolutionTrees {
    std::string dir;                                  // "" = the shipped trees
    std::string root(const std::string& tree) const;  // tree: "core" or "legacy"
    std::string describe() const;                     // for messages: "the shipped shaders" ...
};

// `--solutions DIR` checked: a folder holding shaders_core/ or shaders_legacy/ (UsageError
// otherwise). "" gives the shipped trees.
SolutionTrees solutionTrees(const std::string& dir);

// The files under `root`/`folder` (folder "" = the whole tree) that hold a solution region,
// relative to `root`, sorted. Throws like stripSolutions on a malformed marker.
std::vector<std::string> markedFiles(const std::string& root, const std::string& folder = "");

// A released shader: its path relative to the tree and its text with the regions stubbed.
struct StudentFile {
    std::string rel, text;
};

// The due stages' files from `trees`, stubbed, in assignment order; nothing written. Refuses a
// due file without a region (it would hand out the whole solution), a marker out of place or a
// look-alike.
std::vector<StudentFile> releasedShaders(const Assignment& a, const SolutionTrees& trees);

// UsageError when `outDir` exists and is not empty (checked before the solution is graded).
void checkReleaseOut(const std::string& outDir);

// Writes the release into `outDir` (created; must be empty or absent): shaders/<file> for each
// of `shaders`, assignment.json (the public part) and README.md. Returns the files written.
std::vector<std::string> writeRelease(const Assignment& a, const std::vector<StudentFile>& shaders,
                                      const std::string& outDir);

// The student edition's shader trees: `outDir`/shaders_core and `outDir`/shaders_legacy (made;
// `outDir` must not hold them yet), every file of `trees` copied with every marked region
// stubbed. What the default install ships (CMakeLists.txt). Returns how many files it stubbed.
int writeStudentEdition(const SolutionTrees& trees, const std::string& outDir);

}  // namespace sl
