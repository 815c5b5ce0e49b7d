// Gradescope's autograder package (gradescope-autograders.readthedocs.io, "Autograder
// Specifications"): autograder.zip holding setup.sh (installs the Debian/Ubuntu packages with
// the repository's scripts/deps.sh and builds shadowlab), run_autograder (grades
// /autograder/submission by the assignment into /autograder/results/results.json), the
// assignment and the shadowlab sources.
#pragma once

#include <string>

#include "course/assignment.h"

namespace sl {

// Writes OUTDIR/autograder.zip; returns its name. Needs the source tree (CMakeLists.txt beside
// the data), as a checkout has it.
std::string writeAutograderZip(const Assignment& a, const std::string& assignmentPath,
                               const std::string& outDir);

// The two scripts, as written into the zip.
std::string autograderSetupScript();
std::string autograderRunScript();

}  // namespace sl
