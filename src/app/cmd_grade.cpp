// `shadowlab grade SUBMISSIONS --assignment A.json --out DIR [--jobs N|auto]`: a whole class graded
// by an assignment (src/class/class_grade.h): grades.csv, a feedback page per student, the
// class page and the JSON record per student; resumable, and a rerun regrades what changed.
// The solution is graded by the assignment first (course/solution_check.h).
#include <memory>

#include "app/commands.h"
#include "class/class_grade.h"
#include "io/usage_error.h"

namespace sl {

namespace {

int parseJobs(const std::string& text) {
    const bool digits = !text.empty() && text.size() <= 2 &&
                        text.find_first_not_of("0123456789") == std::string::npos;
    const int n = digits ? std::stoi(text) : 0;
    if (n < 1 || n > 64) throw UsageError("--jobs: give 1 to 64, or auto");
    return n;
}

}  // namespace

Command addGradeCommand(CLI::App& app) {
    auto args = std::make_shared<ClassGradeArgs>();
    auto backend = std::make_shared<std::string>("auto");
    auto seed = std::make_shared<std::optional<std::uint64_t>>();
    auto limits = std::make_shared<LimitOptions>();
    auto* cmd = app.add_subcommand("grade", "grade a class's submissions by an assignment");
    cmd->add_option("SUBMISSIONS", args->submissions,
                    "a folder with one folder or .zip per student")
        ->required();
    cmd->add_option("--assignment", args->assignment, "the assignment file (docs/assignment.md)")
        ->required();
    cmd->add_option("--out", args->out, "the folder to write grades.csv, pages and records to")
        ->required();
    auto jobs = std::make_shared<std::string>("auto");
    cmd->add_option("--jobs", *jobs,
                    "job processes grading in parallel, 1 to 64, or auto (default: one a usable "
                    "core, as memory allows)");
    cmd->add_option("--regrade", args->regrade,
                    "grade these students again (hand-in names), whatever their records say");
    cmd->add_flag("--regrade-all", args->regradeAll, "grade every student again");
    cmd->add_option("--roster", args->roster,
                    "a CSV of id,name,email,hand-in: carried into records, grades.csv and "
                    "pages; a student with no hand-in gets a row");
    cmd->add_option("--times", args->times,
                    "a CSV of hand-in,time (ISO 8601): when each hand-in came, for the "
                    "assignment's late policy (default: the newest time of its files)");
    cmd->add_option("--adjust", args->adjust,
                    "a CSV of hand-in,stage,points,reason: TAs' adjustments, kept for later "
                    "runs and applied to the totals");
    cmd->add_option("--backend", *backend, "headless GL: auto, osmesa or egl");
    cmd->add_option("--seed", *seed,
                    "the displaced views' seed, one for the class (in every record); default: "
                    "drawn now");
    cmd->add_option("--solutions", args->solutions,
                    "your own marked shaders to grade first (DIR/shaders_core/..., "
                    "DIR/shaders_legacy/...; default: the shipped ones)");
    addLimitOptions(cmd, *limits);
    return {cmd, [args, backend, seed, limits, jobs] {
                return guarded([&] {
                    args->jobs = *jobs == "auto" ? 0 : parseJobs(*jobs);
                    args->settings.backend = toBackend(*backend);
                    args->settings.budget = limits->rule();
                    args->seed = *seed;
                    return runClassGrade(*args);
                });
            }};
}

}  // namespace sl
