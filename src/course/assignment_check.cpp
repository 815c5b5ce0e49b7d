#include "course/assignment_check.h"

#include <filesystem>
#include <iostream>

#include "course/intake_adapter.h"
#include "course/student_grade.h"
#include "grade/private_dir.h"
#include "io/files.h"

namespace sl {

int runAssignmentCheck(const AssignmentCheckArgs& args) {
    if (args.shaders.empty())
        throw UsageError(
            "check --assignment: give the student's work with --shaders DIR (a folder or .zip)");
    if (!args.out.diff.empty())
        throw UsageError("--diff: with --assignment use --diff-dir DIR (one image per row)");
    validateOutputs(args.out, args.shaders);
    Assignment a = loadAssignment(args.assignment);
    PrivateDir work("shadowlab-intake");
    StudentWork s = intakeForAssignment(a, args.shaders, work.path() + "/s");
    for (const auto& n : s.notes) std::cerr << "shadowlab: note: " << printable(n) << "\n";
    if (!s.error.empty()) std::cerr << "shadowlab: " << printable(s.error) << "\n";
    GradeSettings settings = args.settings;
    if (!args.out.diffDir.empty())
        settings.imageDir = [dir = args.out.diffDir](const StudentWork&) { return dir; };
    GradingPlan plan = planStudent(a, s, settings.seed);
    return gradeOneStudent(plan, s, settings, args.out, "shadowlab check",
                           "check by " + printableName(args.assignment) + " (" + a.name +
                               "), shaders " + printableName(args.shaders));
}

}  // namespace sl
