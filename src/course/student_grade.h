// An assignment's plan for one student (grade/plan.h): its due stages, each with the rows of
// course/assignment.h's planStage, or MISSING when a listed file is not in the hand-in.
#pragma once

#include <optional>

#include "course/assignment.h"

namespace sl {

GradingPlan planStudent(const Assignment& a, const StudentWork& s,
                        std::optional<std::uint64_t> seed);

}  // namespace sl
