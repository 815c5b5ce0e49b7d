#include "sandbox/private_dir.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace sl {

namespace {

std::string privateTemp() {
    const char* t = std::getenv("TMPDIR");
    return t && *t ? t : "/tmp";
}

// The folders a signal removes: fixed storage, as a signal handler may not allocate.
constexpr int kSlots = 16;
constexpr std::size_t kPathMax = 4096;
char registered[kSlots][kPathMax];
std::atomic<bool> inUse[kSlots];
pid_t owner = 0;  // the process that made them (a forked worker inherits the handler, not them)

// Everything under the open folder `dir` (then closed), with system calls only: safe in a
// signal handler. Links are removed, never followed.
void emptyAndClose(int dir) {
    alignas(8) char buffer[4096];
    for (bool removed = true; removed;) {  // until a pass from the start removes nothing more
        removed = false;
        long n = ::syscall(SYS_getdents64, dir, buffer, sizeof buffer);
        if (n <= 0) break;
        for (long at = 0; at < n;) {
            struct Entry {
                ino64_t ino;
                off64_t off;
                unsigned short reclen;
                unsigned char type;
                char name[1];
            };
            const Entry* e = reinterpret_cast<const Entry*>(buffer + at);
            at += e->reclen;
            const char* name = e->name;
            if (name[0] == '.' && (name[1] == 0 || (name[1] == '.' && name[2] == 0))) continue;
            if (::unlinkat(dir, name, 0) == 0) {
                removed = true;
                continue;
            }
            int sub = ::openat(dir, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
            if (sub >= 0) emptyAndClose(sub);
            if (::unlinkat(dir, name, AT_REMOVEDIR) == 0) removed = true;
        }
        ::lseek(dir, 0, SEEK_SET);  // entries removed while reading: read again until empty
    }
    ::close(dir);
}

void removeRegistered(int sig) {
    if (::getpid() == owner)
        for (int k = 0; k < kSlots; ++k)
            if (inUse[k].load()) {
                int dir = ::open(registered[k], O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
                if (dir >= 0) emptyAndClose(dir);
                ::rmdir(registered[k]);
            }
    ::signal(sig, SIG_DFL);  // then end as the signal asks (the exit status says which)
    ::raise(sig);
}

void installHandlers() {
    static bool done = false;
    if (done) return;
    done = true;
    owner = ::getpid();
    for (int sig : {SIGTERM, SIGINT, SIGHUP}) {
        struct sigaction old {};
        ::sigaction(sig, nullptr, &old);
        if (old.sa_handler != SIG_DFL) continue;  // ignored (a background job's SIGINT) or taken
        struct sigaction act {};
        act.sa_handler = removeRegistered;
        sigemptyset(&act.sa_mask);
        ::sigaction(sig, &act, nullptr);
    }
}

}  // namespace

PrivateDir::PrivateDir(const std::string& prefix) {
    sweepAbandoned(prefix);
    installHandlers();
    std::string pattern =
        privateTemp() + "/" + prefix + "-" + std::to_string(::getpid()) + "-XXXXXX";
    std::vector<char> buf(pattern.begin(), pattern.end());
    buf.push_back('\0');
    if (!::mkdtemp(buf.data()))  // mode 0700: no other user reads or plants anything here
        throw std::runtime_error("cannot make a private folder in " + privateTemp() + ": " +
                                 std::strerror(errno));
    path_ = buf.data();
    if (path_.size() >= kPathMax) return;  // not removed by a signal; the next sweep does
    if (owner != ::getpid()) return;  // made in a forked worker: the signal handler is the parent's
    for (int k = 0; k < kSlots && slot_ < 0; ++k) {
        bool expected = false;
        if (!inUse[k].compare_exchange_strong(expected, true)) continue;
        registered[k][0] = '\0';  // (a signal in between finds nothing to remove here)
        std::memcpy(registered[k] + 1, path_.c_str() + 1, path_.size());
        registered[k][0] = path_[0];
        slot_ = k;
    }
}

PrivateDir::~PrivateDir() {
    if (slot_ >= 0) inUse[slot_].store(false);
    removeTree(path_);
}

std::string removeTree(const std::string& dir) {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);  // removes links themselves, never their targets
    return ec ? ec.message() : "";
}

int sweepAbandoned(const std::string& prefix) {
    namespace fs = std::filesystem;
    const std::string start = prefix + "-";
    int removed = 0;
    std::error_code ec;
    for (fs::directory_iterator it(privateTemp(), ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.compare(0, start.size(), start) != 0) continue;
        char* after = nullptr;
        const long pid = std::strtol(name.c_str() + start.size(), &after, 10);
        if (pid <= 0 || !after || *after != '-') continue;  // not "<prefix>-<pid>-XXXXXX"
        struct stat st {};
        if (::lstat(it->path().c_str(), &st) != 0 || !S_ISDIR(st.st_mode) ||
            st.st_uid != ::getuid())
            continue;
        if (::kill(pid_t(pid), 0) == 0 || errno != ESRCH) continue;  // its process still runs
        if (removeTree(it->path().string()).empty()) ++removed;
    }
    return removed;
}

}  // namespace sl
