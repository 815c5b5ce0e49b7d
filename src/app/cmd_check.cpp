// `shadowlab check (--stage ID | --all)`: renders stages headless, measures them against the
// ray-traced reference and judges each against its expectation (src/stages/expectations.json).
// The stages are evaluated in bounded workers (src/app/worker.h), each stage and tree under its
// own time limit, so a shader that hangs the compiler or crashes the driver costs that stage
// (TIMEOUT, CRASH) and the report is still written. One line per stage as it finishes, an
// optional report (ours, or Gradescope's results.json), JUnit XML and diff images; exit 0 when
// every stage shows its lesson, 1 when one does not, 2 on bad input (a student shader that does
// not build, times out or crashes included), 3 on a GL failure.
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <set>

#include "app/commands.h"
#include "bench/bench_output.h"
#include "course/assignment_check.h"
#include "grade/bounds.h"
#include "grade/check_formats.h"
#include "grade/check_run.h"
#include "grade/intake.h"
#include "grade/worker.h"
#include "io/files.h"
#include "io/json_fields.h"
#include "scene/scene_json.h"
#include "stages/stage.h"

namespace sl {

namespace {

struct CheckArgs {
    CommonOptions common;
    Limits limits;
    std::string stage, report, diff, diffDir, junit, format = "json", assignment;
    bool all = false, glslGiven = false, shadersGiven = false;
    std::optional<std::uint64_t> seed;  // --seed: the displaced view's; else drawn at start
};

std::string canonicalOutput(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::path absolute = fs::absolute(path, ec);
    fs::path c = fs::weakly_canonical(absolute, ec);
    return (ec ? absolute.lexically_normal() : c).string();
}

// Output paths that would overwrite one another, or write into the student's folder (where a
// planted link could point anywhere, and a report would become part of the submission), are
// refused before any work: one line, exit 2.
void refuseOutputClashes(const CheckArgs& a, const std::string& overlay) {
    std::vector<std::pair<std::string, std::string>> outputs;  // option, path
    for (const auto& [option, path] : {std::pair<std::string, std::string>{"--report", a.report},
                                       {"--junit", a.junit},
                                       {"--diff", a.diff},
                                       {"--diff-dir", a.diffDir}})
        if (!path.empty()) outputs.emplace_back(option, path);
    for (std::size_t i = 0; i < outputs.size(); ++i)
        for (std::size_t j = i + 1; j < outputs.size(); ++j)
            if (canonicalOutput(outputs[i].second) == canonicalOutput(outputs[j].second))
                throw UsageError(outputs[i].first + " and " + outputs[j].first + ": both are '" +
                                 printableName(outputs[j].second) + "'; give each its own path");
    if (overlay.empty()) return;
    // As written and as resolved: a link the student planted in the folder resolves elsewhere
    // (another student's folder) and is refused for where it is written.
    auto lexical = [](const std::string& p) {
        std::error_code ec;
        return std::filesystem::absolute(p, ec).lexically_normal().string();
    };
    auto inside = [](const std::string& p, const std::string& root) {
        std::string r =
            root.size() > 1 && root.back() == '/' ? root.substr(0, root.size() - 1) : root;
        return p == r || p.rfind(r + "/", 0) == 0;
    };
    for (const auto& [option, path] : outputs) {
        if (inside(canonicalOutput(path), canonicalOutput(overlay)) ||
            inside(lexical(path), lexical(overlay)))
            throw UsageError(option + " '" + printableName(path) +
                             "' lies inside the submission folder '" + printableName(overlay) +
                             "'; write outputs outside it");
    }
}

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
    int passed = 0, failed = 0, skipped = 0, errors = 0, missing = 0;
    nlohmann::json list = nlohmann::json::array();
    for (const auto& r : results) {
        list.push_back(checkJson(r));
        if (r.missing)
            ++missing;
        else if (r.error)
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
              {"missing", missing},
              {"exit_code", exitCode},
              {"seconds", seconds}}},
            {"results", list}};
}

// The camera, light and scene name a stage would have been rendered with, for a stage whose
// worker returned nothing. The scene is read again only when it is a regular file: a FIFO or a
// device is the scene loader's to refuse, never the parent's to block on.
void describeUnrendered(const RenderRequest& r, CheckResult& out) {
    out.scene = effectiveScene(r);
    std::string path = out.scene;
    if (path.find('/') == std::string::npos && path.find(".json") == std::string::npos)
        path = dataDir() + "/scenes/" + path + ".json";
    struct stat st;
    if (::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode)) {
        try {
            Scene scene = loadScene(out.scene);
            out.scene = scene.name;
            out.camera = scene.camera;
            out.light = scene.light.position;
        } catch (const std::exception&) {  // the worker's error would have said why
        }
    }
    if (r.eye) out.camera.eye = *r.eye;
    if (r.at) out.camera.at = *r.at;
    if (r.fovy) out.camera.fovyDegrees = *r.fovy;
    if (r.light) out.light = *r.light;
}

// What a stage's job threw, as `render` would say it (a shader error may add the log's lines).
std::string jobErrorText(const CheckResult& r, const WorkerOutcome& outcome) {
    const std::string& kind = outcome.errorKind;
    if (kind == "shader") return "shader error: " + outcome.errorWhat;
    if (kind == "scene") return "scene error: " + outcome.errorWhat;
    std::string stage = "stage " + r.stage + " (" + r.tree + "): ";
    if (kind == "runtime") return stage + "GL or platform failure: " + outcome.errorWhat;
    return stage + outcome.errorWhat;
}

std::string firstLine(const std::string& text) {
    return text.substr(0, text.find('\n'));
}

// The result of a stage whose worker ran out of time or died: TIMEOUT or CRASH, an error of the
// submission (exit 2), with the one line that names the stage and the limit. A stage whose job
// threw is ERROR with what it threw: the other stages are still graded, the report written.
// A row for a stage that was not rendered: its settings, scene and expectation, nothing measured.
CheckResult unrenderedResult(const RenderRequest& r) {
    CheckResult out = checkResultFor(r);
    if (const StageInfo* info = findStage(r.stage)) out.parameters = ParamSet(info->params);
    for (const auto& [name, value] : r.sets) out.parameters.set(name, value);
    describeUnrendered(r, out);
    out.expectation =
        findExpectation(expectations(), out.stage, out.scene, out.tree, out.parameters);
    return out;
}

// The row of a stage none of whose own files came from the submission: MISSING, with the files
// it expected. `expected` empty: a stage with no shaders (fixed function), not to be handed in.
CheckResult missingResult(const RenderRequest& r, const std::vector<std::string>& expected,
                          const std::string& folder) {
    CheckResult out = unrenderedResult(r);
    if (expected.empty()) {
        out.judgement = {Verdict::Skip, "stage " + r.stage +
                                            " has no shaders to hand in (fixed function): "
                                            "not graded with --shaders"};
        return out;
    }
    out.missing = true;
    out.judgement = {Verdict::Fail,
                     capped("no file of stage " + r.stage + " came from " + printableName(folder) +
                                ": expected one or more of " + commaList(expected),
                            kMaxRowMessage)};
    return out;
}

CheckResult unjudgedResult(const RenderRequest& r, const WorkerOutcome& outcome,
                           const Limits& limits) {
    CheckResult out = unrenderedResult(r);
    out.error = true;
    out.errorVerdict = outcome.kind == WorkerOutcome::Kind::Timeout ? "TIMEOUT"
                       : outcome.kind == WorkerOutcome::Kind::Error ? "ERROR"
                                                                    : "CRASH";
    out.judgement = {Verdict::Fail,
                     capped(outcome.kind == WorkerOutcome::Kind::Error
                                ? printableName(firstLine(jobErrorText(out, outcome)))
                                : workerFailureLine("stage " + out.stage + " (" + out.tree + ")",
                                                    outcome, limits),
                            kMaxRowMessage)};
    out.seconds = outcome.seconds;
    return out;
}

// The job of one stage in one tree, run inside a worker: every lesson and view of it (its
// cases), their results as JSON.
nlohmann::json checkStageJob(Evaluator& rig, const std::vector<CheckCase>& cases,
                             const std::function<std::string(const CheckCase&)>& diffPath) {
    nlohmann::json list = nlohmann::json::array();
    std::string backend, machine;
    for (const CheckResult& r : runCheckCases(rig, cases, diffPath, [](const CheckResult&) {})) {
        list.push_back(checkJson(r));
        backend = r.backend;
        machine = r.machine;
    }
    return {{"results", list}, {"backend", backend}, {"machine", machine}};
}

// Whether the cases of a stage that ran out of time or memory fail the same way with our
// shipped shaders alone (then it is the platform's or the scene's problem, exit 3, not the
// submission's): "" when ours pass the limits, else one line naming the scene and its size. A
// check without a submission is ours already: no second run.
std::string shippedShadersFailToo(std::vector<CheckCase> cases, Backend backend,
                                  const Limits& limits) {
    WorkerOutcome ours;
    if (!cases.front().request.overlay.empty()) {
        for (CheckCase& c : cases) c.request.overlay.clear();
        ours = runBounded(limits, [&] {
            Evaluator rig(backend);
            return checkStageJob(rig, cases, [](const CheckCase&) { return std::string(); });
        });
        if (ours.kind == WorkerOutcome::Kind::Ok || ours.kind == WorkerOutcome::Kind::Error)
            return "";
    }
    CheckResult described = checkResultFor(cases.front().request);
    describeUnrendered(cases.front().request, described);
    std::string size;
    try {
        size = " (" +
               std::to_string(loadScene(effectiveScene(cases.front().request)).objects.size()) +
               " objects)";
    } catch (const std::exception&) {
    }
    return "our shipped shaders fail the same way under these limits: a platform or scene "
           "problem (scene " +
           printableName(described.scene) + size +
           "), not the submission's; raise --time-limit or --memory-limit, or use a smaller scene";
}

}  // namespace

// Every stage and tree of `requests` evaluated in bounded workers: one worker goes through them
// in order, reusing its contexts from one stage to the next (as one process did before), each
// stage under its own time limit. A stage whose worker runs out of time or dies is one TIMEOUT
// or CRASH result, and a fresh worker goes on with the next stage. The job's exceptions are
// thrown again here. `each(k, results)` gets each stage's results as they come.
void checkInWorkers(const std::vector<std::vector<CheckCase>>& plan,
                    const std::function<std::string(const CheckCase&)>& diffPath, Backend backend,
                    const Limits& limits, bool& platformFailure,
                    const std::function<void(std::size_t, std::vector<CheckResult>)>& each) {
    std::unique_ptr<Evaluator> rig;  // made in each worker, kept for its next stages
    auto job = [&](std::size_t k) {
        if (!rig) rig = std::make_unique<Evaluator>(backend);
        return checkStageJob(*rig, plan[k], diffPath);
    };
    runBoundedSeries(limits, plan.size(), job, [&](std::size_t k, const WorkerOutcome& outcome) {
        std::vector<CheckResult> results;
        if (outcome.kind != WorkerOutcome::Kind::Ok) {
            results.push_back(unjudgedResult(plan[k].front().request, outcome, limits));
            // Not the submission's fault (ours or the machine's): exit 3 once the report is out.
            if (outcome.kind == WorkerOutcome::Kind::Error && outcome.errorKind == "runtime")
                platformFailure = true;
            if (outcome.kind == WorkerOutcome::Kind::Timeout ||
                outcome.kind == WorkerOutcome::Kind::Crash) {
                std::string why = shippedShadersFailToo(plan[k], backend, limits);
                if (!why.empty()) {
                    platformFailure = true;
                    results.back().judgement.message += "; " + why;
                }
            }
            std::string text =
                outcome.kind == WorkerOutcome::Kind::Error
                    ? capped(printable(jobErrorText(results.back(), outcome)), kMaxErrorText)
                    : results.back().judgement.message;
            std::cerr << "shadowlab: " << text << (text.back() == '\n' ? "" : "\n");
        } else {
            for (const auto& j : outcome.value.at("results")) {
                results.push_back(checkResultFromJson(j));
                results.back().backend = outcome.value.at("backend");
                results.back().machine = outcome.value.at("machine");
            }
        }
        each(k, std::move(results));
    });
}

namespace {

// `--assignment`: the submission graded by the assignment's stages, points and visibility.
int runAssignment(const CheckArgs& a) {
    if (a.all || !a.stage.empty())
        throw UsageError(
            "--assignment: the assignment names the stages; leave out --stage and --all");
    AssignmentCheckArgs args{a.assignment, a.common.shaders, a.report, a.format,
                             a.junit,      a.diffDir,        {}};
    args.settings.backend = toBackend(a.common.backend);
    args.settings.limits = a.limits;
    args.settings.pictures = !a.diffDir.empty();
    args.settings.seed = a.seed ? *a.seed : drawSeed();
    return runAssignmentCheck(args);
}

int runCheckCommand(const CheckArgs& a) {
    if (!a.assignment.empty()) return runAssignment(a);
    if (a.all == !a.stage.empty()) throw UsageError("check: give either --stage ID or --all");
    if (!a.diff.empty() && !a.diffDir.empty())
        throw UsageError(
            "--diff and --diff-dir: give one (--diff FILE.png for one stage, "
            "--diff-dir DIR for --all)");
    if (a.all && !a.diff.empty())
        throw UsageError("--diff: with --all use --diff-dir DIR (one image per stage and tree)");
    if (a.format != "json" && a.format != "gradescope")
        throw UsageError("--format: '" + a.format + "' is not one of json, gradescope");
    if (a.format != "json" && a.report.empty())
        throw UsageError("--format " + a.format + ": give --report FILE to write it to");
    if (a.shadersGiven && a.common.shaders.empty())
        throw UsageError("--shaders: empty; give the student's folder (its files replace ours)");
    refuseOutputClashes(a, a.common.shaders);
    if (!a.report.empty()) checkOutputPath("--report", a.report);
    if (!a.diff.empty()) checkOutputPath("--diff", a.diff);
    if (!a.junit.empty()) checkOutputPath("--junit", a.junit);
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
    // The submission, resolved and copied before anything is compiled: what is graded is the
    // copy (src/grade/intake.h); a stage none of whose own files came from it is MISSING.
    std::unique_ptr<PrivateDir> snapshot;
    Submission submission;
    const ShippedTrees& shipped = shippedTrees();
    std::vector<RenderRequest> missingRequests;
    if (!base.overlay.empty()) {
        if (!a.all && expectedFiles(base.stage, shipped.of(base.tree)).empty())
            throw UsageError("--stage " + base.stage +
                             ": this stage has no shaders for --shaders to replace");
        std::vector<std::string> stages;
        for (const auto& r : requests) stages.push_back(r.stage);
        snapshot = std::make_unique<PrivateDir>("shadowlab-submission");
        try {
            submission = takeSubmission(base.overlay, snapshot->path(), shipped.both, stages);
        } catch (const IntakeError& e) {
            throw UsageError(e.what());
        }
        showFolderAs(snapshot->path(), submission.folder);
        for (const auto& n : submission.notes) notes.push_back(n);
        std::vector<RenderRequest> graded;
        for (RenderRequest r : requests) {
            r.overlay = snapshot->path();
            if (stageFiles(submission, r.stage, shipped.of(r.tree)).empty())
                missingRequests.push_back(r);
            else
                graded.push_back(r);
        }
        requests = graded;
    }
    if (!a.diffDir.empty()) makeOutputDir(a.diffDir);
    for (const auto& n : notes) std::cerr << "shadowlab: note: " << n << "\n";

    const std::uint64_t seed = a.seed ? *a.seed : drawSeed();
    auto start = std::chrono::steady_clock::now();
    const Backend backend = toBackend(a.common.backend);
    std::vector<CheckResult> results;
    std::string machine, backendName;
    std::cout << "check against " << expectationsPath() << ", " << base.width << "x" << base.height
              << (base.overlay.empty() ? "" : ", shaders " + printableName(base.overlay))
              << ", seed " << seed << " (--seed " << seed << " repeats the displaced views)\n"
              << "        " << checkTableHeader();
    // Every (stage, tree) with its lessons and views, planned before any GL work.
    const bool narrowed = !base.sets.empty() || base.sceneGiven;
    const bool customView = base.eye || base.at || base.light || base.fovy;
    std::vector<std::vector<CheckCase>> plan;
    std::size_t total = 0;
    for (const RenderRequest& r : requests) {
        plan.push_back(checkCases(r, narrowed, customView, seed));
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
        std::size_t dot = stem.rfind('.'), slash = stem.rfind('/');
        if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) {
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
    total += missingRequests.size();
    std::size_t done = 0;
    auto printRow = [&](const CheckResult& result) {
        char counter[32];
        std::snprintf(counter, sizeof counter, "[%3zu/%zu] ", ++done, total);
        std::cout << counter << checkTableLine(result) << std::flush;
    };
    for (const RenderRequest& r : missingRequests) {
        results.push_back(
            missingResult(r, expectedFiles(r.stage, shipped.of(r.tree)), submission.folder));
        results.back().overlay = base.overlay;
        printRow(results.back());
    }
    // Mesa's shader cache for this run's workers: private, gone with the run.
    PrivateDir shaderCache("shadowlab-shader-cache");
    useShaderCacheFolder(shaderCache.path());
    std::set<std::string> saidNotes;
    bool platformFailure = false;
    checkInWorkers(plan, diffPath, backend, a.limits, platformFailure,
                   [&](std::size_t, std::vector<CheckResult> stageResults) {
                       for (CheckResult& result : stageResults) {
                           if (machine.empty()) {
                               machine = result.machine;
                               backendName = result.backend;
                           }
                           boundResult(result);
                           if (!base.overlay.empty()) {
                               result.overlay = base.overlay;
                               // A row that built nothing (a compile error) still names the
                               // stage's files the student handed in.
                               if (result.studentFiles.empty())
                                   result.studentFiles = stageFiles(
                                       submission, result.stage,
                                       shipped.of(result.tree == "legacy" ? GlslTree::Legacy
                                                                          : GlslTree::Core));
                           }
                           printRow(result);
                           // A note (an unset uniform) holds for every row of the stage:
                           // said once.
                           if (!result.note.empty() && saidNotes.insert(result.note).second)
                               std::cerr << "shadowlab: note: " << result.note << "\n";
                           results.push_back(std::move(result));
                       }
                   });
    if (machine.empty()) machine = "unknown (no stage finished)";
    int exitCode = kOk;
    for (const auto& r : results)
        if (r.error || r.missing)  // a due stage MISSING is bad input (GUIDE section 3)
            exitCode = kBadInput;
        else if (r.judgement.verdict == Verdict::Fail && exitCode == kOk)
            exitCode = kCheckFailed;
    if (platformFailure) exitCode = kGlFailure;
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    nlohmann::json report = reportJson(results, exitCode, seconds, backendName, machine);
    report["seed"] = seed;
    const auto& s = report["summary"];
    std::cout << "checked " << s["checked"] << ": " << s["passed"] << " passed, " << s["failed"]
              << " failed, " << s["skipped"] << " skipped, " << s["errors"] << " errors, "
              << s["missing"] << " missing in " << std::fixed << std::setprecision(1) << seconds
              << std::defaultfloat << " s (" << machine << ")\n";
    for (const auto& r : results)
        if (!r.diffFile.empty() && !a.diff.empty())
            std::cout << "diff image: " << r.diffFile << "\n";
    for (const auto& r : results)
        if (r.missing)
            std::cerr << "shadowlab: stage " << r.stage << " (" << r.tree
                      << ") MISSING: " << r.judgement.message << "\n";
    if (!a.report.empty()) {
        nlohmann::json written =
            a.format == "gradescope" ? gradescopeJson(results, seconds) : report;
        std::string err = writeTextFile(
            a.report, written.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
        if (!err.empty()) throw UsageError("--report: " + err);
    }
    if (!a.junit.empty()) {
        std::string err = writeTextFile(a.junit, junitXml(results, seconds));
        if (!err.empty()) throw UsageError("--junit: " + err);
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
    cmd->add_option("--format", args->format,
                    "the --report's format: json (ours, default) or gradescope (results.json)");
    cmd->add_option("--junit", args->junit, "also write JUnit XML: one testcase per check");
    cmd->add_option("--seed", args->seed,
                    "the displaced views' seed (as the report's \"seed\"); default: drawn now");
    cmd->add_option("--assignment", args->assignment,
                    "grade --shaders DIR by an assignment file: its stages, points and visibility "
                    "(docs/assignment.md)");
    addLimitOptions(cmd, args->limits);
    return {cmd, [args, cmd] {
                args->glslGiven = cmd->count("--glsl") > 0;
                args->shadersGiven = cmd->count("--shaders") > 0;
                return guarded([&] { return runCheckCommand(*args); });
            }};
}

}  // namespace sl
