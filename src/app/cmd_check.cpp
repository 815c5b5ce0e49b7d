// `shadowlab check (--stage ID | --all)`: renders stages headless, measures them against the
// ray-traced reference and judges each against its expectation (src/stages/expectations.json).
// One line per stage as it finishes, an optional JSON report and diff images; exit 0 when every
// stage shows its lesson, 1 when one does not, 2 on bad input (a student shader that does not
// build included), 3 on a GL failure.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>

#include "app/bench_output.h"
#include "app/check_run.h"
#include "app/commands.h"
#include "io/files.h"
#include "scene/scene_json.h"

namespace sl {

namespace {

struct CheckArgs {
    CommonOptions common;
    std::string stage, report, diff, diffDir;
    bool all = false, glslGiven = false;
};

bool declares(const StageInfo& info, const std::string& param) {
    for (const ParamSpec& p : info.params)
        if (p.name == param) return true;
    return false;
}

// The requests `--all` checks: every stage in every tree it runs in (or the --glsl tree), tree
// by tree in lecture order, so stages sharing a scene share a context. --set values go to the
// stages that declare them.
std::vector<RenderRequest> allRequests(const CheckArgs& a, const RenderRequest& base,
                                       std::vector<std::string>& notes) {
    std::vector<GlslTree> trees = {GlslTree::Core, GlslTree::Legacy};
    if (a.glslGiven) {
        trees = {base.tree};
    } else if (!base.overlay.empty()) {
        trees = {GlslTree::Core};
        notes.push_back(
            "--shaders without --glsl: checking the core tree (add --glsl legacy for "
            "a GLSL 1.20 overlay)");
    }
    for (const auto& [name, value] : base.sets) {
        bool any = false;
        for (const StageInfo& s : stageRegistry()) any = any || declares(s, name);
        if (!any)
            throw UsageError("--set " + name + "=" + value + ": no stage declares '" + name + "'");
    }
    bool sceneHasMirror = true;
    if (base.sceneGiven) sceneHasMirror = loadScene(base.scene).mirror.has_value();
    std::vector<RenderRequest> out;
    for (GlslTree tree : trees)
        for (const StageInfo& s : stageRegistry()) {
            if (s.legacyOnly && tree == GlslTree::Core) continue;
            RenderRequest r = base;
            r.stage = s.id;
            r.tree = tree;
            r.sets.clear();
            for (const auto& set : base.sets)
                if (declares(s, set.first)) r.sets.push_back(set);
            if (s.needsMirror && base.sceneGiven && !sceneHasMirror) {
                r.scene = "slides";
                r.sceneGiven = false;  // the stage's own scene
                std::string note = "stage " + s.id + ": --scene " + base.scene +
                                   " has no mirror, checked in its own scene";
                if (std::find(notes.begin(), notes.end(), note) == notes.end())
                    notes.push_back(note);
            }
            out.push_back(r);
        }
    return out;
}

nlohmann::json reportJson(const std::vector<CheckResult>& results, int exitCode, double seconds,
                          const std::string& backend, const std::string& machine) {
    int passed = 0, failed = 0, skipped = 0, errors = 0;
    nlohmann::json list = nlohmann::json::array();
    for (const auto& r : results) {
        list.push_back(checkJson(r));
        if (r.error)
            ++errors;
        else if (r.judgement.verdict == Verdict::Pass)
            ++passed;
        else if (r.judgement.verdict == Verdict::Fail)
            ++failed;
        else
            ++skipped;
    }
    return {{"tool", "shadowlab check"},
            {"report_version", 1},
            {"expectations", expectationsPath()},
            {"machine", {{"backend", backend}, {"renderer", machine}}},
            {"summary",
             {{"checked", results.size()},
              {"passed", passed},
              {"failed", failed},
              {"skipped", skipped},
              {"errors", errors},
              {"exit_code", exitCode},
              {"seconds", seconds}}},
            {"results", list}};
}

int runCheckCommand(const CheckArgs& a) {
    if (a.all == !a.stage.empty()) throw UsageError("check: give either --stage ID or --all");
    if (!a.diff.empty() && !a.diffDir.empty())
        throw UsageError(
            "--diff and --diff-dir: give one (--diff FILE.png for one stage, "
            "--diff-dir DIR for --all)");
    if (a.all && !a.diff.empty())
        throw UsageError("--diff: with --all use --diff-dir DIR (one image per stage and tree)");
    if (!a.report.empty()) checkOutputPath("--report", a.report);
    if (!a.diff.empty()) checkOutputPath("--diff", a.diff);
    CommonOptions common = a.common;
    common.stage = a.all ? "phong" : a.stage;
    RenderRequest base = toRequest(common);
    std::vector<std::string> notes;
    std::vector<RenderRequest> requests;
    if (a.all) {
        requests = allRequests(a, base, notes);
    } else {
        const StageInfo* info = findStage(base.stage);
        if (info && info->legacyOnly && !a.glslGiven) base.tree = GlslTree::Legacy;
        requests = {base};
    }
    for (const auto& r : requests) validateRequest(r);  // every bad value before any GL work
    expectations();                                     // and a broken data file too
    if (!a.diffDir.empty()) makeOutputDir(a.diffDir);
    for (const auto& n : notes) std::cerr << "shadowlab: note: " << n << "\n";

    auto start = std::chrono::steady_clock::now();
    Evaluator rig(toBackend(a.common.backend));
    std::vector<CheckResult> results;
    std::string machine, backend;
    std::cout << "check against " << expectationsPath() << ", " << base.width << "x" << base.height
              << (base.overlay.empty() ? "" : ", shaders " + printable(base.overlay)) << "\n"
              << "        " << checkTableHeader();
    // Every (stage, tree) with its lessons and views, planned before any GL work.
    const bool narrowed = !base.sets.empty() || base.sceneGiven;
    const bool customView = base.eye || base.at || base.light || base.fovy;
    std::vector<std::vector<CheckCase>> plan;
    std::size_t total = 0;
    for (const RenderRequest& r : requests) {
        plan.push_back(checkCases(r, narrowed, customView));
        total += plan.back().size();
    }
    for (const auto& cases : plan)
        for (const CheckCase& c : cases) validateRequest(c.request);
    auto diffPath = [&](const CheckCase& c) -> std::string {
        if (c.request.stage == "mirror") return a.diff;
        std::string slug = c.view;
        for (const auto& [name, value] : c.request.sets) slug += "-" + name + "=" + value;
        if (c.request.sceneGiven && c.request.scene != base.scene) slug += "-" + c.request.scene;
        for (char& ch : slug)
            if (ch == '/' || ch == ' ' || ch == '+') ch = '_';
        if (!a.diffDir.empty())
            return a.diffDir + "/" + c.request.stage + "-" + treeName(c.request.tree) + "-" + slug +
                   ".png";
        if (a.diff.empty() || (&c == &plan.front().front())) return a.diff;
        std::string stem = a.diff, ext;
        std::size_t dot = stem.rfind('.');
        if (dot != std::string::npos && dot > stem.rfind('/')) {
            ext = stem.substr(dot);
            stem.resize(dot);
        }
        return stem + "-" + slug + ext;
    };
    for (const auto& cases : plan)  // every diff image's path, before any GL work
        for (const CheckCase& c : cases) {
            std::string path = diffPath(c);
            if (!path.empty() && c.request.stage != "mirror")
                checkOutputPath(a.diffDir.empty() ? "--diff" : "--diff-dir", path);
        }
    std::size_t done = 0;
    for (const auto& cases : plan) {
        std::vector<CheckResult> stageResults =
            runCheckCases(rig, cases, diffPath, [&](const CheckResult& result) {
                char counter[32];
                std::snprintf(counter, sizeof counter, "[%3zu/%zu] ", ++done, total);
                std::cout << counter << checkTableLine(result) << std::flush;
                if (!result.note.empty()) std::cerr << "shadowlab: note: " << result.note << "\n";
            });
        for (auto& result : stageResults) {
            if (machine.empty()) {
                machine = result.machine;
                backend = result.backend;
            }
            results.push_back(std::move(result));
        }
    }
    int exitCode = kOk;
    for (const auto& r : results)
        if (r.error)
            exitCode = kBadInput;
        else if (r.judgement.verdict == Verdict::Fail && exitCode == kOk)
            exitCode = kCheckFailed;
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    nlohmann::json report = reportJson(results, exitCode, seconds, backend, machine);
    const auto& s = report["summary"];
    std::cout << "checked " << s["checked"] << ": " << s["passed"] << " passed, " << s["failed"]
              << " failed, " << s["skipped"] << " skipped, " << s["errors"] << " errors in "
              << std::fixed << std::setprecision(1) << seconds << std::defaultfloat << " s ("
              << machine << ")\n";
    for (const auto& r : results)
        if (!r.diffFile.empty() && !a.diff.empty())
            std::cout << "diff image: " << r.diffFile << "\n";
    if (!a.report.empty()) {
        std::string err = writeTextFile(
            a.report, report.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
        if (!err.empty()) throw UsageError("--report: " + err);
    }
    return exitCode;
}

}  // namespace

Command addCheckCommand(CLI::App& app) {
    auto args = std::make_shared<CheckArgs>();
    auto* cmd = app.add_subcommand(
        "check", "judge stages against the ray-traced reference and their expected lesson");
    addCommonOptions(cmd, args->common, false);
    cmd->add_option("--stage", args->stage, "the stage to check (see `shadowlab stages`)");
    cmd->add_flag("--all", args->all, "every stage in both shader trees");
    cmd->add_option("--report", args->report, "write a JSON report (fields: docs/check.md)");
    cmd->add_option("--diff", args->diff,
                    "diff image of one stage: red false shadow, blue false lit, grey agreement");
    cmd->add_option("--diff-dir", args->diffDir, "one diff image per stage and tree (with --all)");
    return {cmd, [args, cmd] {
                args->glslGiven = cmd->count("--glsl") > 0;
                return guarded([&] { return runCheckCommand(*args); });
            }};
}

}  // namespace sl
