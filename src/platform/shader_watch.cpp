#include "platform/shader_watch.h"

#include <dirent.h>
#include <sys/stat.h>

#include <functional>

namespace sl {

namespace {

constexpr int kMaxDepth = 4;
constexpr int kMaxEntries = 4000;

// FNV-1a over the names, sizes and modification times of the files under `folder`.
void hashFolder(const std::string& folder, int depth, int& entries, std::uint64_t& h) {
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
            if (depth < kMaxDepth) hashFolder(path, depth + 1, entries, h);
            continue;
        }
        if (!S_ISREG(st.st_mode) && !S_ISLNK(st.st_mode)) continue;
        if (S_ISLNK(st.st_mode) && ::stat(path.c_str(), &st) != 0) continue;  // dangling link
        mix(path.data(), path.size());
        long long stamp[3] = {static_cast<long long>(st.st_size),
                              static_cast<long long>(st.st_mtim.tv_sec),
                              static_cast<long long>(st.st_mtim.tv_nsec)};
        mix(stamp, sizeof stamp);
    }
    ::closedir(dir);
}

}  // namespace

ShaderWatch::ShaderWatch(std::vector<std::string> folders, std::chrono::milliseconds settle)
    : folders_(std::move(folders)), settle_(settle), last_(fingerprint()) {}

std::uint64_t ShaderWatch::fingerprint() const {
    std::uint64_t h = 14695981039346656037ULL;
    int entries = 0;
    for (const auto& f : folders_) hashFolder(f, 0, entries, h);
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
    if (pending_ && now - changedAt_ >= settle_) {
        pending_ = false;
        return true;
    }
    return false;
}

}  // namespace sl
