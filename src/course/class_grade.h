// `grade SUBMISSIONS --assignment A.json --out DIR [--jobs N]`: a class in one command. Each
// entry of the folder SUBMISSIONS (a student's folder or .zip) is taken in safely, the class is
// split over N job processes (each one series of workers: references traced once per view per
// job), and each student's record is written atomically as soon as it is complete, so a run
// that is killed resumes with the students not yet written. Then grades.csv, a feedback page
// per student and the class page.
#pragma once

#include <string>

#include "course/grade_students.h"

namespace sl {

struct ClassGradeArgs {
    std::string submissions, assignment, out;
    std::string solutions;  // the instructor's own marked trees ("" = the shipped ones)
    int jobs = 1;
    GradeSettings settings;
};

// The solution is graded by the assignment first (course/solution_check.h): a row it loses
// refuses the grading (exit 2). Exit 0 when every student was graded (whatever their points),
// 3 on a platform failure.
int runClassGrade(const ClassGradeArgs& args);

}  // namespace sl
