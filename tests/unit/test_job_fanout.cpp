// Jobs fanned out as processes (sandbox/job_fanout.h): each job's exit code comes back with its
// number, an exception is exit 3 with a line, a job killed by a signal is 128 + the signal, and
// jobs still running when the fan-out is dropped are killed, never left behind.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "sandbox/job_fanout.h"

namespace sl {
namespace {

using namespace std::chrono_literals;

TEST(JobFanOut, EachJobsExitCodeComesBackWithItsNumber) {
    JobFanOut fan(3, 1, "test job", [](int j) { return 10 + j; });
    std::vector<JobFanOut::Ended> ended = fan.waitAll();
    ASSERT_EQ(ended.size(), 3u);
    for (const JobFanOut::Ended& e : ended) EXPECT_EQ(e.code, 10 + e.job);
    EXPECT_FALSE(fan.running());
}

TEST(JobFanOut, AnExceptionIsExit3AndASignalIs128Plus) {
    JobFanOut fan(2, 1, "test job", [](int j) -> int {
        if (j == 0) throw std::runtime_error("broken");
        ::raise(SIGKILL);
        return 0;
    });
    std::vector<JobFanOut::Ended> ended;
    while (fan.running())
        for (const JobFanOut::Ended& e : fan.reap(100ms)) ended.push_back(e);
    ASSERT_EQ(ended.size(), 2u);
    std::sort(ended.begin(), ended.end(), [](auto& a, auto& b) { return a.job < b.job; });
    EXPECT_EQ(ended[0].code, 3);
    EXPECT_EQ(ended[1].code, 128 + SIGKILL);
}

TEST(JobFanOut, ReapWaitsNoLongerThanAsked) {
    JobFanOut fan(1, 1, "test job", [](int) {
        std::this_thread::sleep_for(5s);
        return 0;
    });
    auto start = std::chrono::steady_clock::now();
    EXPECT_TRUE(fan.reap(200ms).empty());
    EXPECT_LT(std::chrono::steady_clock::now() - start, 3s);
    EXPECT_TRUE(fan.running());
}

TEST(JobFanOut, JobsStillRunningAreKilledWhenDropped) {
    int fds[2];
    ASSERT_EQ(::pipe(fds), 0);
    {
        JobFanOut fan(1, 1, "test job", [&](int) {
            pid_t me = ::getpid();
            (void)!::write(fds[1], &me, sizeof me);
            ::pause();
            return 0;
        });
        pid_t job = 0;
        ASSERT_EQ(::read(fds[0], &job, sizeof job), ssize_t(sizeof job));
        ASSERT_EQ(::kill(job, 0), 0);
        ::close(fds[0]);
        ::close(fds[1]);
        // Dropped here: the job must be gone (killed and reaped) after the block.
        fds[0] = job;
    }
    EXPECT_NE(::kill(fds[0], 0), 0);
}

}  // namespace
}  // namespace sl
