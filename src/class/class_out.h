// grade's --out folder: what is refused before anything is written there (a symbolic link at any
// of grade's names), the lock that keeps one run per folder, its sub-folders, and writes that
// are whole or absent (a full disk is the machine's failure, said in one line).
#pragma once

#include <string>

namespace sl {

// grade's own names directly under --out and inside its own folders: a symbolic link at any of
// them would have every log, page and record written (or a job's log truncated) wherever it
// points, so one refuses the run before anything is written (exit 2). Nothing is followed.
void refuseLinksInOut(const std::string& out);

// --out itself (and its parents), then refuseLinksInOut again: the solution check took a while.
void createOut(const std::string& out);
// --out/students, feedback, work and logs, made with mkdir (never through a link: one planted
// since refuseLinksInOut is refused here); under the lock.
void makeOutFolders(const std::string& out);

// `text` written to `path` atomically; a failure throws: DiskFullError for a full disk (exit 3,
// what earlier runs wrote is kept), UsageError otherwise.
void writeOrThrow(const std::string& path, const std::string& text);
[[noreturn]] void throwWriteError(const std::string& err);

// One grade run per --out at a time: an flock held by the run's own process until it ends (its
// jobs let go of their copy, so a killed run frees --out at once), the holder's pid written in
// the lock file for the refusal to name.
class OutLock {
  public:
    explicit OutLock(const std::string& out);
    ~OutLock();
    void closeInJob();  // in a forked job: the lock stays the parent's alone
    OutLock(const OutLock&) = delete;
    OutLock& operator=(const OutLock&) = delete;

  private:
    int fd_ = -1;
};

}  // namespace sl
