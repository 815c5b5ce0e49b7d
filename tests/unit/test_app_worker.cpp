// The bounded worker: a value comes back, the job's exceptions come back with their type, and a
// job that hangs, crashes, runs out of memory or exits is reported as such within its limits.
#include <gtest/gtest.h>
#include <pthread.h>
#include <sched.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <ctime>
#include <thread>
#include <vector>

#include "eval/job_errors.h"
#include "gl/shader_library.h"
#include "io/usage_error.h"
#include "sandbox/worker.h"
#include "scene/scene_json.h"

namespace sl {
namespace {

// The worker as render, check and the window run it: the renderer's exceptions carried.
WorkerOutcome runBounded(const Limits& l, const std::function<nlohmann::json()>& job) {
    return sl::runBounded(l, job, renderJobErrors());
}
void runBoundedSeries(const Limits& l, std::size_t count, const SeriesJob& job,
                      const std::function<void(std::size_t, const WorkerOutcome&)>& done) {
    sl::runBoundedSeries(l, count, job, renderJobErrors(), done);
}

// CPU time and the wall-clock backstop alike, and resident memory.
Limits limits(double seconds, long memoryMb) {
    Limits l;
    l.cpuSeconds = l.wallSeconds = seconds;
    l.memoryMb = memoryMb;
    return l;
}

TEST(Worker, ReturnsTheJobsValue) {
    WorkerOutcome o = runBounded(limits(5, 512), [] {
        return nlohmann::json{{"pid", ::getpid()}, {"text", std::string(200000, 'x')}};
    });
    ASSERT_EQ(o.kind, WorkerOutcome::Kind::Ok) << o.detail();
    EXPECT_NE(o.value["pid"].get<int>(), ::getpid());               // it ran in another process
    EXPECT_EQ(o.value["text"].get<std::string>().size(), 200000u);  // more than a pipe holds
}

TEST(Worker, BytesThatAreNotUtf8ComeBackReplaced) {
    WorkerOutcome o = runBounded(limits(5, 512), [] { return nlohmann::json("bad \xff byte"); });
    ASSERT_EQ(o.kind, WorkerOutcome::Kind::Ok);
    EXPECT_EQ(o.value.get<std::string>(), "bad \xEF\xBF\xBD byte");
}

TEST(Worker, TheJobsExceptionsKeepTheirType) {
    EXPECT_THROW(runBounded(limits(5, 512), []() -> nlohmann::json { throw UsageError("bad"); }),
                 UsageError);
    EXPECT_THROW(runBounded(limits(5, 512), []() -> nlohmann::json { throw ShaderError("x"); }),
                 ShaderError);
    EXPECT_THROW(runBounded(limits(5, 512), []() -> nlohmann::json { throw SceneError("x"); }),
                 SceneError);
    try {
        runBounded(limits(5, 512),
                   []() -> nlohmann::json { throw std::runtime_error("gl broke"); });
        FAIL() << "no exception";
    } catch (const UsageError&) {
        FAIL() << "a GL failure became bad input";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "gl broke");
    }
}

// The sandbox alone knows no renderer: a shader error is then any runtime failure.
TEST(Worker, KindsTheCallerDoesNotNameAreTheSandboxs) {
    const JobErrorKinds none;
    EXPECT_THROW(sl::runBounded(
                     limits(5, 512), []() -> nlohmann::json { throw UsageError("bad"); }, none),
                 UsageError);
    try {
        sl::runBounded(
            limits(5, 512), []() -> nlohmann::json { throw ShaderError("x"); }, none);
        FAIL() << "no exception";
    } catch (const ShaderError&) {
        FAIL() << "the sandbox named a kind it was not given";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "x");
    }
}

TEST(Worker, AJobThatWaitsOnNothingEndsAtTheWallClockBackstop) {
    auto start = std::chrono::steady_clock::now();
    WorkerOutcome o = runBounded(limits(0.5, 512), [] {
        for (;;) ::pause();
        return nlohmann::json();
    });
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(o.kind, WorkerOutcome::Kind::Timeout);
    EXPECT_TRUE(o.overWallClock);
    EXPECT_GE(seconds, 0.5);
    EXPECT_LT(seconds, 2.0);
    std::string line = workerFailureLine("stage x (core)", o, limits(0.5, 512));
    EXPECT_NE(line.find("stage x (core): no result within 0.5 s of wall-clock time"),
              std::string::npos)
        << line;
}

// The budget is CPU time: a spinning job ends when it has used it, however long the wall clock
// allows, and the outcome says how much it used.
TEST(Worker, ASpinningJobEndsAtItsCpuBudget) {
    Limits l;
    l.cpuSeconds = 0.4;
    l.wallSeconds = 60;
    auto start = std::chrono::steady_clock::now();
    WorkerOutcome o = runBounded(l, [] {
        for (volatile unsigned long k = 0;; k = k + 1) {
        }
        return nlohmann::json();
    });
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_EQ(o.kind, WorkerOutcome::Kind::Timeout);
    EXPECT_FALSE(o.overWallClock);
    EXPECT_GE(o.cpuSeconds, 0.4);
    EXPECT_LT(seconds, 30.0);  // not the wall clock: even on a loaded machine
    EXPECT_EQ(workerFailureLine("stage x (core)", o, l),
              "stage x (core): used up its time budget of 0.4 s of CPU time (--time-limit)");
}

// A job's cost comes back with its value: CPU time of all its threads, its peak memory.
TEST(Worker, AJobsCostComesBackWithItsValue) {
    Limits l;
    l.wallSeconds = 60;
    WorkerOutcome o = runBounded(l, [] {
        std::vector<char> block(96u << 20, 'x');  // touched: resident
        volatile unsigned long sum = 0;
        for (int pass = 0; pass < 3; ++pass)
            for (char c : block) sum = sum + static_cast<unsigned long>(c);
        return nlohmann::json(block.size());
    });
    ASSERT_EQ(o.kind, WorkerOutcome::Kind::Ok) << o.detail();
    EXPECT_GT(o.cpuSeconds, 0.0);
    EXPECT_GE(o.peakMb, 96);
}

TEST(Worker, ACrashIsReportedWithItsSignal) {
    WorkerOutcome o = runBounded(limits(5, 512), []() -> nlohmann::json {
        // A driver crash under a sanitizer would end in the sanitizer's own handler (an exit
        // code); the default action is what a grading machine sees.
        ::signal(SIGSEGV, SIG_DFL);
        ::raise(SIGSEGV);
        return nullptr;
    });
    ASSERT_EQ(o.kind, WorkerOutcome::Kind::Crash);
    EXPECT_EQ(o.signal, SIGSEGV);
    EXPECT_EQ(o.detail(), "killed by SIGSEGV");
    std::string line = workerFailureLine("stage x (core)", o, limits(5, 512));
    EXPECT_NE(line.find("killed by SIGSEGV"), std::string::npos) << line;
    EXPECT_NE(line.find("512 MB (--memory-limit)"), std::string::npos) << line;
}

#if !defined(__SANITIZE_ADDRESS__)
TEST(Worker, MemoryPastTheLimitIsOutOfMemory) {
    WorkerOutcome o = runBounded(limits(10, 256), [] {
        std::vector<std::vector<char>> hog;
        for (int k = 0; k < 64; ++k) hog.emplace_back(64u << 20, 'x');  // 4 GB in 64 MB steps
        return nlohmann::json(hog.size());
    });
    ASSERT_EQ(o.kind, WorkerOutcome::Kind::Crash) << o.detail();
    EXPECT_TRUE(o.outOfMemory);
    EXPECT_EQ(workerFailureLine("stage x (core)", o, limits(10, 256)),
              "stage x (core): ran out of memory within the memory limit of 256 MB "
              "(--memory-limit)");
}
#endif

TEST(Worker, AJobThatExitsHasNoResult) {
    WorkerOutcome o = runBounded(limits(5, 512), []() -> nlohmann::json { ::_exit(7); });
    ASSERT_EQ(o.kind, WorkerOutcome::Kind::Failed);
    EXPECT_EQ(o.exitCode, 7);
}

TEST(Worker, ASeriesSharesItsWorkerUntilAJobFails) {
    std::vector<WorkerOutcome> outcomes;
    auto start = std::chrono::steady_clock::now();
    runBoundedSeries(
        limits(0.5, 512), 6,
        [](std::size_t k) -> nlohmann::json {
            if (k == 2)
                for (;;) ::pause();  // past the time limit
            if (k == 3) ::raise(SIGABRT);
            if (k == 1 || k == 5) ::usleep(300000);  // each job's own limit, not the series'
            return ::getpid();
        },
        [&](std::size_t k, const WorkerOutcome& o) {
            EXPECT_EQ(k, outcomes.size());
            outcomes.push_back(o);
        });
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_EQ(outcomes.size(), 6u);
    EXPECT_EQ(outcomes[0].kind, WorkerOutcome::Kind::Ok);
    EXPECT_EQ(outcomes[1].kind, WorkerOutcome::Kind::Ok);
    EXPECT_EQ(outcomes[0].value, outcomes[1].value);  // one worker for both
    EXPECT_EQ(outcomes[2].kind, WorkerOutcome::Kind::Timeout);
    EXPECT_EQ(outcomes[3].kind, WorkerOutcome::Kind::Crash);
    EXPECT_EQ(outcomes[3].signal, SIGABRT);
    EXPECT_EQ(outcomes[4].kind, WorkerOutcome::Kind::Ok);
    EXPECT_EQ(outcomes[5].kind, WorkerOutcome::Kind::Ok);
    EXPECT_NE(outcomes[4].value, outcomes[0].value);  // a fresh worker after each failure
    EXPECT_EQ(outcomes[4].value, outcomes[5].value);
    EXPECT_LT(seconds, 3.0);
}

// Should the parent stop watching, the kernel ends a worker at twice its CPU budget (plus 10 s):
// SIGXCPU, then SIGKILL a second later.
TEST(Worker, TheKernelsBackstopIsTwiceTheBudget) {
    Limits l;
    l.cpuSeconds = 1.5;
    l.wallSeconds = 60;
    WorkerOutcome o = runBounded(l, [] {
        struct rlimit cpu;
        ::getrlimit(RLIMIT_CPU, &cpu);
        return nlohmann::json{cpu.rlim_cur, cpu.rlim_max};
    });
    ASSERT_EQ(o.kind, WorkerOutcome::Kind::Ok) << o.detail();
    EXPECT_EQ(o.value, nlohmann::json({13, 14}));
}

// The window's trial at its floor: a job past its CPU time is held (stopped, not killed) and
// goes on from where it stood when given more (no rerun of what it had done): it sees the time
// it was held as one gap, uses no CPU meanwhile, and runs under a CPU backstop raised for its
// new budget.
TEST(Worker, AHeldJobGoesOnFromWhereItStopped) {
    Limits l;
    l.cpuSeconds = 0.3;
    l.wallSeconds = 60;
    BackgroundSeries series(
        l, 1,
        [](std::size_t) -> nlohmann::json {
            // Spins for 0.8 s of its own CPU time, noting the longest wall-clock gap it saw.
            using Clock = std::chrono::steady_clock;
            double gap = 0;
            Clock::time_point last = Clock::now();
            while (std::clock() < 0.8 * CLOCKS_PER_SEC) {
                const Clock::time_point now = Clock::now();
                gap = std::max(gap, std::chrono::duration<double>(now - last).count());
                last = now;
            }
            struct rlimit cpu;
            ::getrlimit(RLIMIT_CPU, &cpu);
            return {{"gap", gap}, {"backstop", cpu.rlim_cur}, {"pid", ::getpid()}};
        },
        renderJobErrors(), true);
    auto wait = [&] {
        const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(30);
        while (!series.poll() && std::chrono::steady_clock::now() < end) ::usleep(20000);
    };
    wait();
    ASSERT_TRUE(series.held());
    ASSERT_EQ(series.outcomes().size(), 1u);
    EXPECT_EQ(series.outcomes()[0].kind, WorkerOutcome::Kind::Timeout);
    EXPECT_GE(series.outcomes()[0].cpuSeconds, 0.3);
    ::usleep(700000);  // held: it must not run meanwhile
    Limits more = l;
    more.cpuSeconds = 8;
    series.resume(more);
    EXPECT_FALSE(series.held());
    EXPECT_TRUE(series.outcomes().empty()) << "its outcome is still to come";
    wait();
    ASSERT_EQ(series.outcomes().size(), 1u);
    const WorkerOutcome& o = series.outcomes()[0];
    ASSERT_EQ(o.kind, WorkerOutcome::Kind::Ok) << o.detail();
    EXPECT_GE(o.value["gap"].get<double>(), 0.7) << "the same run went on after its hold";
    EXPECT_LT(o.cpuSeconds, 1.6) << "0.8 s of work, not redone";
    EXPECT_EQ(o.value["backstop"], 2 * 8 + 10) << "the kernel's backstop raised for 8 s";
}

// A job that throws is its own outcome (Error, with the kind and message), and a fresh worker
// goes on with the next: check grades the other stages and writes the report.
TEST(Worker, AnExceptionInASeriesIsThatJobsOutcome) {
    std::vector<WorkerOutcome> outcomes;
    runBoundedSeries(
        limits(5, 512), 3,
        [](std::size_t k) -> nlohmann::json {
            if (k == 1) throw UsageError("bad");
            return k;
        },
        [&](std::size_t, const WorkerOutcome& o) { outcomes.push_back(o); });
    ASSERT_EQ(outcomes.size(), 3u);
    EXPECT_EQ(outcomes[0].kind, WorkerOutcome::Kind::Ok);
    EXPECT_EQ(outcomes[1].kind, WorkerOutcome::Kind::Error);
    EXPECT_EQ(outcomes[1].errorKind, "usage");
    EXPECT_EQ(outcomes[1].errorWhat, "bad");
    ASSERT_EQ(outcomes[2].kind, WorkerOutcome::Kind::Ok);
    EXPECT_EQ(outcomes[2].value.get<int>(), 2);
    EXPECT_THROW(rethrowJobError(outcomes[1], renderJobErrors()), UsageError);
}

TEST(Worker, NoLimitsMeansNone) {
    WorkerOutcome o = runBounded(limits(0, 0), [] { return nlohmann::json(42); });
    ASSERT_EQ(o.kind, WorkerOutcome::Kind::Ok);
    EXPECT_EQ(o.value.get<int>(), 42);
    EXPECT_EQ(timeLimitText({0, 0}), "no time limit");
    EXPECT_EQ(memoryLimitText({0, 0}), "no memory limit");
}

// The machine's end, not the job's (issue 38): a signal the parent did not send while the job was
// far below its budgets, or the backstop reached with the CPU idle. What the job's own work
// explains (a crash by SIGSEGV, its CPU time or memory used up) stays the job's.
Limits budgets(double cpu, double wall, long memoryMb) {
    Limits l;
    l.cpuSeconds = cpu;
    l.wallSeconds = wall;
    l.memoryMb = memoryMb;
    return l;
}

TEST(WorkerEnd, AKillFromOutsideFarBelowTheBudgetIsTheMachines) {
    const Limits l = budgets(30, 60, 512);
    WorkerOutcome o = runBounded(l, []() -> nlohmann::json {
        ::kill(::getpid(), SIGKILL);  // as an administrator or the OOM killer would
        return nullptr;
    });
    ASSERT_EQ(o.kind, WorkerOutcome::Kind::Crash);
    const std::string why = machineEvidence(o, l);
    EXPECT_NE(why.find("killed by SIGKILL, a signal the grader did not send"), std::string::npos)
        << why;
    EXPECT_NE(why.find("s of CPU time (budget: 30 s of CPU time)"), std::string::npos) << why;
}

TEST(WorkerEnd, AStoppedWorkerAtTheBackstopIsTheMachines) {
    const Limits l = budgets(30, 1, 512);
    WorkerOutcome o = runBounded(l, []() -> nlohmann::json {
        ::raise(SIGSTOP);
        return nullptr;
    });
    ASSERT_EQ(o.kind, WorkerOutcome::Kind::Timeout);
    EXPECT_TRUE(o.overWallClock);
    const std::string why = machineEvidence(o, l);
    EXPECT_NE(why.find("stopped or starved"), std::string::npos) << why;
}

TEST(WorkerEnd, WhatTheJobDidStaysTheJobs) {
    const Limits l = budgets(30, 60, 512);
    WorkerOutcome crash = runBounded(l, []() -> nlohmann::json {
        ::signal(SIGSEGV, SIG_DFL);
        ::raise(SIGSEGV);
        return nullptr;
    });
    ASSERT_EQ(crash.kind, WorkerOutcome::Kind::Crash);
    EXPECT_EQ(machineEvidence(crash, l), "");
    const Limits tight = budgets(0.4, 60, 512);
    WorkerOutcome spin = runBounded(tight, [] {
        for (volatile unsigned long k = 0;; k = k + 1) {
        }
        return nlohmann::json();
    });
    ASSERT_EQ(spin.kind, WorkerOutcome::Kind::Timeout);
    EXPECT_EQ(machineEvidence(spin, tight), "");
    // The backstop reached while working: CPU time spent, the job's.
    const Limits shortWall = budgets(1.2, 0.8, 512);
    WorkerOutcome busy = runBounded(shortWall, [] {
        for (volatile unsigned long k = 0;; k = k + 1) {
        }
        return nlohmann::json();
    });
    ASSERT_EQ(busy.kind, WorkerOutcome::Kind::Timeout);
    if (busy.overWallClock && busy.cpuSeconds >= 0.6)  // a loaded machine may starve it: then not
        EXPECT_EQ(machineEvidence(busy, shortWall), "");
}

// Issue 39: Mesa's disk-cache thread runs at the lowest priority. A worker whose last thread out
// is that one frees the worker's memory at that priority: beside a busy core its end took
// seconds, and the job's parent waited. Here a job leaves a thread like it (SCHED_IDLE, all
// signals blocked, on a core this test keeps busy) and 128 MB of touched memory: the worker is
// reaped soon after its reply (0.2 s; with an _exit, 13-16 s).
TEST(WorkerEnd, ALowPriorityThreadDoesNotHoldUpTheWorkersEnd) {
    cpu_set_t mine;
    ASSERT_EQ(::sched_getaffinity(0, sizeof mine, &mine), 0);
    int core = 0;
    while (!CPU_ISSET(core, &mine)) ++core;
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(core, &one);
    std::atomic<bool> stop{false};
    std::thread busy([&] {
        ::sched_setaffinity(0, sizeof one, &one);
        while (!stop) {
        }
    });
    std::chrono::steady_clock::time_point replied;
    WorkerOutcome outcome;
    runBoundedSeries(
        limits(30, 1024), 1,
        [one](std::size_t) -> nlohmann::json {
            const std::size_t size = 128u << 20;
            void* block =
                ::mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
            if (block == MAP_FAILED) return "mmap failed";
            volatile char* touch = static_cast<char*>(block);
            for (std::size_t i = 0; i < size; i += 4096) touch[i] = 'x';
            std::atomic<bool> lowered{false};
            std::thread([&lowered, one] {
                sigset_t all;
                ::sigfillset(&all);
                ::pthread_sigmask(SIG_BLOCK, &all, nullptr);
                ::sched_setaffinity(0, sizeof one, &one);
                struct sched_param none = {};
                ::pthread_setschedparam(::pthread_self(), SCHED_IDLE, &none);
                lowered = true;
                for (;;) ::pause();
            }).detach();
            while (!lowered) ::usleep(1000);
            return "ok";
        },
        [&](std::size_t, const WorkerOutcome& o) {
            outcome = o;
            replied = std::chrono::steady_clock::now();
        });
    const double endAfterReply =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - replied).count();
    stop = true;
    busy.join();
    RecordProperty("seconds_after_reply", std::to_string(endAfterReply));
    ASSERT_EQ(outcome.kind, WorkerOutcome::Kind::Ok) << outcome.detail();
    ASSERT_EQ(outcome.value, "ok");
    EXPECT_LT(endAfterReply, 2.0);
}

#if !defined(__SANITIZE_ADDRESS__)
TEST(WorkerEnd, AKillAfterTakingMostOfItsMemoryIsTheJobs) {
    const Limits l = budgets(30, 60, 256);
    WorkerOutcome o = runBounded(l, []() -> nlohmann::json {
        // Mapped and touched page by page through a volatile pointer: a vector whose bytes are
        // never read back is an allocation GCC 15 may drop (Debian testing: a peak of 2 MB).
        const std::size_t size = 200u << 20;  // resident, within the limit
        void* block =
            ::mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (block == MAP_FAILED) return "mmap failed";
        volatile char* touch = static_cast<char*>(block);
        for (std::size_t i = 0; i < size; i += 4096) touch[i] = 'x';
        ::usleep(300000);             // the parent sees it (every 20 ms)
        ::kill(::getpid(), SIGKILL);  // the OOM killer, for memory it holds
        return size;
    });
    ASSERT_EQ(o.kind, WorkerOutcome::Kind::Crash);
    EXPECT_GE(o.peakMb, 128);
    EXPECT_EQ(machineEvidence(o, l), "");
}
#endif

}  // namespace
}  // namespace sl
