// The box's limits from the text of /proc and cgroup files (src/io/box.h).
#include <gtest/gtest.h>

#include "io/box.h"

namespace sl {
namespace {

const char* kHybrid =  // cgroup v1 controllers beside an empty v2 hierarchy (this CI machine)
    "9:name=systemd:/\n4:memory:/process_api/cd79\n2:cpu,cpuacct:/jobs/a\n0::/\n";

TEST(Box, CgroupPathPicksTheLineOfTheController) {
    EXPECT_EQ(cgroupPath(kHybrid, "memory"), "/process_api/cd79");
    EXPECT_EQ(cgroupPath(kHybrid, "cpu"), "/jobs/a");
    EXPECT_EQ(cgroupPath(kHybrid, "cpuacct"), "/jobs/a");
    EXPECT_EQ(cgroupPath(kHybrid, ""), "/");
    EXPECT_EQ(cgroupPath("0::/user.slice/session-3.scope\n", ""), "/user.slice/session-3.scope");
    EXPECT_FALSE(cgroupPath("0::/a\n", "memory"));
    EXPECT_FALSE(cgroupPath("4:memory:/a\n", ""));
    EXPECT_FALSE(cgroupPath("", ""));
}

TEST(Box, CgroupMountFindsV2AndTheV1ControllerWithTheirRoots) {
    const char* mountinfo =
        "22 27 0:21 / /proc rw,relatime - proc proc rw\n"
        "31 30 0:27 / /sys/fs/cgroup/cpu rw,relatime - cgroup cgroup rw,cpu,cpuacct\n"
        "34 30 0:30 /process_api /sys/fs/cgroup/memory rw,relatime shared:9 - cgroup cgroup "
        "rw,memory\n"
        "40 30 0:36 / /sys/fs/cgroup/unified rw,relatime - cgroup2 cgroup2 rw\n";
    auto v2 = cgroupMount(mountinfo, "");
    ASSERT_TRUE(v2);
    EXPECT_EQ(v2->point, "/sys/fs/cgroup/unified");
    auto memory = cgroupMount(mountinfo, "memory");
    ASSERT_TRUE(memory);
    EXPECT_EQ(memory->point, "/sys/fs/cgroup/memory");
    EXPECT_EQ(memory->root, "/process_api");  // optional fields before "-" are skipped
    EXPECT_EQ(cgroupMount(mountinfo, "cpu")->point, "/sys/fs/cgroup/cpu");
    EXPECT_FALSE(cgroupMount(mountinfo, "pids"));
    EXPECT_FALSE(cgroupMount("22 27 0:21 / /proc rw - proc proc rw\n", ""));
}

TEST(Box, MemoryLimitReadsBytesAndKnowsNoLimit) {
    EXPECT_EQ(parseMemoryLimit("805306368\n"), 805306368LL);  // 768 MB
    EXPECT_FALSE(parseMemoryLimit("max\n"));                  // v2: none
    EXPECT_FALSE(parseMemoryLimit("9223372036854771712\n"));  // v1: none
    EXPECT_FALSE(parseMemoryLimit(""));                       // no such file
    EXPECT_FALSE(parseMemoryLimit("12abc"));
}

TEST(Box, CpuQuotaInCores) {
    EXPECT_DOUBLE_EQ(*parseCpuMax("50000 100000\n"), 0.5);
    EXPECT_DOUBLE_EQ(*parseCpuMax("150000 100000"), 1.5);
    EXPECT_FALSE(parseCpuMax("max 100000\n"));
    EXPECT_FALSE(parseCpuMax(""));
    EXPECT_DOUBLE_EQ(*parseCpuQuotaV1("200000\n", "100000\n"), 2.0);
    EXPECT_FALSE(parseCpuQuotaV1("-1\n", "100000\n"));
}

TEST(Box, DefaultMemoryLeavesTheParentRoomInACgroup) {
    const long long mb = 1024 * 1024;
    EXPECT_EQ(defaultMemoryMb(std::nullopt, std::nullopt, 2048), 2048);
    EXPECT_EQ(defaultMemoryMb(768 * mb, std::nullopt, 2048), 512);  // Gradescope's default
    EXPECT_EQ(defaultMemoryMb(4096 * mb, std::nullopt, 2048), 2048);
    EXPECT_EQ(defaultMemoryMb(2048 * mb, std::nullopt, 2048), 1536);  // a quarter kept
    // ulimit -v binds each process alone: the worker may have all of it.
    EXPECT_EQ(defaultMemoryMb(std::nullopt, 1000 * mb, 2048), 1000);
    EXPECT_EQ(defaultMemoryMb(768 * mb, 600 * mb, 2048), 512);
    EXPECT_EQ(defaultMemoryMb(768 * mb, 400 * mb, 2048), 400);
    EXPECT_GE(defaultMemoryMb(100 * mb, std::nullopt, 2048), 1);  // never 0 (= no limit)
}

TEST(Box, CoresFollowAffinityAndQuota) {
    EXPECT_EQ(usableCores(2, std::nullopt), 2);
    EXPECT_EQ(usableCores(1, std::nullopt), 1);  // taskset -c 0
    EXPECT_EQ(usableCores(8, 2.0), 2);
    EXPECT_EQ(usableCores(8, 1.5), 2);  // a part core still runs a thread
    EXPECT_EQ(usableCores(8, 0.5), 1);
    EXPECT_EQ(usableCores(2, 4.0), 2);
    EXPECT_EQ(usableCores(0, std::nullopt), 1);
}

TEST(Box, ThisProcessSeesAtLeastOneCore) {
    Box box = readBox();
    EXPECT_GE(box.affinityCores, 1);
    EXPECT_GE(boxCores(), 1);
    EXPECT_LE(boxCores(), box.affinityCores);
    EXPECT_GE(boxDefaultMemoryMb(2048), 1);
    EXPECT_LE(boxDefaultMemoryMb(2048), 2048);
}

TEST(Box, JobsOneACoreAsMemoryAllows) {
    const long long mb = 1024 * 1024;
    EXPECT_EQ(jobsFor(2, std::nullopt, 768), 2);
    EXPECT_EQ(jobsFor(16, 64LL * 1024 * mb, 768), 16);
    EXPECT_EQ(jobsFor(16, 4096 * mb, 768), 5);  // the memory, not the cores
    EXPECT_EQ(jobsFor(2, 768 * mb, 768), 1);    // Gradescope's box
    EXPECT_EQ(jobsFor(4, 100 * mb, 768), 1);    // never none
    EXPECT_EQ(jobsFor(0, std::nullopt, 768), 1);
}

TEST(Box, ASharedCoreCountCapsThisProcess) {
    const int all = boxCores();
    shareCores(1);
    EXPECT_EQ(boxCores(), 1);
    shareCores(all + 5);  // more than the box: the box
    EXPECT_EQ(boxCores(), all);
}

}  // namespace
}  // namespace sl
