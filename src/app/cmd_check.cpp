// `shadowlab check`: its options, handed to grade/ (grade/check_session.h: --stage and --all)
// or course/ (course/assignment_check.h: --assignment). Both grade one student by a plan in
// bounded workers and draw every output from the student's record.
#include <memory>

#include "app/commands.h"
#include "course/assignment_check.h"
#include "grade/check_session.h"
#include "io/usage_error.h"
#include "stages/registry.h"

namespace sl {

namespace {

struct CheckArgs {
    CommonOptions common;
    LimitOptions limits;
    std::string stage, assignment, submissionMetadata;
    CheckOutputs out;
    bool all = false, glslGiven = false, shadersGiven = false;
    std::optional<std::uint64_t> seed;  // --seed: the displaced view's; else drawn at start
};

GradeSettings settingsOf(const CheckArgs& a) {
    GradeSettings s;
    s.backend = toBackend(a.common.backend);
    s.budget = a.limits.rule();
    s.seed = a.seed ? *a.seed : drawSeed();
    return s;
}

int runCheckCommand(const CheckArgs& a) {
    if (!a.assignment.empty()) {
        if (a.all || !a.stage.empty())
            throw UsageError(
                "--assignment: the assignment names the stages; leave out --stage and --all");
        AssignmentCheckArgs args{a.assignment, a.common.shaders, a.submissionMetadata, a.out,
                                 settingsOf(a)};
        args.settings.pictures = !a.out.diffDir.empty();
        return runAssignmentCheck(args);
    }
    if (a.all == !a.stage.empty()) throw UsageError("check: give either --stage ID or --all");
    if (a.shadersGiven && a.common.shaders.empty())
        throw UsageError("--shaders: empty; give the student's folder (its files replace ours)");
    StageCheckArgs args;
    CommonOptions common = a.common;
    common.stage = a.all ? lightingStage().id : a.stage;
    args.base = toRequest(common);
    args.all = a.all;
    args.glslGiven = a.glslGiven;
    args.narrowed = !args.base.sets.empty() || args.base.sceneGiven;
    args.customView = args.base.eye || args.base.at || args.base.light || args.base.fovy;
    args.out = a.out;
    args.settings = settingsOf(a);
    return runStageCheck(args);
}

}  // namespace

Command addCheckCommand(CLI::App& app) {
    auto args = std::make_shared<CheckArgs>();
    auto* cmd = app.add_subcommand(
        "check", "judge stages against the ray-traced reference and their expected lesson");
    addCommonOptions(cmd, args->common, false);
    cmd->add_option("--stage", args->stage, "the stage to check (see `shadowlab stages`)");
    cmd->add_flag("--all", args->all, "every stage in both shader trees");
    cmd->add_option("--report", args->out.report,
                    "write the student's record as JSON (fields: docs/check.md)");
    cmd->add_option("--diff", args->out.diff,
                    "diff image of one stage: red false shadow, blue false lit, grey agreement");
    cmd->add_option("--diff-dir", args->out.diffDir,
                    "one diff image per row: DIR/<stage>-<tree>-<view>[-<settings>].png");
    cmd->add_option("--format", args->out.format,
                    "the --report's format: json (ours, default) or gradescope (results.json)");
    cmd->add_option("--junit", args->out.junit, "also write JUnit XML: one testcase per row");
    cmd->add_option("--seed", args->seed,
                    "the displaced views' seed (as the report's \"seed\"); default: drawn now");
    cmd->add_option("--assignment", args->assignment,
                    "grade --shaders DIR by an assignment file: its stages, points and visibility "
                    "(docs/assignment.md)");
    cmd->add_option("--submission-metadata", args->submissionMetadata,
                    "with --assignment: Gradescope's submission_metadata.json; its created_at "
                    "is when the hand-in came, for the assignment's late policy");
    addLimitOptions(cmd, args->limits);
    return {cmd, [args, cmd] {
                args->glslGiven = cmd->count("--glsl") > 0;
                args->shadersGiven = cmd->count("--shaders") > 0;
                return guarded([&] { return runCheckCommand(*args); });
            }};
}

}  // namespace sl
