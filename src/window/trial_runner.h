// The window's watchdog worker. A shader that loops makes the draw call spin inside the driver,
// one that crashes the compiler kills the process: neither may reach the window's own context.
// So a changed stage is first drawn by a bounded worker (a child process, sandbox/worker.h), at
// the window's size, every view and the HUD, and the window adopts its new programs only when
// they drew there. The budget follows grading's rule (sandbox/budget.h): CPU time, never a fixed
// wall clock, k x what our shipped shaders take for the same job (measured here, in the same
// worker, once per stage, tree, scene, settings and size, and remembered), with a floor that
// suits one interactive frame.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lecture/lessons.h"  // Sets
#include "platform/headless.h"
#include "sandbox/budget.h"
#include "sandbox/worker.h"

namespace sl {

// The window's floor: two seconds of CPU, against grading's 30 s: one interactive frame. Our
// shipped shaders draw a stage's trial (a fresh context, its programs compiled, every view at
// 1920x1080) in 0.09-0.44 s of CPU on llvmpipe (docs/window.md, measured), so a copy of
// ours or an ordinary student's shader never waits for a calibration, and a loop is refused
// after 2 s of CPU, or after 8 x ours where our shaders take more than 0.25 s for that frame.
constexpr double kWindowCpuFloorSeconds = 2;
// The wall-clock backstop of a trial worker that waits on nothing: 10 x its CPU budget, at
// least this (a worker at a tenth of a loaded core still finishes what its budget allows; one
// stopped there with less than half its budget used is the machine's, not the shader's).
constexpr double kWindowWallFloorSeconds = 60;

// One stage drawn in the worker: the programs of `tree` with `overlay` over ours, in `scene`,
// with `sets` (its parameters off their defaults), at width x height.
struct TrialJob {
    GlslTree tree = GlslTree::Core;
    std::string overlay;
    std::string stage, scene;
    Sets sets;
    int width = 640, height = 480;
    std::string describe() const;  // "stage margin (core, margin-kind = slope)"
};

// How a trial ended. Lost: the worker went away without a verdict on the shader (killed from
// outside, a fork that failed, our own shaders unable to finish): nothing is adopted or refused.
struct TrialVerdict {
    enum class Kind { Drew, Refused, Lost };
    Kind kind = Kind::Drew;
    std::string what;          // Refused, Lost: one line or a driver log
    double cpuSeconds = 0;     // what the student's job used (its last run)
    double budgetSeconds = 0;  // the CPU budget it ran under (0: none)
    double oursSeconds = -1;   // our shaders' cost for the same job, when measured
};

// The window's limits for a job: the rule's fixed values, else max(kCpuFactor x ours, floor)
// CPU seconds (the floor alone before ours are known) and the box's worker memory.
Limits windowLimits(const BudgetRule& rule, const std::optional<JobCost>& ours);

// Runs one job at a time in a bounded worker; never blocks the window.
class TrialRunner {
  public:
    TrialRunner(const BudgetRule& rule, Backend backend);
    ~TrialRunner();
    // Starts `job` (a running one is abandoned: its worker is killed off the window's thread).
    void start(const TrialJob& job);
    void abandon();
    bool running() const { return phase_ != Phase::Idle; }
    const TrialJob& job() const { return job_; }
    // Never waits. True once the job is over: `verdict` then says how.
    bool poll(TrialVerdict& verdict);
    // The CPU budget the running job has now (seconds; 0: none).
    double budgetSeconds() const { return limits_.cpuSeconds; }
    const BudgetRule& rule() const { return rule_; }
    // Jobs of our shipped shaders measured so far (what the budgets came from).
    std::size_t oursMeasured() const { return ours_.size(); }

  private:
    enum class Phase { Idle, Student, Ours, StudentAgain };
    struct Series;
    void run(const TrialJob& job, const Limits& limits, Phase phase, bool hold = false);
    static void letGo(std::unique_ptr<Series>& series);  // killed and reaped off this thread
    std::string cacheKey(const TrialJob& job) const;
    std::string failureLine(const std::string& what, const WorkerOutcome& o,
                            const Limits& limits) const;

    BudgetRule rule_;
    Backend backend_;
    TrialJob job_;
    Phase phase_ = Phase::Idle;
    Limits limits_;
    std::unique_ptr<Series> series_;
    std::unique_ptr<Series> heldStudent_;  // stopped at its floor while ours are measured
    std::map<std::string, std::optional<JobCost>> ours_;  // by cacheKey; none: ours failed
    // While ours are measured: what the student's job got, and under which limits.
    TrialVerdict waiting_;
    WorkerOutcome studentOutcome_;
    Limits studentLimits_;
};

// Seconds as the trials' messages write them ("3.4 s").
std::string secondsText(double seconds);

}  // namespace sl
