#include "course/assignment_check.h"

#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "course/intake_adapter.h"
#include "course/student_grade.h"
#include "gradebook/late_policy.h"
#include "io/files.h"
#include "io/usage_error.h"
#include "sandbox/private_dir.h"

namespace sl {

namespace {

// When Gradescope says the hand-in came (created_at), or why it cannot say: the file is the
// platform's, so a missing or malformed one costs the student nothing (no penalty, a note).
std::optional<long long> gradescopeTime(const std::string& path, std::string& why) {
    std::string text;
    std::string err = readRegularFile(path, 1u << 20, text);
    if (!err.empty()) {
        why = err;
        return std::nullopt;
    }
    nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object() || !j.contains("created_at") ||
        !j["created_at"].is_string()) {
        why = printableName(path) + " holds no created_at time";
        return std::nullopt;
    }
    std::optional<long long> t = parseIsoTime(j["created_at"].get<std::string>());
    if (!t) why = printableName(path) + ": created_at is not an ISO 8601 time with a zone";
    return t;
}

}  // namespace

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
    if (!args.submissionMetadata.empty() && a.late) {
        std::string why;
        std::optional<long long> handedIn = gradescopeTime(args.submissionMetadata, why);
        if (handedIn)
            settings.annotate = [late = *a.late, t = *handedIn](StudentRecord& r) {
                r.late = lateFor(late, t, "Gradescope's created_at", r.maxScore, r.score);
            };
        else
            std::cerr << "shadowlab: note: no late policy applied: " << printable(why) << "\n";
    }
    GradingPlan plan = planStudent(a, s, settings.seed);
    return gradeOneStudent(plan, s, settings, args.out, "shadowlab check",
                           "check by " + printableName(args.assignment) + " (" + a.name +
                               "), shaders " + printableName(args.shaders));
}

}  // namespace sl
