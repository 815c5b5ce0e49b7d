// `check --assignment A.json --shaders DIR`: one submission graded by an assignment.
#pragma once

#include <string>

#include "course/grade_students.h"

namespace sl {

struct AssignmentCheckArgs {
    std::string assignment, shaders, report, format = "json", junit, diffDir;
    GradeSettings settings;
};

// Prints one line per row and the points per stage; writes the report (ours or Gradescope's),
// JUnit and the images when asked. Exit 0 all points, 1 points lost (FAIL or MISSING), 2 a
// stage that did not build or the submission unreadable, 3 a platform failure.
int runAssignmentCheck(const AssignmentCheckArgs& args);

// The exit code a record earns (as above).
int recordExitCode(const nlohmann::json& record);

}  // namespace sl
