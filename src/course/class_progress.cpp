#include "course/class_progress.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>

#include "io/files.h"

namespace sl {

JobProgress::JobProgress(const std::string& path, const std::vector<GradingPlan>& plans) {
    for (const GradingPlan& plan : plans)
        for (const StagePlan& st : plan.stages)
            if (st.rendered()) total_ += st.rows.size();
    fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    write();
}

JobProgress::~JobProgress() {
    if (fd_ >= 0) ::close(fd_);
}

void JobProgress::stageDone(const GradingPlan& plan, const StageRecord& stage) {
    for (const StagePlan& st : plan.stages)
        if (st.stage == stage.stage && st.tree == stage.tree && st.rendered()) {
            done_ = std::min(total_, done_ + st.rows.size());
            break;
        }
    write();
}

void JobProgress::write() {
    if (fd_ < 0) return;  // no progress file: the lines fall back to nothing worse than no time
    char line[64];
    int n = std::snprintf(line, sizeof line, "%20zu %20zu\n", done_, total_);
    if (n > 0 && ::pwrite(fd_, line, std::size_t(n), 0) < 0) {
        ::close(fd_);
        fd_ = -1;
    }
}

RowsDone readProgress(const std::vector<std::string>& paths) {
    RowsDone sum;
    for (const std::string& p : paths) {
        std::string text;
        if (!readRegularFile(p, 256, text).empty()) continue;
        std::size_t done = 0, total = 0;
        if (std::sscanf(text.c_str(), "%zu %zu", &done, &total) != 2 || done > total) continue;
        sum.done += done;
        sum.total += total;
    }
    return sum;
}

std::optional<double> Pace::timeLeft(double seconds, const RowsDone& rows) {
    if (rows.done == 0 || rows.total == 0) return std::nullopt;
    const double left = double(rows.total - std::min(rows.done, rows.total));
    if (!first_) first_ = std::make_pair(seconds, rows.done);
    const auto [at, done] = *first_;
    if (rows.done > done && seconds > at) return (seconds - at) / double(rows.done - done) * left;
    return seconds / double(rows.done) * left;
}

}  // namespace sl
