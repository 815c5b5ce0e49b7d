#include "class/class_progress.h"

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
    fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0644);
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

std::vector<RowsDone> readProgress(const std::vector<std::string>& paths) {
    std::vector<RowsDone> jobs(paths.size());
    for (std::size_t j = 0; j < paths.size(); ++j) {
        std::string text;
        if (!readRegularFile(paths[j], 256, text).empty()) continue;
        std::size_t done = 0, total = 0;
        if (std::sscanf(text.c_str(), "%zu %zu", &done, &total) != 2 || done > total) continue;
        jobs[j] = {done, total};
    }
    return jobs;
}

std::optional<double> Pace::timeLeft(double seconds, const std::vector<RowsDone>& jobs) {
    first_.resize(std::max(first_.size(), jobs.size()));
    std::vector<std::optional<double>> perRow(jobs.size());  // seconds a row, by job
    double rates = 0;
    int known = 0;
    for (std::size_t j = 0; j < jobs.size(); ++j) {
        const RowsDone& r = jobs[j];
        if (r.done == 0) continue;
        if (!first_[j]) first_[j] = std::make_pair(seconds, r.done);
        const auto [at, done] = *first_[j];
        perRow[j] = r.done > done && seconds > at ? (seconds - at) / double(r.done - done)
                                                  : seconds / double(r.done);
        rates += *perRow[j];
        ++known;
    }
    if (known == 0) return std::nullopt;
    double left = 0;
    for (std::size_t j = 0; j < jobs.size(); ++j) {
        const double rate = perRow[j] ? *perRow[j] : rates / known;
        left = std::max(left, rate * double(jobs[j].total - jobs[j].done));
    }
    return left;
}

}  // namespace sl
