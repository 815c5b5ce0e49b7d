#include "sandbox/job_fanout.h"

#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <thread>

#include "io/box.h"

namespace sl {

namespace {

int exitCodeOf(int status) {
    if (WIFEXITED(status)) return WEXITSTATUS(status);
    return WIFSIGNALED(status) ? 128 + WTERMSIG(status) : 3;
}

[[noreturn]] void runJob(int job, int coresEach, const std::string& what,
                         const std::function<int(int)>& body) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    shareCores(coresEach);
    int code = 3;
    try {
        code = body(job);
    } catch (const std::exception& e) {
        std::cerr << "shadowlab: " << what << " " << job << ": " << e.what() << "\n";
    }
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    ::_exit(code);  // nothing of the parent's (its destructors, atexit) runs twice
}

}  // namespace

JobFanOut::JobFanOut(int count, int coresEach, const std::string& what,
                     const std::function<int(int)>& body) {
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    for (int j = 0; j < count; ++j) {
        const pid_t pid = ::fork();
        if (pid < 0) throw std::runtime_error(what + ": cannot start a job process");
        if (pid == 0) runJob(j, coresEach, what, body);
        pids_.push_back(pid);
        ++running_;
    }
}

JobFanOut::~JobFanOut() {
    for (pid_t pid : pids_)
        if (pid > 0) {
            ::kill(pid, SIGKILL);
            while (::waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
            }
        }
}

std::vector<JobFanOut::Ended> JobFanOut::reap(std::chrono::milliseconds wait) {
    std::vector<Ended> ended;
    const auto until = std::chrono::steady_clock::now() + wait;
    while (running_ > 0) {
        for (std::size_t j = 0; j < pids_.size(); ++j) {
            int status = 0;
            if (pids_[j] <= 0 || ::waitpid(pids_[j], &status, WNOHANG) != pids_[j]) continue;
            ended.push_back({int(j), exitCodeOf(status)});
            pids_[j] = -1;
            --running_;
        }
        if (!ended.empty() || std::chrono::steady_clock::now() >= until) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return ended;
}

std::vector<JobFanOut::Ended> JobFanOut::waitAll() {
    std::vector<Ended> ended;
    for (std::size_t j = 0; j < pids_.size(); ++j) {
        if (pids_[j] <= 0) continue;
        int status = 0;
        while (::waitpid(pids_[j], &status, 0) < 0 && errno == EINTR) {
        }
        ended.push_back({int(j), exitCodeOf(status)});
        pids_[j] = -1;
        --running_;
    }
    return ended;
}

}  // namespace sl
