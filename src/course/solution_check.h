// Before students see an assignment (GUIDE section 7): the solution (the shipped shaders, or an
// instructor's own with --solutions) is graded by the assignment as a student's hand-in would
// be, and any row it loses refuses the release or the grading: an extra view that our own
// method fails, a lesson whose expectation the solution does not meet, would otherwise cost
// every correct student those points.
#pragma once

#include <functional>

#include "course/release.h"
#include "grade/grade_students.h"

namespace sl {

// Grades the due stages' files of `trees` by `a` through the one-student path (gradeStudents).
// Returns the solution's record when it earns every point. Throws AssignmentError (exit 2)
// naming the first row it loses (its stage, view, lesson, verdict and message, and the JSON path
// of the assignment entry that made it: the stage or the extra view) and how many points the
// solution loses in all; a stage of the solution that does not build is refused the same way,
// and so is a graded row that draws with a marked file its stage does not list (students have
// only its stub).
// Throws std::runtime_error (exit 3) when the grading itself failed (NOT GRADED: a GL or
// platform failure; TIMEOUT or CRASH of our own solution: rerun).
// `gradingStarts` is called once what the files alone show has passed, before any rendering
// (where the caller says it grades the solution: never before such a refusal).
StudentRecord verifySolution(const Assignment& a, const SolutionTrees& trees,
                             const GradeSettings& settings,
                             const std::function<void()>& gradingStarts = {});

}  // namespace sl
