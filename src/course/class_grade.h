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
    int jobs = 1;
    GradeSettings settings;
};

// Exit 0 when every student was graded (whatever their points), 3 on a platform failure.
int runClassGrade(const ClassGradeArgs& args);

}  // namespace sl
