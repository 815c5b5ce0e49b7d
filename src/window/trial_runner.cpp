#include "window/trial_runner.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

#include "eval/job_errors.h"
#include "gl/debug.h"
#include "sandbox/worker.h"
#include "stages/request.h"

namespace sl {

namespace {

// The worker keeps to one core (llvmpipe's rasteriser threads; a user's LP_NUM_THREADS stays):
// the window's own frames keep the others, and a shader's CPU time counts the same either way.
void becomeABackgroundWorker() {
    ::setenv("LP_NUM_THREADS", "1", 0);
}

// Draws one job in the worker's own headless context (one per tree, made by the first job
// that needs it). Quiet: the window prints its own notes when it builds the programs it
// adopts, and the verdict comes back through the worker's pipe.
nlohmann::json drawOnThisThread(Backend backend, const TrialJob& job) {
    static std::map<GlslTree, std::unique_ptr<HeadlessContext>> contexts;  // in the worker only
    static bool quiet = false;
    if (!quiet) {
        int null = ::open("/dev/null", O_WRONLY);
        if (null >= 0) ::dup2(null, 1), ::dup2(null, 2), ::close(null);
        becomeABackgroundWorker();
        quiet = true;
    }
    auto& context = contexts[job.tree];
    if (!context) {
        context = createHeadlessContext(backend, job.tree, job.width, job.height);
        installGlDebugOutput(true);
    }
    RenderRequest r;
    r.stage = job.stage;
    r.tree = job.tree;
    r.overlay = job.overlay;
    r.scene = job.scene;
    r.sceneGiven = true;
    r.width = job.width;
    r.height = job.height;
    r.sets = job.sets;
    auto renderer = makeRenderer(r);
    // At the window's size (a loop's cost grows with the pixels), every view: each may have
    // its own program.
    for (ViewMode v : renderer->stage().views) {
        renderer->view = v;
        renderer->render(context->framebuffer(), job.width, job.height);
    }
    glFinish();
    return {{"stage", job.stage}};
}

// The worker is forked from the window, whose thread has the window's GLX context current in
// libglvnd's dispatch: on that thread EGL refuses to make its own context current
// (EGL_BAD_ACCESS, seen where there is no OSMesa and EGL is the headless path). A thread of the
// worker's own starts with no context current; every trial draw runs there, one after another.
class WorkerGlThread {
  public:
    WorkerGlThread() : thread_([this] { loop(); }) { thread_.detach(); }
    void run(const std::function<void()>& task) {
        std::unique_lock<std::mutex> lock(mutex_);
        task_ = task;
        done_ = false;
        wake_.notify_all();
        wake_.wait(lock, [&] { return done_; });
    }

  private:
    void loop() {
        for (;;) {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [&] { return bool(task_); });
            std::function<void()> task = std::move(task_);
            task_ = nullptr;
            lock.unlock();
            task();
            lock.lock();
            done_ = true;
            wake_.notify_all();
        }
    }
    std::mutex mutex_;
    std::condition_variable wake_;
    std::function<void()> task_;
    bool done_ = false;
    std::thread thread_;
};

nlohmann::json drawInWorker(Backend backend, const TrialJob& job) {
    static WorkerGlThread gl;  // made in the worker, on its first job
    nlohmann::json result;
    std::exception_ptr failure;
    gl.run([&] {
        try {
            result = drawOnThisThread(backend, job);
        } catch (...) {
            failure = std::current_exception();
        }
    });
    if (failure) std::rethrow_exception(failure);
    return result;
}

std::string setsText(const Sets& sets) {
    std::string text;
    for (const auto& [name, value] : sets)
        text += (text.empty() ? "" : ", ") + name + " = " + value;
    return text;
}

std::string seconds(double s) {
    char t[32];
    std::snprintf(t, sizeof t, "%.3g s", s);
    return t;
}

// Signals nobody in this window sends: the worker was ended from outside (the system's
// out-of-memory killer, a user), which says nothing about the shader.
bool killedFromOutside(const WorkerOutcome& o) {
    return o.kind == WorkerOutcome::Kind::Crash && !o.outOfMemory &&
           (o.signal == SIGKILL || o.signal == SIGTERM || o.signal == SIGINT ||
            o.signal == SIGHUP || o.signal == SIGQUIT);
}

}  // namespace

std::string secondsText(double s) {
    return seconds(s);
}

std::string TrialJob::describe() const {
    std::string text = "stage " + stage + " (" + treeName(tree);
    if (!sets.empty()) text += ", " + setsText(sets);
    return text + ")";
}

Limits windowLimits(const BudgetRule& rule, const std::optional<JobCost>& ours) {
    Limits l;
    if (rule.cpuSeconds)
        l.cpuSeconds = *rule.cpuSeconds;
    else
        l.cpuSeconds = std::max(kWindowCpuFloorSeconds, ours ? kCpuFactor * ours->cpuSeconds : 0);
    l.wallSeconds =
        l.cpuSeconds > 0 ? std::max(kWindowWallFloorSeconds, kWallFactor * l.cpuSeconds) : 0;
    l.memoryMb = rule.memoryMb ? *rule.memoryMb : rule.memoryCeilingMb;
    return l;
}

// A job's worker, watched without blocking. Destroying it kills and reaps the worker, which
// waits for the process to go: an abandoned one is destroyed on a thread of its own.
// `hold`: a job past its CPU time is stopped, not killed, so that it can go on (see poll).
struct TrialRunner::Series {
    Series(const Limits& limits, Backend backend, const TrialJob& job, bool hold = false)
        : background(
              limits, 1, [backend, job](std::size_t) { return drawInWorker(backend, job); },
              renderJobErrors(), hold) {}
    BackgroundSeries background;
};

TrialRunner::TrialRunner(const BudgetRule& rule, Backend backend)
    : rule_(rule), backend_(backend) {}

TrialRunner::~TrialRunner() = default;  // a running worker is killed and reaped

void TrialRunner::abandon() {
    letGo(series_);
    letGo(heldStudent_);
    phase_ = Phase::Idle;
}

void TrialRunner::letGo(std::unique_ptr<Series>& series) {
    if (series) std::thread([s = std::move(series)]() mutable { s.reset(); }).detach();
}

void TrialRunner::run(const TrialJob& job, const Limits& limits, Phase phase, bool hold) {
    abandon();
    limits_ = limits;
    phase_ = phase;
    series_ = std::make_unique<Series>(limits, backend_, job, hold);
}

std::string TrialRunner::cacheKey(const TrialJob& job) const {
    return std::string(treeName(job.tree)) + "/" + job.stage + "/" + job.scene + "/" +
           setsText(job.sets) + "/" + std::to_string(job.width) + "x" + std::to_string(job.height);
}

void TrialRunner::start(const TrialJob& job) {
    job_ = job;
    auto known = ours_.find(cacheKey(job));
    std::optional<JobCost> ours;
    if (known != ours_.end()) ours = known->second;
    // Stopped at the floor while ours are measured, a student's job goes on from there if its
    // budget grows (it was run again from the start: 2 s of CPU and a fresh worker more).
    const bool hold = !job.overlay.empty() && !rule_.cpuSeconds && known == ours_.end();
    run(job, windowLimits(rule_, ours), Phase::Student, hold);
}

bool TrialRunner::poll(TrialVerdict& verdict) {
    if (!series_) return false;
    bool over = false;
    try {
        over = series_->background.poll();
    } catch (const std::exception& e) {  // fork or pipe refused: the machine, not the shader
        abandon();
        verdict = {TrialVerdict::Kind::Lost, "the trial worker could not start (" +
                                                 std::string(e.what()) +
                                                 "): nothing was tried; r tries again"};
        return true;
    }
    if (!over) return false;
    const WorkerOutcome o = series_->background.outcomes().front();
    const Phase phase = phase_;
    const Limits limits = limits_;
    std::unique_ptr<Series> held;  // the student's job, stopped at its floor: kept for now
    if (series_->background.held()) held = std::move(series_);
    series_.reset();  // the worker has sent its line or ended: reaped at once
    phase_ = Phase::Idle;
    const std::string key = cacheKey(job_);
    const std::string what = job_.describe() + " in the trial worker";
    verdict = TrialVerdict{};
    verdict.budgetSeconds = limits.cpuSeconds;
    verdict.cpuSeconds = o.cpuSeconds;
    auto ours = ours_.find(key);
    if (ours != ours_.end() && ours->second) verdict.oursSeconds = ours->second->cpuSeconds;

    if (phase == Phase::Ours) {  // our shipped shaders drew the same job: the measure
        verdict = waiting_;
        if (o.kind == WorkerOutcome::Kind::Ok) {
            ours_[key] = JobCost{o.cpuSeconds, o.seconds, o.peakMb};
            verdict.oursSeconds = o.cpuSeconds;
        } else {
            ours_[key] = std::nullopt;
            letGo(heldStudent_);
            const std::string why = o.kind == WorkerOutcome::Kind::Error
                                        ? o.errorWhat
                                        : workerFailureLine("our shipped shaders", o, limits);
            verdict.kind = TrialVerdict::Kind::Lost;
            verdict.what = what +
                           ": our shipped shaders could not draw the same frame here either (" +
                           why + "): a platform problem, not the shader's; nothing was adopted";
            return true;
        }
        if (studentOutcome_.kind == WorkerOutcome::Kind::Error) {  // ours drew: the error is its
            letGo(heldStudent_);
            verdict.kind = TrialVerdict::Kind::Refused;
            verdict.what = studentOutcome_.errorWhat;
            return true;
        }
        const Limits budget = windowLimits(rule_, ours_[key]);
        if (budget.cpuSeconds > studentLimits_.cpuSeconds) {  // the floor was less: go on
            if (heldStudent_) {                               // from where it stopped
                series_ = std::move(heldStudent_);
                series_->background.resume(budget);
                limits_ = budget;
                phase_ = Phase::StudentAgain;
            } else {
                run(job_, budget, Phase::StudentAgain);
            }
            return false;
        }
        letGo(heldStudent_);
        verdict.kind = TrialVerdict::Kind::Refused;
        verdict.what = failureLine(what, studentOutcome_, studentLimits_);
        return true;
    }

    if (o.kind == WorkerOutcome::Kind::Ok) return true;  // drew
    if (o.kind == WorkerOutcome::Kind::Timeout && o.overWallClock &&
        o.cpuSeconds < 0.5 * limits.cpuSeconds) {  // the backstop, far from the budget
        char line[160];
        std::snprintf(line, sizeof line, "the worker had %.2g s of CPU time in %.3g s",
                      o.cpuSeconds, o.seconds);
        verdict.kind = TrialVerdict::Kind::Lost;
        verdict.what = what + ": " + line +
                       " (the machine is too busy to try it, or the worker waits on nothing), so "
                       "nothing is known of the shader; nothing was adopted; r tries again";
        return true;
    }
    if (killedFromOutside(o)) {
        verdict.kind = TrialVerdict::Kind::Lost;
        verdict.what = what + ": the worker was lost (" + o.detail() +
                       " from outside this window: the system's out-of-memory killer, or a "
                       "user), so nothing is known of the shader; nothing was adopted; r tries "
                       "again";
        return true;
    }
    const bool shaderError = o.kind == WorkerOutcome::Kind::Error && o.errorKind == "shader";
    const bool measurable = !job_.overlay.empty() && phase == Phase::Student;
    const bool platformMaybe = o.kind == WorkerOutcome::Kind::Error && !shaderError;
    const bool atFloor = o.kind == WorkerOutcome::Kind::Timeout && stoppedAtFloor(rule_, o);
    if (measurable && (platformMaybe || atFloor) && ours == ours_.end()) {
        // How long do ours take for the same frame (or do they fail the same way)?
        waiting_ = verdict;
        studentOutcome_ = o;
        studentLimits_ = limits;
        TrialJob shipped = job_;
        shipped.overlay.clear();
        Limits oursLimit = windowLimits(rule_, std::nullopt);
        oursLimit.cpuSeconds = kCpuFloorSeconds;  // ours past grading's floor: the platform
        oursLimit.wallSeconds = kWallFloorSeconds;
        limits_ = oursLimit;
        phase_ = Phase::Ours;
        heldStudent_ = std::move(held);
        series_ = std::make_unique<Series>(oursLimit, backend_, shipped);
        return false;
    }
    letGo(held);  // not measured now: the job is over
    if (platformMaybe && ours != ours_.end() && !ours->second) {
        verdict.kind = TrialVerdict::Kind::Lost;
        verdict.what = what + ": " + o.errorWhat +
                       " (our shipped shaders fail here too: a platform problem; nothing was "
                       "adopted)";
        return true;
    }
    verdict.kind = TrialVerdict::Kind::Refused;
    verdict.what =
        o.kind == WorkerOutcome::Kind::Error ? o.errorWhat : failureLine(what, o, limits);
    return true;
}

std::string TrialRunner::failureLine(const std::string& what, const WorkerOutcome& o,
                                     const Limits& limits) const {
    if (o.kind != WorkerOutcome::Kind::Timeout || o.overWallClock)
        return workerFailureLine(what, o, limits);
    std::string how;
    auto ours = ours_.find(cacheKey(job_));
    if (rule_.cpuSeconds)
        how = "fixed by --time-limit";
    else if (ours != ours_.end() && ours->second)
        how = std::to_string(int(kCpuFactor)) + " x our shaders' " +
              seconds(ours->second->cpuSeconds) + " for the same frame, at least " +
              seconds(kWindowCpuFloorSeconds) + "; --time-limit fixes it";
    else
        how = "the window's floor; --time-limit fixes it";
    return what + ": no result within its time limit of " + seconds(limits.cpuSeconds) +
           " of CPU time (" + how + ")";
}

}  // namespace sl
