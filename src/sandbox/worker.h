// A job run in a child process under a CPU-time, resident-memory and wall-clock limit. Mesa
// compiles a shader without ever checking a clock, and a crash in the driver kills its process:
// so the GL work of an untrusted submission runs in a worker, and the parent (which never creates
// a GL context) watches it and always survives to write the report.
//
// The limits measure the work, not the machine: CPU time (all the worker's threads, llvmpipe's
// included) does not grow when other processes share the cores, and resident memory is what a
// container's cgroup charges (an address-space limit counts what llvmpipe's threads and a GPU
// driver merely reserve). The wall clock is only a backstop for a worker that waits on nothing
// (sandbox/budget.h sets it generously).
#pragma once

#include <chrono>
#include <exception>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace sl {

struct Limits {
    double cpuSeconds = 0;   // CPU time one job may use, all the worker's threads; 0 = none
    double wallSeconds = 0;  // wall clock of one job (a backstop); 0 = none
    long memoryMb = 0;       // resident memory of the worker while a job runs; 0 = none
};

// How a job's exception crosses from the worker to its parent, by kind and message, and back
// into an exception of its type, so the exit codes stay what they would be without the worker.
// The sandbox knows UsageError ("usage"), std::invalid_argument and any other std::exception
// ("runtime"); the floors above name their own types first (eval/job_errors.h: the renderer's
// "shader", "scene", "expectation").
struct JobErrorKinds {
    // The kind of the exception in `error` (rethrown inside), or "" when it is none of these.
    std::function<std::string(const std::exception_ptr& error)> kindOf;
    // Throws the exception of `kind` with `what`; returns when `kind` is none of these.
    std::function<void(const std::string& kind, const std::string& what)> raise;
};

// How a worker ended. Ok carries the job's value; Error an exception the job threw, by kind
// (JobErrorKinds) and message: rethrowJobError throws it again with its type; runBounded does.
struct WorkerOutcome {
    enum class Kind {
        Ok,
        Timeout,  // past the CPU-time limit or the wall-clock backstop (killed)
        Crash,    // killed by a signal, or past the memory limit (killed, or std::bad_alloc)
        Failed,   // exited without a result (exit code in `exitCode`)
        Error,    // the job threw: errorKind, errorWhat
    };
    Kind kind = Kind::Ok;
    nlohmann::json value;
    int signal = 0;    // Crash by a signal
    int exitCode = 0;  // Failed
    bool outOfMemory = false;
    bool overWallClock = false;        // Timeout by the wall-clock backstop, not CPU time
    bool tooLong = false;              // Failed: its reply passed the parent's bound
    std::string errorKind, errorWhat;  // Error
    double seconds = 0;                // wall clock of the job
    double cpuSeconds = 0;             // CPU time of the job, all the worker's threads
    long peakMb = 0;                   // the worker's peak resident memory during the job
    // "killed by SIGSEGV", "ran out of memory", "exited with code 1 without a result", ...
    std::string detail() const;
};

// Throws an Error outcome's exception again, with its type.
[[noreturn]] void rethrowJobError(const WorkerOutcome& outcome, const JobErrorKinds& kinds);

// Forks, and in the child applies the limits, runs `job`, sends its value back through a pipe
// and _exits; the parent waits up to the time limit, then kills the child's process group.
// Flushes stdout and stderr before forking (the child prints to the same ones).
WorkerOutcome runBounded(const Limits& limits, const std::function<nlohmann::json()>& job,
                         const JobErrorKinds& kinds);

// job(0) ... job(count - 1) in order, each under the limits of one job, in as few workers as
// may be: one worker runs them one after the other and sends each value back as it finishes,
// so what a job sets up in the worker (a GL context) serves the next, and the time limit starts
// again with each job. A job that runs out of time or ends its worker gets that outcome and a
// fresh worker goes on with the next; so does one that threw (Error). `done(k, outcome)` is
// called for each, in order.
using SeriesJob = std::function<nlohmann::json(std::size_t)>;
void runBoundedSeries(const Limits& limits, std::size_t count, const SeriesJob& job,
                      const JobErrorKinds& kinds,
                      const std::function<void(std::size_t, const WorkerOutcome&)>& done);

// Workers started after this keep Mesa's shader cache in `folder` (a private one the caller
// removes); "" (the default): no shader cache at all. Never the user's ~/.cache.
void useShaderCacheFolder(const std::string& folder);

// The same series watched without blocking: the window tries a student's changed shaders in
// it between frames, and must answer keys while a looping shader spins in the worker. Stops at
// the first job that fails (its outcome is the last). The destructor kills a running worker.
// `holdOverCpu`: a job past its CPU time is held (its worker stopped with SIGSTOP, not killed):
// poll() says so (true, held(), a Timeout outcome), and resume() lets it go on under larger
// limits from where it stood, so that a budget raised once its floor ran out costs no rerun.
class BackgroundSeries {
  public:
    BackgroundSeries(const Limits& limits, std::size_t count, SeriesJob job, JobErrorKinds kinds,
                     bool holdOverCpu = false);
    ~BackgroundSeries();
    BackgroundSeries(const BackgroundSeries&) = delete;
    BackgroundSeries& operator=(const BackgroundSeries&) = delete;
    // Reads what the worker has sent (never waits); true once every job has an outcome or one
    // failed. The first call starts the worker (fork: call it where no other thread is in GL).
    bool poll();
    const std::vector<WorkerOutcome>& outcomes() const { return outcomes_; }
    bool held() const { return held_; }
    // The held job goes on under `limits` (its wall clock resumes where it stopped).
    void resume(const Limits& limits);

  private:
    struct Running;
    Limits limits_;
    std::size_t count_;
    SeriesJob job_;
    JobErrorKinds kinds_;
    std::vector<WorkerOutcome> outcomes_;
    std::unique_ptr<Running> running_;
    bool failed_ = false;
    bool holdOverCpu_ = false, held_ = false;
    std::chrono::steady_clock::time_point heldSince_;
};

// "30 s of CPU time" or "no time limit"; "2048 MB" or "no memory limit".
std::string timeLimitText(const Limits& limits);
std::string memoryLimitText(const Limits& limits);

// Why a worker's end was the machine's and not its job's, or "" when the job's own work explains
// it: a signal the parent did not send (SIGKILL or SIGTERM from outside: an administrator, the
// kernel's OOM killer for memory others hold) while the job's CPU time and memory were far below
// their limits (under half), or the wall-clock backstop reached while it had used under half its
// CPU time (a stopped or starved worker: SIGSTOP). The text names the evidence that decided
// (the signal, CPU seconds, memory). What the job did (its CPU time or memory used up, a crash
// by SIGSEGV or SIGABRT in the driver) stays the job's.
std::string machineEvidence(const WorkerOutcome& outcome, const Limits& limits);
// What the job had used when it ended: "0.41 s of CPU time (budget: 30 s of CPU time) at a peak
// of 96 MB (512 MB)".
std::string usageText(const WorkerOutcome& outcome, const Limits& limits);

// The one line for a worker that did not return, naming `what` ("stage margin (core)") and the
// limit concerned: "stage margin (core): used up its time budget of 20 s of CPU time
// (--time-limit)".
std::string workerFailureLine(const std::string& what, const WorkerOutcome& outcome,
                              const Limits& limits);

}  // namespace sl
