// What `check --stage/--all` grades, planned from its options alone (no files written, no GL):
// the requests (a stage, or every stage in its trees) and the default plan of their rows. The
// native check grades the plan in bounded workers (grade/check_session.h), the browser edition
// in the page (grade/check_steps.h): one plan, one verdict.
#pragma once

#include <string>
#include <vector>

#include "grade/grade_students.h"
#include "grade/intake.h"

namespace sl {

// Where a check writes what it found.
struct CheckOutputs {
    std::string report, format = "json", junit;
    std::string diff, diffDir;  // --diff FILE.png (one stage) or --diff-dir DIR
};

struct StageCheckArgs {
    RenderRequest base;  // the common options (stage, tree, scene, overlay, size, camera, sets)
    bool all = false, glslGiven = false, narrowed = false, customView = false;
    CheckOutputs out;
    GradeSettings settings;
};

// The requests `check` runs: `--all`'s every stage in every tree it runs in (or the --glsl
// tree), tree by tree in lecture order, --set values to the stages that declare them; else the
// base request, in the legacy tree for a legacy-only stage without --glsl. `notes` gets what the
// user should know (a tree chosen for them, a scene without a mirror). Throws UsageError for a
// --set no stage declares.
std::vector<RenderRequest> checkRequests(const StageCheckArgs& a, std::vector<std::string>& notes);

// check's default plan: one stage per request, every lesson and view of it, a point a row; the
// stage's own files due (those the student handed in, or all of them when none: MISSING).
GradingPlan defaultPlan(const StageCheckArgs& a, const std::vector<RenderRequest>& requests,
                        const Submission* submission);

}  // namespace sl
