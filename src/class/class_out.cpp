#include "class/class_out.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>

#include "io/files.h"
#include "io/usage_error.h"

namespace sl {

void throwWriteError(const std::string& err) {
    if (diskFull(errno))
        throw DiskFullError("grade: the disk is full: " + err +
                            " (what earlier runs wrote is kept): free space and rerun grade");
    throw UsageError("grade: " + err);
}

void writeOrThrow(const std::string& path, const std::string& text) {
    std::string err = writeFileAtomically(path, text.data(), text.size());
    if (!err.empty()) throwWriteError(err);
}

void refuseLinksInOut(const std::string& out) {
    auto refuse = [](const std::string& path) {
        throw UsageError("--out: " + printableName(path) +
                         " is a symbolic link: grade writes nothing through a link (remove it)");
    };
    struct stat st;
    if (::stat(out.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
        return;  // --out itself may be a link
    for (const char* name :
         {".grade.lock", "solution_check.txt", "grades.csv", "gradebook-canvas.csv",
          "gradebook-moodle.csv", "class.html", "adjustments.csv"})
        if (::lstat((out + "/" + name).c_str(), &st) == 0 && S_ISLNK(st.st_mode))
            refuse(out + "/" + name);
    for (const char* name : {"students", "feedback", "work", "logs"}) {
        const std::string folder = out + "/" + name;
        if (::lstat(folder.c_str(), &st) != 0) continue;
        if (S_ISLNK(st.st_mode)) refuse(folder);
        if (!S_ISDIR(st.st_mode))
            throw UsageError("--out: " + printableName(folder) + " is not a folder");
        DIR* dir = ::opendir(folder.c_str());
        if (!dir) throw UsageError("--out: cannot list " + printableName(folder));
        std::string link;
        while (const dirent* e = ::readdir(dir)) {
            const std::string path = folder + "/" + e->d_name;
            if (link.empty() && ::lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode)) link = path;
        }
        ::closedir(dir);
        if (!link.empty()) refuse(link);
    }
}

void createOut(const std::string& out) {
    std::error_code mkdirError;
    std::filesystem::create_directories(out, mkdirError);
    refuseLinksInOut(out);  // again: the solution check took a while
}

void makeOutFolders(const std::string& out) {
    for (const char* sub : {"/students", "/feedback", "/work", "/logs"}) {
        // mkdir, never through a link: one planted since the check above is refused here.
        struct stat made;
        if (::mkdir((out + sub).c_str(), 0755) != 0 && errno != EEXIST)
            throw UsageError("--out: cannot create " + printableName(out + sub));
        if (::lstat((out + sub).c_str(), &made) != 0 || !S_ISDIR(made.st_mode))
            throw UsageError("--out: " + printableName(out + sub) +
                             " is not a folder (a symbolic link is refused: remove it)");
    }
}

OutLock::OutLock(const std::string& out) {
    std::string path = out + "/.grade.lock";
    fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd_ < 0) throw UsageError("--out: cannot write " + printableName(path));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
        char pid[32] = {};
        ssize_t n = ::pread(fd_, pid, sizeof pid - 1, 0);
        ::close(fd_);
        std::string holder = n > 0 ? std::string(pid, std::size_t(n)) : "?";
        holder.erase(holder.find_last_not_of(" \n") + 1);
        throw UsageError("--out: " + printableName(out) + " is in use by another grade run (pid " +
                         printable(holder) + "): wait for it to end or give another --out");
    }
    // The pid is only for another run's message; the lock itself is the flock.
    std::string pid = std::to_string(::getpid()) + "\n";
    if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, pid.data(), pid.size(), 0) < 0)
        pid.clear();  // no pid to name: the lock holds all the same
}

OutLock::~OutLock() {
    ::close(fd_);
}

void OutLock::closeInJob() {
    ::close(fd_);
    fd_ = -1;
}

}  // namespace sl
