// `shadowlab release --assignment A.json --out DIR [--gradescope]`: what students receive (the
// due stages' files with their solutions replaced by stubs, the assignment's public part, a
// README), and with --gradescope also autograder.zip for Gradescope (docs/assignment.md).
#include <iostream>
#include <memory>

#include "app/commands.h"
#include "course/autograder.h"
#include "course/release.h"
#include "io/files.h"

namespace sl {

namespace {

struct ReleaseArgs {
    std::string assignment, out;
    bool gradescope = false;
};

int runRelease(const ReleaseArgs& args) {
    Assignment a = loadAssignment(args.assignment);
    std::vector<std::string> written = writeRelease(a, args.assignment, args.out);
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
    cmd->add_option("--assignment", args->assignment, "the assignment file (docs/assignment.md)")
        ->required();
    cmd->add_option("--out", args->out, "the folder to write (absent or empty)")->required();
    cmd->add_flag("--gradescope", args->gradescope,
                  "also write autograder.zip (setup.sh, run_autograder) for Gradescope");
    return {cmd, [args] { return guarded([&] { return runRelease(*args); }); }};
}

}  // namespace sl
