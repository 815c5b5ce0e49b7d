// The box this process runs in: the memory and CPUs a container or a shared grader really
// gives it, which /proc/meminfo and nproc do not tell (Gradescope's default is 768 MB; a job
// pinned to one core still sees every core). Defaults follow it: the worker's memory limit,
// llvmpipe's threads, the reference tracer's threads, the core count printed.
// The parsers are plain functions over the files' text, so tests need no cgroup.
#pragma once

#include <optional>
#include <string>

namespace sl {

// The cgroup path of this process from /proc/self/cgroup's text: v2's "0::PATH" line when
// `controller` is empty, else the v1 line naming it ("4:memory:/a/b", "2:cpu,cpuacct:/a").
std::optional<std::string> cgroupPath(const std::string& procSelfCgroup,
                                      const std::string& controller);

// Where a cgroup hierarchy is mounted, from /proc/self/mountinfo's text: the v2 one when
// `controller` is empty, else the v1 one carrying that controller. `root` is the mount's root
// within the hierarchy (a container may see only its own subtree).
struct CgroupMount {
    std::string point, root;
};
std::optional<CgroupMount> cgroupMount(const std::string& mountinfo, const std::string& controller);

// memory.max (v2) or memory.limit_in_bytes (v1) in bytes; none for "max" or v1's "unlimited"
// (a page-rounded 2^63).
std::optional<long long> parseMemoryLimit(const std::string& text);
// Cores a quota allows: v2's cpu.max "QUOTA PERIOD" ("max PERIOD": none); v1's
// cpu.cfs_quota_us (-1: none) over cpu.cfs_period_us.
std::optional<double> parseCpuMax(const std::string& text);
std::optional<double> parseCpuQuotaV1(const std::string& quota, const std::string& period);

// The default address-space limit of one worker: `fallbackMb`, or less where the box is
// smaller. A cgroup's memory is shared with the parent process (it keeps room for it, a
// quarter and at least 256 MB); an address-space rlimit (ulimit -v) is per process.
long defaultMemoryMb(std::optional<long long> cgroupBytes,
                     std::optional<long long> addressSpaceBytes, long fallbackMb);
// Cores to use: the affinity mask's count, fewer under a quota (rounded up), at least one.
int usableCores(int affinityCores, std::optional<double> quotaCores);

struct Box {
    std::optional<long long> memoryBytes;        // the tightest memory limit up the cgroup tree
    std::optional<long long> addressSpaceBytes;  // RLIMIT_AS, the soft one
    int affinityCores = 1;                       // sched_getaffinity
    std::optional<double> quotaCores;            // the tightest CPU quota up the cgroup tree
};
// Reads /proc/self/cgroup, /proc/self/mountinfo, the cgroup files, the rlimit and the affinity.
Box readBox();

// Parallel jobs a box holds: one a core, fewer where the memory (the box's limit, else the
// machine's) would not give each `perJobMb`; at least one.
int jobsFor(int cores, std::optional<long long> memoryBytes, long perJobMb);

int boxCores();  // usableCores of readBox(), capped by shareCores
// jobsFor this box: its cores, and its memory (the cgroup's limit, else the machine's).
int boxJobs(long perJobMb);
// This process and what it starts use at most `cores` of the box from now on (a job of a
// class's share): boxCores() says so, and llvmpipe's threads follow (LP_NUM_THREADS) unless
// the user set them.
void shareCores(int cores);
long boxDefaultMemoryMb(long fallbackMb);  // defaultMemoryMb of readBox()
// Sets LP_NUM_THREADS to boxCores() where the box has fewer cores than the machine, unless
// the caller set it: llvmpipe otherwise starts a thread per online CPU.
void applyBoxThreads();

}  // namespace sl
