// Notices edited shader files for the window's hot reload, debounced: a change counts once the
// folders have stayed the same (every file's size and modification time) for `settle` (a
// second while some file is empty: a save caught between truncating and writing), so an
// editor's or `cp`'s half-written file is never compiled.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

namespace sl {

class ShaderWatch {
  public:
    using Clock = std::chrono::steady_clock;
    // `folders`: our tree and the student's overlay (bounded walk: a few levels, a few thousand
    // files, so a huge overlay cannot stall the window).
    explicit ShaderWatch(std::vector<std::string> folders,
                         std::chrono::milliseconds settle = std::chrono::milliseconds(250));

    // Call a few times a second: true once per settled change.
    bool poll(Clock::time_point now);
    // True while a change has been seen but has not settled yet.
    bool pending() const { return pending_; }
    // The folders' state now (names, sizes, times), and the file modified last when it was taken.
    std::uint64_t current() { return fingerprint(); }
    const std::string& newestFile() const { return newest_; }

  private:
    std::uint64_t fingerprint();  // also counts the empty files

    std::vector<std::string> folders_;
    std::chrono::milliseconds settle_;
    int empty_ = 0;  // empty files in the last fingerprint (set by it: declared before last_)
    std::string newest_;
    std::uint64_t last_;
    Clock::time_point changedAt_{};
    bool pending_ = false;
};

}  // namespace sl
