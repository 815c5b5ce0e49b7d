#include "window/shader_watch.h"

#include <dirent.h>
#include <sys/stat.h>

#include <algorithm>

namespace sl {

namespace {

constexpr int kMaxDepth = 4;
constexpr int kMaxEntries = 4000;
constexpr std::chrono::milliseconds kEmptySettle(1000);

// FNV-1a of a file's size and modification time.
std::uint64_t stampOf(const struct stat& st) {
    const long long stamp[3] = {static_cast<long long>(st.st_size),
                                static_cast<long long>(st.st_mtim.tv_sec),
                                static_cast<long long>(st.st_mtim.tv_nsec)};
    std::uint64_t h = 14695981039346656037ULL;
    const auto* p = reinterpret_cast<const unsigned char*>(stamp);
    for (std::size_t i = 0; i < sizeof stamp; ++i) h = (h ^ p[i]) * 1099511628211ULL;
    return h;
}

void walkFolder(const std::string& folder, int depth, int& entries, ShaderWatch::Files& files,
                int& empty) {
    DIR* dir = ::opendir(folder.c_str());
    if (!dir) return;
    while (dirent* e = ::readdir(dir)) {
        if (++entries > kMaxEntries) break;
        std::string name = e->d_name;
        if (name == "." || name == "..") continue;
        std::string path = folder + "/" + name;
        struct stat st;
        if (::lstat(path.c_str(), &st) != 0) continue;
        if (S_ISDIR(st.st_mode)) {
            if (depth < kMaxDepth) walkFolder(path, depth + 1, entries, files, empty);
            continue;
        }
        if (!S_ISREG(st.st_mode) && !S_ISLNK(st.st_mode)) continue;
        if (S_ISLNK(st.st_mode) && ::stat(path.c_str(), &st) != 0) continue;  // dangling link
        empty += st.st_size == 0;
        files[path] = stampOf(st);
    }
    ::closedir(dir);
}

}  // namespace

ShaderWatch::ShaderWatch(std::vector<std::string> folders, std::chrono::milliseconds settle)
    : folders_(std::move(folders)), settle_(settle) {
    last_ = settled_ = walk();
}

ShaderWatch::Files ShaderWatch::walk() {
    Files files;
    int entries = 0, empty = 0;
    for (const auto& f : folders_)
        if (!f.empty()) walkFolder(f, 0, entries, files, empty);
    empty_ = empty;
    return files;
}

bool ShaderWatch::poll(Clock::time_point now) {
    Files current = walk();
    if (current != last_) {  // still changing: wait until it has been quiet for `settle`
        last_ = std::move(current);
        changedAt_ = now;
        pending_ = true;
        return false;
    }
    // An empty file is nearly always a save in progress (truncated, not yet written): it gets
    // longer to be filled before it is compiled and called empty.
    const auto settle = empty_ > 0 ? std::max(settle_, kEmptySettle) : settle_;
    if (pending_ && now - changedAt_ >= settle) {
        pending_ = false;
        settled_ = last_;
        return true;
    }
    return false;
}

void ShaderWatch::settleNow() {
    last_ = settled_ = walk();
    pending_ = false;
}

}  // namespace sl
