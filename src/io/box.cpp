#include "io/box.h"

#include <sched.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

namespace sl {

namespace {

std::vector<std::string> words(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

std::vector<std::string> split(const std::string& text, char sep) {
    std::vector<std::string> out;
    std::string part;
    std::istringstream in(text);
    while (std::getline(in, part, sep)) out.push_back(part);
    return out;
}

std::optional<long long> number(const std::string& text) {
    std::vector<std::string> w = words(text);
    if (w.size() != 1) return std::nullopt;
    char* end = nullptr;
    errno = 0;
    long long v = std::strtoll(w[0].c_str(), &end, 10);
    if (errno != 0 || *end != '\0') return std::nullopt;
    return v;
}

std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

template <typename T>
void keepSmaller(std::optional<T>& best, std::optional<T> v) {
    if (v && (!best || *v < *best)) best = v;
}

// The tightest of `file`'s limits from this process's cgroup up to the mount's root: a parent's
// limit binds its children too.
template <typename T, typename Parse>
std::optional<T> tightestUpTheTree(const std::string& procCgroup, const std::string& mountinfo,
                                   const std::string& controller, const Parse& parse) {
    std::optional<std::string> path = cgroupPath(procCgroup, controller);
    std::optional<CgroupMount> mount = cgroupMount(mountinfo, controller);
    if (!path || !mount) return std::nullopt;
    std::string rel = *path;
    if (mount->root != "/" && rel.compare(0, mount->root.size(), mount->root) == 0)
        rel = rel.substr(mount->root.size());
    std::optional<T> best;
    for (;;) {
        keepSmaller(best, parse(mount->point + (rel == "/" ? "" : rel)));
        if (rel.empty() || rel == "/") break;
        std::size_t slash = rel.rfind('/');
        rel = slash == 0 || slash == std::string::npos ? "/" : rel.substr(0, slash);
    }
    return best;
}

}  // namespace

std::optional<std::string> cgroupPath(const std::string& procSelfCgroup,
                                      const std::string& controller) {
    std::istringstream in(procSelfCgroup);
    for (std::string line; std::getline(in, line);) {
        std::size_t a = line.find(':'), b = line.find(':', a + 1);
        if (a == std::string::npos || b == std::string::npos) continue;
        std::string id = line.substr(0, a), list = line.substr(a + 1, b - a - 1);
        if (controller.empty() ? id == "0" && list.empty() : id != "0" && [&] {
                std::vector<std::string> c = split(list, ',');
                return std::find(c.begin(), c.end(), controller) != c.end();
            }())
            return line.substr(b + 1);
    }
    return std::nullopt;
}

std::optional<CgroupMount> cgroupMount(const std::string& mountinfo,
                                       const std::string& controller) {
    std::istringstream in(mountinfo);
    for (std::string line; std::getline(in, line);) {
        // ID PARENT MAJ:MIN ROOT POINT OPTIONS [OPTIONAL...] - FSTYPE SOURCE SUPEROPTIONS
        std::vector<std::string> w = words(line);
        auto dash = std::find(w.begin(), w.end(), "-");
        if (w.size() < 5 || dash == w.end() || w.end() - dash < 4) continue;
        const std::string& type = dash[1];
        bool match = controller.empty() ? type == "cgroup2" : type == "cgroup" && [&] {
            std::vector<std::string> o = split(dash[3], ',');
            return std::find(o.begin(), o.end(), controller) != o.end();
        }();
        if (match) return CgroupMount{w[4], w[3]};
    }
    return std::nullopt;
}

std::optional<long long> parseMemoryLimit(const std::string& text) {
    std::optional<long long> v = number(text);
    // v1 writes "no limit" as 2^63 rounded down to a page; nothing real comes near 2^60.
    if (!v || *v <= 0 || *v >= (1LL << 60)) return std::nullopt;
    return v;
}

std::optional<double> parseCpuMax(const std::string& text) {
    std::vector<std::string> w = words(text);
    if (w.size() != 2 || w[0] == "max") return std::nullopt;
    std::optional<long long> quota = number(w[0]), period = number(w[1]);
    if (!quota || !period || *quota <= 0 || *period <= 0) return std::nullopt;
    return double(*quota) / double(*period);
}

std::optional<double> parseCpuQuotaV1(const std::string& quota, const std::string& period) {
    std::optional<long long> q = number(quota), p = number(period);
    if (!q || !p || *q <= 0 || *p <= 0) return std::nullopt;  // -1: no quota
    return double(*q) / double(*p);
}

long defaultMemoryMb(std::optional<long long> cgroupBytes,
                     std::optional<long long> addressSpaceBytes, long fallbackMb) {
    const long long mb = 1024 * 1024;
    long result = fallbackMb;
    if (cgroupBytes) {
        long total = long(*cgroupBytes / mb);
        long room = std::max(256L, total / 4);  // the parent and the page cache live there too
        result = std::min(result, std::max(1L, total - room));
    }
    if (addressSpaceBytes) result = std::min(result, std::max(1L, long(*addressSpaceBytes / mb)));
    return result;
}

int usableCores(int affinityCores, std::optional<double> quotaCores) {
    int n = std::max(1, affinityCores);
    if (quotaCores) n = std::min(n, std::max(1, int(std::ceil(*quotaCores - 1e-9))));
    return n;
}

Box readBox() {
    Box box;
    std::string procCgroup = slurp("/proc/self/cgroup");
    std::string mountinfo = slurp("/proc/self/mountinfo");
    auto memory = [](const std::string& dir) {
        std::optional<long long> v = parseMemoryLimit(slurp(dir + "/memory.max"));
        keepSmaller(v, parseMemoryLimit(slurp(dir + "/memory.limit_in_bytes")));
        return v;
    };
    keepSmaller(box.memoryBytes, tightestUpTheTree<long long>(procCgroup, mountinfo, "", memory));
    keepSmaller(box.memoryBytes,
                tightestUpTheTree<long long>(procCgroup, mountinfo, "memory", memory));
    keepSmaller(box.quotaCores,
                tightestUpTheTree<double>(procCgroup, mountinfo, "", [](const std::string& dir) {
                    return parseCpuMax(slurp(dir + "/cpu.max"));
                }));
    keepSmaller(box.quotaCores,
                tightestUpTheTree<double>(procCgroup, mountinfo, "cpu", [](const std::string& dir) {
                    return parseCpuQuotaV1(slurp(dir + "/cpu.cfs_quota_us"),
                                           slurp(dir + "/cpu.cfs_period_us"));
                }));
    rlimit as{};
    if (::getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY)
        box.addressSpaceBytes = (long long)as.rlim_cur;
#ifdef __EMSCRIPTEN__
    box.affinityCores = 1;  // the browser edition runs on the page's one thread
#else
    cpu_set_t set;
    CPU_ZERO(&set);
    box.affinityCores = ::sched_getaffinity(0, sizeof set, &set) == 0
                            ? CPU_COUNT(&set)
                            : int(std::max(1u, std::thread::hardware_concurrency()));
#endif
    return box;
}

namespace {

int& coreShare() {  // 0: the whole box
    static int share = 0;
    return share;
}

// Whether LP_NUM_THREADS came from the user (applyBoxThreads and shareCores set it otherwise).
bool& threadsFromUser() {
    static bool user = std::getenv("LP_NUM_THREADS") != nullptr;
    return user;
}

}  // namespace

int jobsFor(int cores, std::optional<long long> memoryBytes, long perJobMb) {
    long long byMemory =
        memoryBytes && perJobMb > 0 ? *memoryBytes / (perJobMb * 1048576LL) : cores;
    return int(std::max<long long>(1, std::min<long long>(cores, byMemory)));
}

int boxCores() {
    static const int cores = [] {  // the affinity and the quota do not change while we run
        Box box = readBox();
        return usableCores(box.affinityCores, box.quotaCores);
    }();
    return coreShare() > 0 ? std::min(cores, coreShare()) : cores;
}

int boxJobs(long perJobMb) {
    std::optional<long long> memory = readBox().memoryBytes;
    const long pages = ::sysconf(_SC_PHYS_PAGES), size = ::sysconf(_SC_PAGESIZE);
    if (!memory && pages > 0 && size > 0) memory = (long long)pages * size;
    return jobsFor(boxCores(), memory, perJobMb);
}

void shareCores(int cores) {
    threadsFromUser();  // read before it is set here
    coreShare() = std::max(1, cores);
    if (!threadsFromUser()) ::setenv("LP_NUM_THREADS", std::to_string(boxCores()).c_str(), 1);
}

long boxDefaultMemoryMb(long fallbackMb) {
    Box box = readBox();
    return defaultMemoryMb(box.memoryBytes, box.addressSpaceBytes, fallbackMb);
}

void applyBoxThreads() {
    if (threadsFromUser()) return;
    int cores = boxCores();
    if (cores < int(std::thread::hardware_concurrency()))
        ::setenv("LP_NUM_THREADS", std::to_string(cores).c_str(), 0);
}

}  // namespace sl
