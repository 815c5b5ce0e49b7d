#include "app/worker.h"

#include <fcntl.h>
#include <malloc.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <new>
#include <optional>
#include <stdexcept>

#include "gl/shader_library.h"
#include "render/request.h"
#include "scene/scene_json.h"
#include "stages/expectations.h"

// A sanitizer reserves terabytes of address space for its shadow memory: no RLIMIT_AS there.
#if defined(__SANITIZE_ADDRESS__)
#define SL_NO_ADDRESS_LIMIT 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer)
#define SL_NO_ADDRESS_LIMIT 1
#endif
#endif

namespace sl {

namespace {

using Clock = std::chrono::steady_clock;

// The exception kinds carried from the child to the parent, most derived first.
std::pair<std::string, std::string> classify(const std::exception_ptr& error) {
    try {
        std::rethrow_exception(error);
    } catch (const ShaderError& e) {
        return {"shader", e.what()};
    } catch (const SceneError& e) {
        return {"scene", e.what()};
    } catch (const UsageError& e) {
        return {"usage", e.what()};
    } catch (const ExpectationError& e) {
        return {"expectation", e.what()};
    } catch (const std::invalid_argument& e) {
        return {"invalid_argument", e.what()};
    } catch (const std::exception& e) {
        return {"runtime", e.what()};
    } catch (...) {
        return {"runtime", "an unknown exception in the worker"};
    }
}

[[noreturn]] void rethrowCarried(const nlohmann::json& error) {
    const std::string kind = error.value("kind", "runtime");
    const std::string what = error.value("what", "");
    if (kind == "shader") throw ShaderError(what);
    if (kind == "scene") throw SceneError(what);
    if (kind == "usage") throw UsageError(what);
    if (kind == "expectation") throw ExpectationError(what);
    if (kind == "invalid_argument") throw std::invalid_argument(what);
    throw std::runtime_error(what);
}

void applyLimits(const Limits& limits) {
    if (limits.seconds > 0) {  // a backstop: the wall clock ends the worker first
        long cpus = std::max(1L, ::sysconf(_SC_NPROCESSORS_ONLN));
        rlim_t cpu = static_cast<rlim_t>(std::ceil(limits.seconds * cpus)) + 1;
        struct rlimit r = {cpu, cpu + 1};
        ::setrlimit(RLIMIT_CPU, &r);
    }
#ifndef SL_NO_ADDRESS_LIMIT
    if (limits.memoryMb > 0) {
        // glibc reserves 64 MB of address space per malloc arena, up to 8 per core: cap them so
        // the limit measures memory in use, not the machine's core count.
        ::mallopt(M_ARENA_MAX, 2);
        rlim_t bytes = static_cast<rlim_t>(limits.memoryMb) << 20;
        struct rlimit r = {bytes, bytes};
        ::setrlimit(RLIMIT_AS, &r);
    }
#endif
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

[[noreturn]] void runChild(const Limits& limits, const std::function<nlohmann::json()>& job, int fd,
                           pid_t parent) {
    ::setpgid(0, 0);  // its own group: a timeout kills whatever it started too
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(125);  // the parent died before prctl
    applyLimits(limits);
    std::string message;
    try {
        nlohmann::json reply;
        try {
            reply = {{"ok", job()}};
        } catch (const std::bad_alloc&) {
            reply = {{"oom", true}};
        } catch (...) {
            auto [kind, what] = classify(std::current_exception());
            reply = {{"error", {{"kind", kind}, {"what", what}}}};
        }
        message = reply.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    } catch (const std::bad_alloc&) {
        message = "{\"oom\":true}";
    }
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    writeAll(fd, message);
    ::_exit(0);  // no destructors, no atexit: the parent owns everything else
}

// Reads the child's reply until end of file or the deadline; false = the deadline passed.
bool readUntil(int fd, const std::optional<Clock::time_point>& deadline, std::string& out) {
    char buffer[65536];
    for (;;) {
        int wait = -1;
        if (deadline) {
            auto left =
                std::chrono::duration_cast<std::chrono::milliseconds>(*deadline - Clock::now());
            if (left.count() <= 0) return false;
            wait = static_cast<int>(std::min<long long>(left.count() + 1, 60000));
        }
        struct pollfd p = {fd, POLLIN, 0};
        int ready = ::poll(&p, 1, wait);
        if (ready < 0 && errno == EINTR) continue;
        if (ready < 0)
            throw std::runtime_error(std::string("worker: poll: ") + std::strerror(errno));
        if (ready == 0) continue;  // the loop checks the deadline
        ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return true;  // end of file: the child exited (or closed its end)
        out.append(buffer, static_cast<std::size_t>(n));
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

}  // namespace

std::string WorkerOutcome::detail() const {
    switch (kind) {
        case Kind::Ok:
            return "finished";
        case Kind::Timeout:
            return signal == SIGXCPU ? "used up its CPU time" : "ran out of time";
        case Kind::Crash:
            return outOfMemory ? "ran out of memory" : "killed by " + signalName(signal);
        case Kind::Failed:
            return "exited with code " + std::to_string(exitCode) + " without a result";
    }
    return "";
}

std::string timeLimitText(const Limits& limits) {
    return limits.seconds > 0 ? limitSeconds(limits.seconds) : "no time limit";
}

std::string memoryLimitText(const Limits& limits) {
    return limits.memoryMb > 0 ? std::to_string(limits.memoryMb) + " MB" : "no memory limit";
}

std::string workerFailureLine(const std::string& what, const WorkerOutcome& o,
                              const Limits& limits) {
    const std::string memory =
        "the memory limit is " + memoryLimitText(limits) + " (--memory-limit)";
    switch (o.kind) {
        case WorkerOutcome::Kind::Ok:
            return what + ": finished";
        case WorkerOutcome::Kind::Timeout:
            return what + ": no result within the time limit of " + timeLimitText(limits) +
                   " (--time-limit)" + (o.signal == SIGXCPU ? ": its CPU time ran out" : "");
        case WorkerOutcome::Kind::Crash:
            if (o.outOfMemory)
                return what + ": ran out of memory within the memory limit of " +
                       memoryLimitText(limits) + " (--memory-limit)";
            return what + ": its worker was killed by " + signalName(o.signal) +
                   " (a crash in the shader compiler or driver, or memory exhausted; " + memory +
                   ")";
        case WorkerOutcome::Kind::Failed:
            return what + ": its worker " + o.detail() + " (" + memory + ")";
    }
    return what;
}

WorkerOutcome runBounded(const Limits& limits, const std::function<nlohmann::json()>& job) {
    std::cout.flush();  // else the child inherits unwritten output and writes it a second time
    std::cerr.flush();
    std::fflush(nullptr);
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0)
        throw std::runtime_error(std::string("worker: pipe: ") + std::strerror(errno));
    const pid_t parent = ::getpid();
    const auto start = Clock::now();
    pid_t pid = ::fork();
    if (pid < 0) {
        int err = errno;
        ::close(fds[0]);
        ::close(fds[1]);
        throw std::runtime_error(std::string("worker: fork: ") + std::strerror(err));
    }
    if (pid == 0) {
        ::close(fds[0]);
        runChild(limits, job, fds[1], parent);
    }
    ::setpgid(pid, pid);  // as the child does: whichever runs first
    ::close(fds[1]);
    std::optional<Clock::time_point> deadline;
    if (limits.seconds > 0)
        deadline = start + std::chrono::duration_cast<Clock::duration>(
                               std::chrono::duration<double>(limits.seconds));
    std::string reply;
    bool timedOut = false;
    int status = 0;
    try {
        timedOut = !readUntil(fds[0], deadline, reply) || !reapUntil(pid, deadline, status);
    } catch (...) {
        killGroup(pid);
        ::waitpid(pid, &status, 0);
        ::close(fds[0]);
        throw;
    }
    ::close(fds[0]);
    if (timedOut) {
        killGroup(pid);
        while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
        }
    }

    WorkerOutcome out;
    out.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (timedOut) {
        out.kind = WorkerOutcome::Kind::Timeout;
        return out;
    }
    if (WIFSIGNALED(status)) {
        out.signal = WTERMSIG(status);
        out.kind =
            out.signal == SIGXCPU ? WorkerOutcome::Kind::Timeout : WorkerOutcome::Kind::Crash;
        return out;
    }
    out.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    nlohmann::json message;
    if (out.exitCode == 0) message = nlohmann::json::parse(reply, nullptr, false);
    if (!message.is_object()) {
        out.kind = WorkerOutcome::Kind::Failed;
        return out;
    }
    if (message.contains("error")) rethrowCarried(message["error"]);
    if (message.contains("oom")) {
        out.kind = WorkerOutcome::Kind::Crash;
        out.outOfMemory = true;
        return out;
    }
    out.kind = WorkerOutcome::Kind::Ok;
    out.value = std::move(message["ok"]);
    return out;
}

}  // namespace sl
