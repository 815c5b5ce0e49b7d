// Jobs fanned out as child processes: grading a class and checking the solution both deal their
// work over the box's cores this way. Each job is forked from a parent that holds no GL context,
// gets its share of the cores, dies with the parent (PR_SET_PDEATHSIG: a killed grade leaves no
// job behind) and ends with the exit code its body returns.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <functional>
#include <string>
#include <vector>

namespace sl {

class JobFanOut {
  public:
    // Starts `count` jobs; job j runs body(j) with `coresEach` cores and exits with what it
    // returns. An exception out of the body is a line on stderr naming `what` and exit 3. The
    // parent's streams are flushed first, so no buffered line is written twice.
    JobFanOut(int count, int coresEach, const std::string& what,
              const std::function<int(int job)>& body);
    ~JobFanOut();  // jobs still running are killed and reaped
    JobFanOut(const JobFanOut&) = delete;
    JobFanOut& operator=(const JobFanOut&) = delete;

    struct Ended {
        int job;
        int code;  // the exit code; 128 + the signal for a job killed by one
    };
    // Jobs that ended since the last call, waiting up to `wait` for the first of them.
    std::vector<Ended> reap(std::chrono::milliseconds wait);
    // Every job's end, in the order they started.
    std::vector<Ended> waitAll();
    bool running() const { return running_ > 0; }

  private:
    std::vector<pid_t> pids_;  // -1 once reaped
    int running_ = 0;
};

}  // namespace sl
