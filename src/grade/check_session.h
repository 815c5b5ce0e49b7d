// `check`: one student graded by a plan, the outputs drawn from their record. `--stage` and
// `--all` grade a default plan (every lesson and view of the stages asked for, a point a row,
// the stage's own files due); `--assignment` (course/assignment_check.h) an assignment's plan.
// Both print the same table and summary, write the same report, JUnit and Gradescope files, and
// exit with the record's code.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "grade/check_plan.h"

namespace sl {

// Throws UsageError (exit 2) for a bad format, or outputs that would overwrite one another or
// land inside the student's folder `submission` ("" for none).
void validateOutputs(const CheckOutputs& out, const std::string& submission);

// Grades `work` by `plan` in bounded workers, printing `headline`, a line per row as its stage
// finishes and a summary; writes the outputs. Returns the record's exit code. `tool` names the
// report's tool ("shadowlab check").
int gradeOneStudent(const GradingPlan& plan, const StudentWork& work, GradeSettings settings,
                    const CheckOutputs& out, const std::string& tool, const std::string& headline);

// `check --stage/--all`.
int runStageCheck(const StageCheckArgs& args);

}  // namespace sl
