// Notices edited shader files for the window's hot reload, debounced: a change counts once the
// folders have stayed the same (every file's size and modification time) for `settle` (a
// second while some file is empty: a save caught between truncating and writing), so an
// editor's or `cp`'s half-written file is never compiled. It also keeps each file's stamp, so
// that the window tries only the stages whose files changed.
#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace sl {

class ShaderWatch {
  public:
    using Clock = std::chrono::steady_clock;
    // A file's size and modification time, hashed.
    using Files = std::map<std::string, std::uint64_t>;
    // `folders`: our trees and the student's overlay (bounded walk: a few levels, a few thousand
    // files, so a huge overlay cannot stall the window).
    explicit ShaderWatch(std::vector<std::string> folders,
                         std::chrono::milliseconds settle = std::chrono::milliseconds(250));

    // Call a few times a second: true once per settled change.
    bool poll(Clock::time_point now);
    // True while a change has been seen but has not settled yet.
    bool pending() const { return pending_; }
    // Every file under the folders (its path as the folder was given, then the relative name)
    // as they were when the last change settled (or at the start).
    const Files& settled() const { return settled_; }
    // Walks the folders now (after `r`: what is on disk, settled or not).
    void settleNow();

  private:
    Files walk();  // also counts the empty files

    std::vector<std::string> folders_;
    std::chrono::milliseconds settle_;
    int empty_ = 0;  // empty files in the last walk
    Files last_, settled_;
    Clock::time_point changedAt_{};
    bool pending_ = false;
};

}  // namespace sl
