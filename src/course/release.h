// The student release (docs/assignment.md, "Solution markers"): the due stages' files with each
// solution region replaced by its stub, the assignment's public part and a README for students.
#pragma once

#include <string>
#include <vector>

#include "course/assignment.h"

namespace sl {

// `text` with every region between "// BEGIN SOLUTION" and "// END SOLUTION" lines removed and
// the "// STUB: " lines that follow the region turned into code (the prefix cut). A region
// without STUB lines gets "// TODO: write this part". Throws AssignmentError naming `origin`
// and the line on a marker out of place (unclosed, nested, END without BEGIN).
// `solution` receives the removed lines.
std::string stripSolutions(const std::string& text, const std::string& origin,
                           std::vector<std::string>* solution = nullptr);

// Writes the release into `outDir` (created; must be empty or absent): shaders/<files of every
// due stage>, assignment.json (the public part) and README.md. Returns the files written.
std::vector<std::string> writeRelease(const Assignment& a, const std::string& assignmentPath,
                                      const std::string& outDir);

}  // namespace sl
