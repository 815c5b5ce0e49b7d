// Private temporary folders (the submission's snapshot, the workers' shader cache): made mode
// 0700 under $TMPDIR or /tmp, removed when done, and never left behind by a grading harness's
// kill. SIGTERM, SIGINT and SIGHUP remove them before the process ends as the signal asks; after
// SIGKILL, which nothing can catch, the next PrivateDir of the same name removes them, as their
// name carries the pid of a process that no longer runs.
#pragma once

#include <string>

namespace sl {

class PrivateDir {
  public:
    // Makes "$TMPDIR/<prefix>-<pid>-XXXXXX". Throws std::runtime_error when it cannot.
    explicit PrivateDir(const std::string& prefix = "shadowlab-intake");
    ~PrivateDir();
    PrivateDir(const PrivateDir&) = delete;
    PrivateDir& operator=(const PrivateDir&) = delete;
    const std::string& path() const { return path_; }

  private:
    std::string path_;
    int slot_ = -1;  // its place among the folders a signal removes
};

// Removes `dir` and everything in it without following links ("" or the error).
std::string removeTree(const std::string& dir);

// The folders "<prefix>-<pid>-*" under $TMPDIR or /tmp, owned by this user, whose process no
// longer runs: removed. Returns how many.
int sweepAbandoned(const std::string& prefix);

}  // namespace sl
