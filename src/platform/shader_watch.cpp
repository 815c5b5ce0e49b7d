#include "platform/shader_watch.h"

#include <dirent.h>
#include <sys/stat.h>

#include <algorithm>
#include <functional>

namespace sl {

namespace {

constexpr int kMaxDepth = 4;
constexpr int kMaxEntries = 4000;
constexpr std::chrono::milliseconds kEmptySettle(1000);

// FNV-1a over the names, sizes and modification times of the files under `folder`; `empty`
// counts the files of size 0.
struct Newest {
    std::string path;
    long long seconds = 0, nanos = 0;
};

void hashFolder(const std::string& folder, int depth, int& entries, std::uint64_t& h, int& empty,
                Newest& newest) {
    DIR* dir = ::opendir(folder.c_str());
    if (!dir) return;
    auto mix = [&h](const void* data, std::size_t n) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 1099511628211ULL;
    };
    while (dirent* e = ::readdir(dir)) {
        if (++entries > kMaxEntries) break;
        std::string name = e->d_name;
        if (name == "." || name == "..") continue;
        std::string path = folder + "/" + name;
        struct stat st;
        if (::lstat(path.c_str(), &st) != 0) continue;
        if (S_ISDIR(st.st_mode)) {
            if (depth < kMaxDepth) hashFolder(path, depth + 1, entries, h, empty, newest);
            continue;
        }
        if (!S_ISREG(st.st_mode) && !S_ISLNK(st.st_mode)) continue;
        if (S_ISLNK(st.st_mode) && ::stat(path.c_str(), &st) != 0) continue;  // dangling link
        mix(path.data(), path.size());
        empty += st.st_size == 0;
        long long stamp[3] = {static_cast<long long>(st.st_size),
                              static_cast<long long>(st.st_mtim.tv_sec),
                              static_cast<long long>(st.st_mtim.tv_nsec)};
        mix(stamp, sizeof stamp);
        if (stamp[1] > newest.seconds || (stamp[1] == newest.seconds && stamp[2] > newest.nanos))
            newest = {path, stamp[1], stamp[2]};
    }
    ::closedir(dir);
}

}  // namespace

ShaderWatch::ShaderWatch(std::vector<std::string> folders, std::chrono::milliseconds settle)
    : folders_(std::move(folders)), settle_(settle), last_(fingerprint()) {}

std::uint64_t ShaderWatch::fingerprint() {
    std::uint64_t h = 14695981039346656037ULL;
    int entries = 0, empty = 0;
    Newest newest;
    for (const auto& f : folders_) hashFolder(f, 0, entries, h, empty, newest);
    empty_ = empty;
    newest_ = newest.path;
    return h;
}

bool ShaderWatch::poll(Clock::time_point now) {
    std::uint64_t current = fingerprint();
    if (current != last_) {  // still changing: wait until it has been quiet for `settle`
        last_ = current;
        changedAt_ = now;
        pending_ = true;
        return false;
    }
    // An empty file is nearly always a save in progress (truncated, not yet written): it gets
    // longer to be filled before it is compiled and called empty.
    const auto settle = empty_ > 0 ? std::max(settle_, kEmptySettle) : settle_;
    if (pending_ && now - changedAt_ >= settle) {
        pending_ = false;
        return true;
    }
    return false;
}

}  // namespace sl
