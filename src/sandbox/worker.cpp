#include "sandbox/worker.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iostream>
#include <memory>
#include <new>
#include <optional>
#include <stdexcept>

#include "io/files.h"
#include "io/usage_error.h"

namespace sl {

namespace {

using Clock = std::chrono::steady_clock;

// The exception kinds carried from the child to the parent: the caller's first (the most
// derived), then the sandbox's own.
std::pair<std::string, std::string> classify(const std::exception_ptr& error,
                                             const JobErrorKinds& kinds) {
    try {
        std::rethrow_exception(error);
    } catch (const std::exception& e) {
        std::string kind = kinds.kindOf ? kinds.kindOf(error) : std::string();
        if (!kind.empty()) return {kind, e.what()};
    } catch (...) {
        return {"runtime", "an unknown exception in the worker"};
    }
    try {
        std::rethrow_exception(error);
    } catch (const UsageError& e) {
        return {"usage", e.what()};
    } catch (const std::invalid_argument& e) {
        return {"invalid_argument", e.what()};
    } catch (const std::exception& e) {
        return {"runtime", e.what()};
    }
}

}  // namespace

[[noreturn]] void rethrowJobError(const WorkerOutcome& outcome, const JobErrorKinds& kinds) {
    const std::string& kind = outcome.errorKind;
    const std::string& what = outcome.errorWhat;
    if (kinds.raise) kinds.raise(kind, what);  // returns when the kind is not one of the caller's
    if (kind == "usage") throw UsageError(what);
    if (kind == "invalid_argument") throw std::invalid_argument(what);
    throw std::runtime_error(what);
}

namespace {

// Where workers keep Mesa's shader cache ("" = none): useShaderCacheFolder.
std::string& shaderCacheFolder() {
    static std::string folder;
    return folder;
}

// A backstop should the parent stop watching (it is the parent that ends a job at its budget):
// the kernel ends the worker once it has used every job's CPU time twice over (SIGXCPU, and
// SIGKILL a second later). `pid` 0: the calling process (the child, as it starts), else the
// worker's, a held job given more time: its hard limit was left where it was (`resumable`),
// since only a privileged parent may raise one.
void applyCpuBackstop(const Limits& limits, std::size_t jobs, bool resumable, pid_t pid = 0) {
    if (limits.cpuSeconds <= 0) return;
    const rlim_t cpu = static_cast<rlim_t>(std::ceil(limits.cpuSeconds * 2 * double(jobs))) + 10;
    struct rlimit now;
    if (::prlimit(pid, RLIMIT_CPU, nullptr, &now) != 0) return;
    struct rlimit r = {cpu, resumable ? now.rlim_max : std::min(now.rlim_max, cpu + 1)};
    r.rlim_cur = std::min(r.rlim_cur, r.rlim_max);
    ::prlimit(pid, RLIMIT_CPU, &r, nullptr);
}

// The calling process's CPU time, user and system, all its threads.
double ownCpuSeconds() {
    struct rusage u;
    ::getrusage(RUSAGE_SELF, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           double(u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-6;
}

// A field ("VmHWM:") of /proc/self/status in MB, or 0.
long ownStatusMb(const char* field) {
    FILE* f = std::fopen("/proc/self/status", "r");
    if (!f) return 0;
    char line[256];
    long kb = 0;
    std::size_t n = std::strlen(field);
    while (std::fgets(line, sizeof line, f))
        if (std::strncmp(line, field, n) == 0) kb = std::atol(line + n);
    std::fclose(f);
    return kb / 1024;
}

// Starts a new peak of resident memory (Linux >= 4.0): each job's own peak is then VmHWM.
void resetPeakMemory() {
    int fd = ::open("/proc/self/clear_refs", O_WRONLY | O_CLOEXEC);
    if (fd < 0) return;
    ssize_t ignored = ::write(fd, "5", 1);
    (void)ignored;
    ::close(fd);
}

void writeAll(int fd, const std::string& text) {
    const char* p = text.data();
    std::size_t left = text.size();
    while (left > 0) {
        ssize_t n = ::write(fd, p, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return;  // the parent is gone: nothing to tell
        p += n;
        left -= static_cast<std::size_t>(n);
    }
}

// The worker's end once its replies are written. An _exit leaves the freeing of its memory to
// whichever of its threads dies last, and that is Mesa's disk-cache thread (nice 19,
// SCHED_BATCH): beside a busy loop it waits seconds for a core, the parent waiting for it
// (issue 39: 2.2-4.9 s a worker). execve makes the kernel end every other thread first (a few
// microseconds of work each) and free the old memory in this thread, at the worker's own
// priority; `true` then exits at once. Without a `true` to run, _exit as before.
[[noreturn]] void endWorker() {
    char name[] = "true";
    char* argv[] = {name, nullptr};
    char* envp[] = {nullptr};
    ::execve("/bin/true", argv, envp);
    ::execve("/usr/bin/true", argv, envp);
    ::_exit(0);
}

// The child: jobs [first, count) in order, one line of JSON for each as it finishes; it stops
// after a job that threw (the parent rethrows) or ran out of memory.
[[noreturn]] void runChild(const Limits& limits, const SeriesJob& job, const JobErrorKinds& kinds,
                           std::size_t first, std::size_t count, int fd, pid_t parent,
                           bool resumable) {
    ::setpgid(0, 0);  // its own group: a timeout kills whatever it started too
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(125);  // the parent died before prctl
    applyCpuBackstop(limits, count - first, resumable);
    // Mesa would keep every shader a submission compiles in ~/.cache/mesa_shader_cache: grading
    // leaves nothing behind (and no student's cache entry serves another's). In the run's own
    // folder when it has one (a check recompiles the same programs for every lesson and view:
    // peers at 160x120 takes 1.6 s so, 5.5 s with no cache), else no cache at all.
    const std::string& cache = shaderCacheFolder();
    if (!cache.empty()) {
        ::setenv("MESA_SHADER_CACHE_DIR", cache.c_str(), 1);
        ::setenv("MESA_GLSL_CACHE_DIR", cache.c_str(), 1);  // Mesa before 21
        ::unsetenv("MESA_SHADER_CACHE_DISABLE");
        ::unsetenv("MESA_GLSL_CACHE_DISABLE");
    } else {
        ::setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
        ::setenv("MESA_GLSL_CACHE_DISABLE", "true", 1);
    }
    for (std::size_t k = first; k < count; ++k) {
        std::string line;
        bool stop = true;
        resetPeakMemory();
        const double cpuBefore = ownCpuSeconds();
        try {
            nlohmann::json reply;
            try {
                reply = {{"ok", job(k)}};
                stop = false;
            } catch (const std::bad_alloc&) {
                reply = {{"oom", true}};
            } catch (...) {
                auto [kind, what] = classify(std::current_exception(), kinds);
                reply = {{"error", {{"kind", kind}, {"what", capped(what, kMaxErrorText)}}}};
            }
            // What the job cost: the parent's budgets are calibrated on these (sandbox/budget.h).
            const double cpuAfter = ownCpuSeconds();
            reply["cpu"] = cpuAfter - cpuBefore;
            reply["cpu_total"] = cpuAfter;
            reply["peak_mb"] = ownStatusMb("VmHWM:");
            line = reply.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
        } catch (const std::bad_alloc&) {
            line = "{\"oom\":true}";
            stop = true;
        }
        std::cout.flush();
        std::cerr.flush();
        std::fflush(nullptr);
        writeAll(fd, line + "\n");  // dump(-1) escapes every line break inside
        if (stop) break;
    }
    endWorker();  // no destructors, no atexit: the parent owns everything else
}

enum class Read { Line, EndOfFile, Deadline, TooLong, OverCpu, OverMemory };

// How often the parent looks at a running job's CPU time and memory: a job past its budget is
// stopped within this (a compiler that allocates 2 GB/s overshoots by some 40 MB).
constexpr int kWatchMs = 20;

// A job's reply is a few kilobytes a row (messages are capped in the worker): a reply past this
// is not read on, so the parent stays small whatever the worker does.
constexpr std::size_t kMaxReplyBytes = 16u << 20;

// The next line from the worker into `line`, or why there is none. `watch` is asked every
// kWatchMs while the job runs: Read::Line to go on, else why the job must stop.
Read nextLine(int fd, std::string& buffer, const std::optional<Clock::time_point>& deadline,
              std::string& line, const std::function<Read()>& watch = nullptr) {
    char chunk[65536];
    for (;;) {
        std::size_t end = buffer.find('\n');
        if (end != std::string::npos) {
            line = buffer.substr(0, end);
            buffer.erase(0, end + 1);
            return Read::Line;
        }
        int wait = watch ? kWatchMs : -1;
        if (deadline) {
            // Rounded up: truncated, the last fraction of a millisecond read as "reached" and
            // the deadline came up to 1 ms early (a 0.5 s backstop measured 0.4995 s).
            auto now = Clock::now();
            if (now >= *deadline) return Read::Deadline;
            auto left = std::chrono::ceil<std::chrono::milliseconds>(*deadline - now);
            long long most = watch ? kWatchMs : 60000;
            wait = static_cast<int>(std::min<long long>(left.count() + 1, most));
        }
        struct pollfd p = {fd, POLLIN, 0};
        int ready = ::poll(&p, 1, wait);
        if (ready < 0 && errno == EINTR) continue;
        if (ready < 0)
            throw std::runtime_error(std::string("worker: poll: ") + std::strerror(errno));
        if (ready == 0) {  // the loop checks the deadline; the watch the budgets
            if (watch) {
                Read verdict = watch();
                if (verdict != Read::Line) return verdict;
            }
            continue;
        }
        ssize_t n = ::read(fd, chunk, sizeof chunk);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return Read::EndOfFile;  // the child exited (a partial line is no result)
        buffer.append(chunk, static_cast<std::size_t>(n));
        if (buffer.size() > kMaxReplyBytes && buffer.find('\n') == std::string::npos)
            return Read::TooLong;
    }
}

// Waits for the child until the deadline; false = the deadline passed, the child still runs.
bool reapUntil(pid_t pid, const std::optional<Clock::time_point>& deadline, int& status) {
    for (;;) {
        pid_t done = ::waitpid(pid, &status, WNOHANG);
        if (done == pid) return true;
        if (done < 0 && errno != EINTR)
            throw std::runtime_error(std::string("worker: waitpid: ") + std::strerror(errno));
        if (deadline && Clock::now() >= *deadline) return false;
        ::usleep(1000);
    }
}

void killGroup(pid_t pid) {
    ::kill(-pid, SIGKILL);
    ::kill(pid, SIGKILL);
}

std::string signalName(int sig) {
    switch (sig) {
        case SIGSEGV:
            return "SIGSEGV";
        case SIGABRT:
            return "SIGABRT";
        case SIGBUS:
            return "SIGBUS";
        case SIGFPE:
            return "SIGFPE";
        case SIGILL:
            return "SIGILL";
        case SIGKILL:
            return "SIGKILL";
        case SIGTERM:
            return "SIGTERM";
        case SIGXCPU:
            return "SIGXCPU";
        case SIGXFSZ:
            return "SIGXFSZ";
        case SIGTRAP:
            return "SIGTRAP";
        case SIGSYS:
            return "SIGSYS";
        default:
            return "signal " + std::to_string(sig);
    }
}

std::string limitSeconds(double s) {
    char text[32];
    std::snprintf(text, sizeof text, "%g s", s);
    return text;
}

// /proc/PID/FILE of a running process as text ("" when it cannot be read): small files, read
// in one call.
std::string procFile(pid_t pid, const char* file) {
    char path[64], text[1024];
    std::snprintf(path, sizeof path, "/proc/%d/%s", int(pid), file);
    int fd = ::open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0) return "";
    ssize_t n = ::read(fd, text, sizeof text - 1);
    ::close(fd);
    return n > 0 ? std::string(text, std::size_t(n)) : "";
}

// A running process's CPU time (user + system, every thread) from /proc/PID/stat, or -1.
double processCpuSeconds(pid_t pid) {
    const std::string text = procFile(pid, "stat");
    std::size_t close = text.rfind(')');  // the name may hold spaces and parentheses
    if (close == std::string::npos || close + 2 > text.size()) return -1;
    unsigned long long utime = 0, stime = 0;
    // After ") ": state, then fields 4..13, then utime (14) and stime (15).
    if (std::sscanf(text.c_str() + close + 2,
                    "%*c %*d %*d %*d %*d %*d %*u %*u %*u %*u %*u %llu %llu", &utime, &stime) != 2)
        return -1;
    static const double tick = double(::sysconf(_SC_CLK_TCK));
    return double(utime + stime) / tick;
}

// A running process's resident memory in MB from /proc/PID/statm, or -1.
long processResidentMb(pid_t pid) {
    unsigned long long size = 0, resident = 0;
    if (std::sscanf(procFile(pid, "statm").c_str(), "%llu %llu", &size, &resident) != 2) return -1;
    static const long page = ::sysconf(_SC_PAGESIZE);
    return long(resident * static_cast<unsigned long long>(page) >> 20);
}

}  // namespace

std::string WorkerOutcome::detail() const {
    switch (kind) {
        case Kind::Ok:
            return "finished";
        case Kind::Timeout:
            return overWallClock ? "ran out of time" : "used up its CPU time";
        case Kind::Crash:
            return outOfMemory ? "ran out of memory" : "killed by " + signalName(signal);
        case Kind::Failed:
            if (tooLong) return "sent a result of more than 16 MB";
            return "exited with code " + std::to_string(exitCode) + " without a result";
        case Kind::Error:
            return errorWhat;
    }
    return "";
}

void useShaderCacheFolder(const std::string& folder) {
    shaderCacheFolder() = folder;
}

std::string timeLimitText(const Limits& limits) {
    return limits.cpuSeconds > 0 ? limitSeconds(limits.cpuSeconds) + " of CPU time"
                                 : "no time limit";
}

std::string memoryLimitText(const Limits& limits) {
    return limits.memoryMb > 0 ? std::to_string(limits.memoryMb) + " MB" : "no memory limit";
}

std::string usageText(const WorkerOutcome& o, const Limits& limits) {
    char used[160];
    std::snprintf(used, sizeof used, "%.2f s of CPU time (budget: %s) at a peak of %ld MB (%s)",
                  o.cpuSeconds, timeLimitText(limits).c_str(), o.peakMb,
                  memoryLimitText(limits).c_str());
    return used;
}

std::string machineEvidence(const WorkerOutcome& o, const Limits& limits) {
    // A job's own work can reach its limits; a signal from outside or a stall cannot be its.
    const bool cpuFarBelow = limits.cpuSeconds <= 0 || o.cpuSeconds < 0.5 * limits.cpuSeconds;
    const bool memoryFarBelow = limits.memoryMb <= 0 || o.peakMb < limits.memoryMb / 2;
    const std::string used = usageText(o, limits);
    const int s = o.signal;
    const bool fromOutside = s == SIGKILL || s == SIGTERM || s == SIGINT || s == SIGHUP ||
                             s == SIGQUIT || s == SIGUSR1 || s == SIGUSR2 || s == SIGALRM;
    if (o.kind == WorkerOutcome::Kind::Crash && !o.outOfMemory && fromOutside && cpuFarBelow &&
        memoryFarBelow)
        return "killed by " + signalName(s) + ", a signal the grader did not send, after " + used;
    if (o.kind == WorkerOutcome::Kind::Timeout && o.overWallClock && limits.cpuSeconds > 0 &&
        cpuFarBelow) {
        char wall[200];
        std::snprintf(wall, sizeof wall,
                      "no result within %.0f s of wall-clock time while it used ", o.seconds);
        return wall + used + ": the worker was stopped or starved, not working";
    }
    return "";
}

std::string workerFailureLine(const std::string& what, const WorkerOutcome& o,
                              const Limits& limits) {
    const std::string memory =
        "the memory limit is " + memoryLimitText(limits) + " (--memory-limit)";
    switch (o.kind) {
        case WorkerOutcome::Kind::Ok:
            return what + ": finished";
        case WorkerOutcome::Kind::Timeout:
            if (o.overWallClock)
                return what + ": no result within " + limitSeconds(limits.wallSeconds) +
                       " of wall-clock time (the backstop of a worker that waits on nothing)";
            return what + ": used up its time budget of " + timeLimitText(limits) +
                   " (--time-limit)";
        case WorkerOutcome::Kind::Crash:
            if (o.outOfMemory)
                return what + ": ran out of memory within the memory limit of " +
                       memoryLimitText(limits) + " (--memory-limit)";
            return what + ": its worker was killed by " + signalName(o.signal) +
                   " (a crash in the shader compiler or driver, or memory exhausted; " + memory +
                   ")";
        case WorkerOutcome::Kind::Failed:
            return what + ": its worker " + o.detail() + " (" + memory + ")";
        case WorkerOutcome::Kind::Error:
            return what + ": " + o.errorWhat;
    }
    return what;
}

namespace {

// A running worker: its process (own group), the parent's end of its pipe, and what its
// current job has used so far.
class Worker {
  public:
    // `resumable`: its CPU backstop may be raised later (resume).
    Worker(const Limits& limits, const SeriesJob& job, const JobErrorKinds& kinds,
           std::size_t first, std::size_t count, bool resumable = false)
        : limits_(limits) {
        std::cout.flush();  // else the child inherits unwritten output and writes it twice
        std::cerr.flush();
        std::fflush(nullptr);
        int fds[2];
        if (::pipe2(fds, O_CLOEXEC) != 0)
            throw std::runtime_error(std::string("worker: pipe: ") + std::strerror(errno));
        const pid_t parent = ::getpid();
        pid_ = ::fork();
        if (pid_ < 0) {
            int err = errno;
            ::close(fds[0]);
            ::close(fds[1]);
            throw std::runtime_error(std::string("worker: fork: ") + std::strerror(err));
        }
        if (pid_ == 0) {
            ::close(fds[0]);
            runChild(limits, job, kinds, first, count, fds[1], parent, resumable);
        }
        ::setpgid(pid_, pid_);  // as the child does: whichever runs first
        ::close(fds[1]);
        fd_ = fds[0];
    }
    Worker(const Worker&) = delete;
    Worker& operator=(const Worker&) = delete;
    ~Worker() {  // killed and reaped unless finish() reaped it
        if (pid_ > 0) {
            killGroup(pid_);
            int status;
            while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
            }
        }
        if (fd_ >= 0) ::close(fd_);
    }
    Read next(const std::optional<Clock::time_point>& deadline, std::string& line) {
        Read read = nextLine(fd_, buffer_, deadline, line, [this] { return watch(); });
        if (read == Read::Line) noteReply(line);
        return read;
    }
    // A line if one has arrived, EndOfFile if the child has gone, OverCpu or OverMemory when
    // the job is past its budget, else Deadline (nothing yet).
    Read nextNow(std::string& line) {
        struct pollfd p = {fd_, POLLIN, 0};
        while (buffer_.find('\n') == std::string::npos && ::poll(&p, 1, 0) > 0) {
            char chunk[65536];
            ssize_t n = ::read(fd_, chunk, sizeof chunk);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) return Read::EndOfFile;
            buffer_.append(chunk, static_cast<std::size_t>(n));
        }
        if (nextLine(fd_, buffer_, Clock::now() - std::chrono::seconds(1), line) == Read::Line) {
            noteReply(line);
            return Read::Line;
        }
        Read verdict = watch();
        return verdict == Read::Line ? Read::Deadline : verdict;
    }
    // Reaps the child, killing it at the deadline; returns its wait status and whether it had
    // to be killed.
    int finish(const std::optional<Clock::time_point>& deadline, bool& killed) {
        int status = 0;
        killed = !reapUntil(pid_, deadline, status);
        if (killed) {
            killGroup(pid_);
            while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
            }
        }
        pid_ = -1;
        return status;
    }
    // Stops the worker where it is (every thread of its group), or lets it go on with new
    // limits (its CPU backstop raised to suit them).
    void hold() { ::kill(-pid_, SIGSTOP); }
    void resume(const Limits& limits, std::size_t jobs) {
        limits_ = limits;
        applyCpuBackstop(limits, jobs, true, pid_);
        ::kill(-pid_, SIGCONT);
    }
    // What the current job has used: CPU seconds since it began, the highest resident memory
    // the parent saw.
    double jobCpuSeconds() const { return std::max(0.0, lastCpu_ - cpuAtJobStart_); }
    long jobPeakMb() const { return peakMb_; }

  private:
    // Read::Line while the job is within its budgets.
    Read watch() {
        double cpu = processCpuSeconds(pid_);
        long mb = processResidentMb(pid_);
        if (cpu >= 0) lastCpu_ = cpu;
        if (mb > peakMb_) peakMb_ = mb;
        if (limits_.cpuSeconds > 0 && jobCpuSeconds() > limits_.cpuSeconds) return Read::OverCpu;
        if (limits_.memoryMb > 0 && mb > limits_.memoryMb) return Read::OverMemory;
        return Read::Line;
    }
    // A job's reply says where the worker's CPU clock stood when it ended: the next job's
    // usage counts from there.
    // The reply's keys are sorted, so "cpu_total" comes before the job's own text ("error",
    // "ok"): its first occurrence is ours.
    void noteReply(const std::string& line) {
        static const std::string key = "\"cpu_total\":";
        std::size_t at = line.find(key);
        if (at != std::string::npos)
            cpuAtJobStart_ = lastCpu_ = std::strtod(line.c_str() + at + key.size(), nullptr);
        peakMb_ = 0;
    }
    Limits limits_;
    pid_t pid_ = -1;
    int fd_ = -1;
    std::string buffer_;
    double cpuAtJobStart_ = 0, lastCpu_ = 0;
    long peakMb_ = 0;
};

std::optional<Clock::time_point> deadlineFrom(const Clock::time_point& start,
                                              const Limits& limits) {
    if (limits.wallSeconds <= 0) return std::nullopt;
    return start + std::chrono::duration_cast<Clock::duration>(
                       std::chrono::duration<double>(limits.wallSeconds));
}

// How a worker that ended without a line for its job ended.
WorkerOutcome endedWithout(int status, bool killed) {
    WorkerOutcome out;
    if (killed) {
        out.kind = WorkerOutcome::Kind::Timeout;
        out.overWallClock = true;
    } else if (WIFSIGNALED(status)) {
        out.signal = WTERMSIG(status);
        out.kind =
            out.signal == SIGXCPU ? WorkerOutcome::Kind::Timeout : WorkerOutcome::Kind::Crash;
    } else {
        out.kind = WorkerOutcome::Kind::Failed;
        out.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }
    return out;
}

// What the worker's line for a job says.
WorkerOutcome outcomeOfLine(const std::string& line) {
    WorkerOutcome out;
    nlohmann::json message = nlohmann::json::parse(line, nullptr, false);
    if (message.is_object() && message.contains("error")) {
        out.kind = WorkerOutcome::Kind::Error;
        out.errorKind = message["error"].value("kind", "runtime");
        out.errorWhat = message["error"].value("what", "");
    } else if (message.is_object() && message.contains("ok")) {
        out.value = std::move(message["ok"]);
    } else {
        out.kind = WorkerOutcome::Kind::Crash;
        out.outOfMemory = message.is_object() && message.contains("oom");
    }
    if (message.is_object()) {
        out.cpuSeconds = message.value("cpu", 0.0);
        out.peakMb = message.value("peak_mb", 0L);
    }
    return out;
}

// The outcome of a read that brought no line: the job is over its budget, past the backstop,
// its reply too long, or the worker gone (reaped here).
WorkerOutcome outcomeWithoutLine(Read read, Worker& worker, const Limits& limits) {
    WorkerOutcome out;
    if (read == Read::OverCpu || read == Read::Deadline) {
        out.kind = WorkerOutcome::Kind::Timeout;  // ~Worker kills it
        out.overWallClock = read == Read::Deadline;
    } else if (read == Read::OverMemory) {
        out.kind = WorkerOutcome::Kind::Crash;
        out.outOfMemory = true;
    } else if (read == Read::TooLong) {
        out.kind = WorkerOutcome::Kind::Failed;
        out.exitCode = -1;
        out.tooLong = true;
    } else {
        bool killed = false;
        int status = worker.finish(deadlineFrom(Clock::now(), limits), killed);
        out = endedWithout(status, killed);
    }
    out.cpuSeconds = worker.jobCpuSeconds();
    out.peakMb = worker.jobPeakMb();
    return out;
}

}  // namespace

struct BackgroundSeries::Running {
    std::unique_ptr<Worker> worker;
    Clock::time_point since;
};

BackgroundSeries::BackgroundSeries(const Limits& limits, std::size_t count, SeriesJob job,
                                   JobErrorKinds kinds, bool holdOverCpu)
    : limits_(limits),
      count_(count),
      job_(std::move(job)),
      kinds_(std::move(kinds)),
      holdOverCpu_(holdOverCpu) {}

void BackgroundSeries::resume(const Limits& limits) {
    if (!held_ || !running_) return;
    limits_ = limits;
    outcomes_.pop_back();                          // the job goes on: its outcome is still to come
    running_->since += Clock::now() - heldSince_;  // the wall clock counts the time it ran
    running_->worker->resume(limits, count_ - outcomes_.size());
    held_ = false;
}

BackgroundSeries::~BackgroundSeries() = default;  // ~Worker kills and reaps a running child

bool BackgroundSeries::poll() {
    if (failed_ || held_) return true;
    while (outcomes_.size() < count_) {
        if (!running_) {  // a fresh worker for the next job (the first, or after a failure)
            running_ = std::make_unique<Running>();
            running_->worker = std::make_unique<Worker>(limits_, job_, kinds_, outcomes_.size(),
                                                        count_, holdOverCpu_);
            running_->since = Clock::now();
        }
        // Only what has arrived: a deadline already past makes nextLine return at once, so
        // look at the pipe without waiting first.
        std::string line;
        Read read = running_->worker->nextNow(line);
        const auto deadline = deadlineFrom(running_->since, limits_);
        WorkerOutcome out;
        if (read == Read::Line) {
            out = outcomeOfLine(line);
        } else if (read == Read::Deadline && !(deadline && Clock::now() >= *deadline)) {
            return false;  // still working, within its budgets
        } else {
            out = outcomeWithoutLine(read, *running_->worker, limits_);
        }
        out.seconds = std::chrono::duration<double>(Clock::now() - running_->since).count();
        if (read == Read::OverCpu && holdOverCpu_) {  // stopped, not ended: resume() or not
            running_->worker->hold();
            held_ = true;
            heldSince_ = Clock::now();
            outcomes_.push_back(std::move(out));
            return true;
        }
        running_->since = Clock::now();
        const bool ok = out.kind == WorkerOutcome::Kind::Ok;
        outcomes_.push_back(std::move(out));
        if (!ok || outcomes_.size() == count_) {
            running_.reset();  // killed and reaped
            failed_ = !ok;
        }
        if (failed_) return true;
    }
    return true;
}

void runBoundedSeries(const Limits& limits, std::size_t count, const SeriesJob& job,
                      const JobErrorKinds& kinds,
                      const std::function<void(std::size_t, const WorkerOutcome&)>& done) {
    std::size_t k = 0;
    while (k < count) {
        auto worker = std::make_unique<Worker>(limits, job, kinds, k, count);
        auto since = Clock::now();
        for (;;) {
            std::string line;
            Read read = worker->next(deadlineFrom(since, limits), line);
            WorkerOutcome out = read == Read::Line ? outcomeOfLine(line)
                                                   : outcomeWithoutLine(read, *worker, limits);
            out.seconds = std::chrono::duration<double>(Clock::now() - since).count();
            since = Clock::now();
            bool goOn = out.kind == WorkerOutcome::Kind::Ok;
            // A failed worker is ended before anyone hears of it: what `done` runs next (our
            // shaders measured, the job again) must not share the cores with a spinning shader.
            if (!goOn) worker.reset();
            if (done) done(k, out);
            ++k;
            if (!goOn) break;  // a fresh worker for the jobs after this one
            if (k == count) {
                bool killed = false;
                worker->finish(deadlineFrom(Clock::now(), limits), killed);
                break;
            }
        }
    }
}

WorkerOutcome runBounded(const Limits& limits, const std::function<nlohmann::json()>& job,
                         const JobErrorKinds& kinds) {
    WorkerOutcome outcome;
    runBoundedSeries(
        limits, 1, [&](std::size_t) { return job(); }, kinds,
        [&](std::size_t, const WorkerOutcome& o) { outcome = o; });
    if (outcome.kind == WorkerOutcome::Kind::Error) rethrowJobError(outcome, kinds);
    return outcome;
}

}  // namespace sl
