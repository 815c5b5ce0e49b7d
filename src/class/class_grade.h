// `grade SUBMISSIONS --assignment A.json --out DIR [--jobs N|auto]`: a class in one command.
// Each entry of the folder SUBMISSIONS (a student's folder or .zip) is taken in safely, the
// class is split over job processes (auto: one a usable core, as memory allows; each job one
// series of workers on its share of the cores: references traced and our shaders measured once
// per view per job, one Mesa shader cache for the run), and each student's record is written
// atomically as soon as it is complete. A rerun keeps a record only while the student's hand-in and
// the assignment are those it was graded from and it is a score (no NOT GRADED row); every other
// student is graded (again), and says why. Then grades.csv, a feedback page per student and the
// class page.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "grade/grade_students.h"

namespace sl {

struct ClassGradeArgs {
    std::string submissions, assignment, out;
    std::string solutions;             // the instructor's own marked trees ("" = the shipped ones)
    int jobs = 0;                      // 0: auto (jobsFor the box)
    std::vector<std::string> regrade;  // --regrade NAME...: these students again
    bool regradeAll = false;           // --regrade-all
    std::string roster;                // --roster roster.csv (gradebook/roster.h), or ""
    std::string times;                 // --times times.csv (gradebook/late_policy.h), or ""
    std::string adjust;                // --adjust adjust.csv (gradebook/adjustments.h), or ""
    // --seed: the displaced views' seed. Without it a class keeps the seed its records share
    // (a rerun, --regrade NAME), or draws one; a different seed over kept records is refused
    // unless --regrade-all grades everyone in the new views (one seed a class).
    std::optional<std::uint64_t> seed;
    GradeSettings settings;  // its seed is set by runClassGrade
};

// The solution is graded by the assignment first (course/solution_check.h): a row it loses
// refuses the grading (exit 2). Exit 0 when every student was graded (whatever their points),
// 3 when any is not graded (a platform failure: rerun, and exactly those are graded again).
int runClassGrade(const ClassGradeArgs& args);

}  // namespace sl
