// Solution markers (docs/assignment.md, "Solution markers"): the regions `release` stubs, read
// by one tokenizer. A file of its own with no dependency above io/, so the fuzzer runs it alone.
#pragma once

#include <string>
#include <vector>

#include "course/assignment_error.h"

namespace sl {

// `text` with every region between "// BEGIN SOLUTION" and "// END SOLUTION" lines removed and
// the "// STUB: " lines that follow the region turned into code (the prefix cut). A region
// without STUB lines gets "// TODO: write this part". Throws AssignmentError naming `origin`
// and the line on a marker out of place (unclosed, nested, END without BEGIN) and on any line
// that looks like a marker without being the exact form ("//BEGIN SOLUTION", "/* BEGIN
// SOLUTION */", "// begin solution", "// END-SOLUTION", "//STUB:", a marker after code...):
// such a line would otherwise ship its region's solution. `solution` receives the removed lines.
std::string stripSolutions(const std::string& text, const std::string& origin,
                           std::vector<std::string>* solution = nullptr);

}  // namespace sl
