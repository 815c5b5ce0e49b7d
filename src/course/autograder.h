// Gradescope's autograder package (gradescope-autograders.readthedocs.io, "Autograder
// Specifications"): autograder.zip holding setup.sh (installs the Debian/Ubuntu packages with
// the repository's scripts/deps.sh and builds shadowlab), run_autograder (grades
// /autograder/submission by the assignment into /autograder/results/results.json), the
// assignment and the shadowlab sources.
#pragma once

#include <string>
#include <vector>

#include "course/assignment.h"

namespace sl {

// The files the program's build reads (cmake/source_kit.py): `list` names them relative to
// `root`. Found beside the installed data, else beside the program in its build tree.
struct SourceKit {
    std::string list;
    std::string root;
};
SourceKit findSourceKit();
std::vector<std::string> readSourceKit(const SourceKit& kit);

// Writes OUTDIR/autograder.zip: setup.sh, run_autograder, the assignment and the source kit
// under shadowlab/. Returns its name.
std::string writeAutograderZip(const Assignment& a, const std::string& assignmentPath,
                               const std::string& outDir);

// The two scripts, as written into the zip.
std::string autograderSetupScript();
std::string autograderRunScript();

}  // namespace sl
