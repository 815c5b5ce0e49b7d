#include "grade/stage_runs.h"

#include <iostream>
#include <memory>

#include "eval/evaluator.h"
#include "eval/job_errors.h"
#include "grade/bounds.h"
#include "grade/formats.h"
#include "io/data_paths.h"
#include "io/files.h"
#include "scene/scene_json.h"
#include "stages/registry.h"

namespace sl {

namespace {

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
    return {{"format", kWorkerRows.name},
            {"version", kWorkerRows.version},
            {"rows", list},
            {"backend", backend},
            {"machine", machine}};
}

std::vector<CheckCase> withoutSubmission(std::vector<CheckCase> cases) {
    for (CheckCase& c : cases) {
        c.request.overlay.clear();
        c.pictures = RowPictures::Difference;
    }
    return cases;
}

// Everything a job's cost depends on, as text: the calibration's key.
std::string jobKey(const std::vector<CheckCase>& cases) {
    nlohmann::json key = nlohmann::json::array();
    auto vec = [](const std::optional<glm::vec3>& v) {
        return v ? nlohmann::json{v->x, v->y, v->z} : nlohmann::json();
    };
    for (const CheckCase& c : cases) {
        const RenderRequest& r = c.request;
        key.push_back({r.stage, treeName(r.tree), effectiveScene(r), r.width, r.height, vec(r.eye),
                       vec(r.at), vec(r.light), r.fovy ? nlohmann::json(*r.fovy) : nullptr, r.sets,
                       r.displaceSeed ? nlohmann::json(*r.displaceSeed) : nullptr, c.view,
                       c.lesson});
    }
    return key.dump();
}

std::string firstLine(const std::string& text) {
    return text.substr(0, text.find('\n'));
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

// The one row of a job that gave no results.
CheckResult failedRow(const RenderRequest& r, Status status, const std::string& message,
                      double seconds) {
    CheckResult out = unrenderedResult(r);
    out.status = status;
    out.message = capped(message, kMaxRowMessage);
    out.seconds = seconds;
    return out;
}

// The rows of a job whose worker threw: the submission's ERROR, or the platform's (a GL failure
// is never the student's: NOT GRADED).
std::vector<CheckResult> errorRows(const RenderRequest& r, const WorkerOutcome& outcome) {
    CheckResult described = checkResultFor(r);
    std::string text = jobErrorText(described, outcome);
    std::cerr << "shadowlab: " << capped(printable(text), kMaxErrorText)
              << (text.back() == '\n' ? "" : "\n");
    if (outcome.errorKind == "runtime")
        return {failedRow(r, Status::NotGraded,
                          printableName(firstLine(text)) +
                              " (not the submission's: the rows are not graded; rerun)",
                          outcome.seconds)};
    return {failedRow(r, Status::Error, printableName(firstLine(text)), outcome.seconds)};
}

Status failureStatus(const WorkerOutcome& o) {
    return o.kind == WorkerOutcome::Kind::Timeout ? Status::Timeout : Status::Crash;
}

}  // namespace

std::optional<JobCost> Calibration::ours(const std::vector<CheckCase>& cases, std::string& why) {
    const std::string key = jobKey(cases);
    auto found = cache_.find(key);
    if (found == cache_.end()) {
        std::vector<CheckCase> shipped = withoutSubmission(cases);
        Measured m;
        const Limits limits = oursLimits(rule_);
        WorkerOutcome o;
        try {
            o = runBounded(
                limits,
                [&] {
                    Evaluator rig(backend_);
                    return checkStageJob(rig, shipped,
                                         [](const CheckCase&) { return std::string(); });
                },
                renderJobErrors());
        } catch (const std::exception& e) {  // the job threw: our data or the platform
            o.kind = WorkerOutcome::Kind::Error;
            o.errorWhat = e.what();
        }
        if (o.kind == WorkerOutcome::Kind::Ok)
            m.cost = JobCost{o.cpuSeconds, o.seconds, o.peakMb};
        else
            m.why = o.kind == WorkerOutcome::Kind::Error
                        ? "our shipped shaders failed: " + firstLine(o.errorWhat)
                        : workerFailureLine("our shipped shaders", o, limits);
        found = cache_.emplace(key, m).first;
    }
    why = found->second.why;
    return found->second.cost;
}

void checkInWorkers(const std::vector<std::vector<CheckCase>>& plan,
                    const std::function<std::string(const CheckCase&)>& diffPath,
                    Calibration& calibration,
                    const std::function<void(std::size_t, std::vector<CheckResult>)>& each) {
    if (plan.empty()) return;
    const BudgetRule& rule = calibration.rule();
    const Backend backend = calibration.backend();
    auto isOurs = [&](std::size_t k) { return plan[k].front().request.overlay.empty(); };
    bool allOurs = true;
    for (std::size_t k = 0; k < plan.size(); ++k) allOurs = allOurs && isOurs(k);
    const Limits first = allOurs ? oursLimits(rule) : provisionalLimits(rule);
    std::unique_ptr<Evaluator> rig;  // made in each worker, kept for its next stages
    auto job = [&](std::size_t k) {
        if (!rig) rig = std::make_unique<Evaluator>(backend);
        return checkStageJob(*rig, plan[k], diffPath);
    };
    // The rows of job k from how its worker ended under `limits`.
    std::function<std::vector<CheckResult>(std::size_t, const WorkerOutcome&, const Limits&, bool)>
        resolve = [&](std::size_t k, const WorkerOutcome& outcome, const Limits& limits,
                      bool retried) -> std::vector<CheckResult> {
        const RenderRequest& r = plan[k].front().request;
        if (outcome.kind == WorkerOutcome::Kind::Ok) return workerResults(outcome);
        if (outcome.kind == WorkerOutcome::Kind::Error) return errorRows(r, outcome);
        const std::string what = "stage " + r.stage + " (" + treeName(r.tree) + ")";
        const std::string line = workerFailureLine(what, outcome, limits);
        auto notGraded = [&](const std::string& why) {
            std::string text = line + "; " + why +
                               ": a platform problem, not the submission's: these rows are not "
                               "graded (rerun, on a less loaded machine or with more memory)";
            std::cerr << "shadowlab: " << text << "\n";
            return std::vector<CheckResult>{failedRow(r, Status::NotGraded, text, outcome.seconds)};
        };
        if (isOurs(k)) return notGraded("these are our shipped shaders");
        if (std::string machine = machineEvidence(outcome, limits); !machine.empty()) {
            std::string text = what + ": its worker was " + machine +
                               ": a platform problem, not the submission's: these rows are not "
                               "graded (rerun)";
            std::cerr << "shadowlab: " << text << "\n";
            return {failedRow(r, Status::NotGraded, text, outcome.seconds)};
        }
        std::string why;
        std::optional<JobCost> ours = calibration.ours(plan[k], why);
        if (!ours) return notGraded(why);
        const Limits budget = submissionLimits(rule, *ours);
        const bool raised =
            outcome.kind == WorkerOutcome::Kind::Timeout
                ? budget.cpuSeconds > limits.cpuSeconds || budget.wallSeconds > limits.wallSeconds
                : budget.memoryMb > limits.memoryMb;
        if (!retried && stoppedAtFloor(rule, outcome) && raised) {
            WorkerOutcome again;
            runBoundedSeries(
                budget, 1, [&](std::size_t) { return job(k); }, renderJobErrors(),
                [&](std::size_t, const WorkerOutcome& o) { again = o; });
            rig.reset();
            return resolve(k, again, budget, true);
        }
        std::string text = line;
        if (outcome.kind == WorkerOutcome::Kind::Timeout && !outcome.overWallClock)
            text += " [budget: " + budgetExplained(rule, *ours, true) + "]";
        else if (outcome.kind == WorkerOutcome::Kind::Crash && outcome.outOfMemory)
            text += " [budget: " + budgetExplained(rule, *ours, false) + "]";
        else  // a crash or a stall of its own: what it had used, the evidence it was its work
            text += " [used: " + usageText(outcome, limits) + "]";
        std::cerr << "shadowlab: " << text << "\n";
        return {failedRow(r, failureStatus(outcome), text, outcome.seconds)};
    };
    runBoundedSeries(first, plan.size(), job, renderJobErrors(),
                     [&](std::size_t k, const WorkerOutcome& outcome) {
                         each(k, resolve(k, outcome, first, false));
                     });
}

std::vector<CheckResult> workerResults(const WorkerOutcome& outcome) {
    std::vector<CheckResult> results;
    requireFormat(outcome.value, kWorkerRows, "format", "version", "a worker's rows");
    for (const auto& j : outcome.value.at("rows")) {
        results.push_back(checkResultFromJson(j));
        boundResult(results.back());  // the worker caps its rows; the parent never trusts it to
        results.back().backend = outcome.value.at("backend");
        results.back().machine = outcome.value.at("machine");
    }
    return results;
}

}  // namespace sl
