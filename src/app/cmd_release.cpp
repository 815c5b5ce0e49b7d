// `shadowlab release --assignment A.json --out DIR [--solutions DIR] [--gradescope]`: what
// students receive (the due stages' files with their solutions replaced by stubs, the
// assignment's public part, a README), once the solution has earned every point of the
// assignment; with --gradescope also autograder.zip for Gradescope. `release --student-edition
// --out DIR`: every shader with every marked region stubbed (docs/assignment.md).
#include <iostream>
#include <memory>

#include "app/commands.h"
#include "app/options.h"
#include "course/autograder.h"
#include "course/release.h"
#include "course/solution_check.h"
#include "grade/check_run.h"
#include "io/files.h"
#include "io/usage_error.h"

namespace sl {

namespace {

struct ReleaseArgs {
    std::string assignment, out, solutions, backend = "auto";
    bool gradescope = false, studentEdition = false;
    LimitOptions limits;
    GradeSettings settings;
};

int runRelease(ReleaseArgs& args) {
    SolutionTrees trees = solutionTrees(args.solutions);
    if (args.studentEdition) {
        if (!args.assignment.empty() || args.gradescope)
            throw UsageError(
                "release --student-edition: takes no --assignment or --gradescope "
                "(it stubs every marked region of every stage)");
        int files = writeStudentEdition(trees, args.out);
        std::cout << "student edition of " << trees.describe() << " in " << printableName(args.out)
                  << ": shaders_core, shaders_legacy (" << files << " files stubbed)\n";
        return kOk;
    }
    if (args.assignment.empty())
        throw UsageError("release: give --assignment A.json (or --student-edition)");
    Assignment a = loadAssignment(args.assignment);
    checkReleaseOut(args.out);
    std::vector<StudentFile> shaders = releasedShaders(a, trees);
    args.settings.backend = toBackend(args.backend);
    args.settings.budget = args.limits.rule();
    args.settings.seed = drawSeed();
    StudentRecord record = verifySolution(a, trees, args.settings, [&] {
        std::cout << "grading the solution (" << trees.describe() << ") by "
                  << printableName(args.assignment) << " first, displaced view seed "
                  << *args.settings.seed << "\n"
                  << std::flush;
    });
    std::cout << "the solution earns every point: " << record.score << " of " << record.maxScore
              << "\n";
    std::vector<std::string> written = writeRelease(a, shaders, args.out);
    if (args.gradescope) written.push_back(writeAutograderZip(a, args.assignment, args.out));
    std::cout << "release of " << a.name << " in " << printableName(args.out) << ":\n";
    for (const auto& f : written) std::cout << "  " << printableName(f) << "\n";
    return kOk;
}

}  // namespace

Command addReleaseCommand(CLI::App& app) {
    auto args = std::make_shared<ReleaseArgs>();
    auto* cmd = app.add_subcommand(
        "release", "write an assignment's student release (solutions replaced by stubs)");
    cmd->add_option("--assignment", args->assignment, "the assignment file (docs/assignment.md)");
    cmd->add_option("--out", args->out, "the folder to write (absent or empty)")->required();
    cmd->add_option("--solutions", args->solutions,
                    "your own marked shaders: DIR/shaders_core/..., DIR/shaders_legacy/... "
                    "(default: the shipped ones)");
    cmd->add_flag("--gradescope", args->gradescope,
                  "also write autograder.zip (setup.sh, run_autograder) for Gradescope");
    cmd->add_flag("--student-edition", args->studentEdition,
                  "write shaders_core/ and shaders_legacy/ with every marked region stubbed "
                  "(what the default install ships)");
    cmd->add_option("--backend", args->backend, "headless GL for the solution's grading");
    addLimitOptions(cmd, args->limits);
    return {cmd, [args] { return guarded([&] { return runRelease(*args); }); }};
}

}  // namespace sl
