// An assignment's plan for one student (grade/plan.h): its due stages, each with the rows of
// course/assignment.h's planStage, or MISSING when a listed file is not in the hand-in.
#pragma once

#include <optional>

#include "course/assignment.h"

namespace sl {

GradingPlan planStudent(const Assignment& a, const StudentWork& s,
                        std::optional<std::uint64_t> seed);

// The due stages' names, in the assignment's order.
std::vector<std::string> dueStageNames(const Assignment& a);

// A note per due stage whose folder holds files of the student's that the assignment does not
// list (`hardware/lit_pcf3x3.frag` when it grades `hardware/lit.frag`): they are not graded, and
// the student should know. Files another note already names (a near miss) are left out.
std::vector<std::string> unlistedFileNotes(const Assignment& a, const StudentWork& s);

}  // namespace sl
