// `check --assignment A.json --shaders DIR`: one submission (a folder or .zip) graded by an
// assignment's plan through the same path as `check --stage` (grade/check_session.h).
#pragma once

#include <string>

#include "grade/check_session.h"

namespace sl {

struct AssignmentCheckArgs {
    std::string assignment, shaders;
    // Gradescope's /autograder/submission_metadata.json ("" = none): its created_at is when the
    // hand-in came, for the assignment's late policy (docs/assignment.md "Late policy").
    std::string submissionMetadata;
    CheckOutputs out;
    GradeSettings settings;
};

// Prints one line per row and the points per stage; writes the report (ours or Gradescope's),
// JUnit and the images when asked. Exits with the record's code (grade/status.h): 0 every
// point, 1 a FAIL, 2 MISSING, ERROR, TIMEOUT, CRASH or an unreadable hand-in, 3 NOT GRADED.
int runAssignmentCheck(const AssignmentCheckArgs& args);

}  // namespace sl
