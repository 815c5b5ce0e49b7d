#include "class/class_progress.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>

#include "grade/grade_students.h"
#include "io/files.h"

namespace sl {

namespace {

std::string roundViews(std::size_t round, const StagePlan& st) {
    return std::to_string(round) + " " + st.stage + " " + st.tree;
}

}  // namespace

JobProgress::JobProgress(const std::string& path, const std::vector<GradingPlan>& plans)
    : plans_(plans) {
    std::set<std::string> roundViewsPlanned;
    for (std::size_t k = 0; k < plans.size(); ++k)
        for (const StagePlan& st : plans[k].stages) {
            if (!st.rendered()) continue;
            total_ += st.rows.size();
            if (roundViewsPlanned.insert(roundViews(roundOf(k, plans.size()), st)).second)
                total_ += st.rows.size();
        }
    fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0644);
    write();
}

JobProgress::~JobProgress() {
    if (fd_ >= 0) ::close(fd_);
}

const StagePlan* JobProgress::renderedStage(std::size_t k, const std::string& stage,
                                            const std::string& tree) const {
    if (k >= plans_.size()) return nullptr;
    for (const StagePlan& st : plans_[k].stages)
        if (st.stage == stage && st.tree == tree && st.rendered()) return &st;
    return nullptr;
}

void JobProgress::stageDone(std::size_t k, const StageRecord& stage) {
    if (const StagePlan* st = renderedStage(k, stage.stage, stage.tree)) {
        done_ += st->rows.size();
        if (roundViewsDone_.insert(roundViews(roundOf(k, plans_.size()), *st)).second)
            done_ += st->rows.size();
        done_ = std::min(done_, total_);
    }
    write();
}

void JobProgress::write() {
    if (fd_ < 0) return;  // no progress file: the lines fall back to nothing worse than no time
    char line[96];
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

double Pace::Seen::secondsPerRow() const {
    return lastDone > firstDone && lastAt > firstAt
               ? (lastAt - firstAt) / double(lastDone - firstDone)
               : firstAt / double(firstDone);
}

std::optional<double> Pace::timeLeft(double seconds, const std::vector<RowsDone>& jobs) {
    seen_.resize(std::max(seen_.size(), jobs.size()));
    double paces = 0;
    int known = 0;
    for (std::size_t j = 0; j < jobs.size(); ++j) {
        const RowsDone& r = jobs[j];
        if (r.done == 0) continue;
        std::optional<Seen>& s = seen_[j];
        if (!s) s = Seen{seconds, seconds, r.done, r.done, r.done};
        if (r.done > s->lastDone) {
            s->lastAt = seconds;
            s->lastStep = r.done - s->lastDone;
            s->lastDone = r.done;
        }
        paces += s->secondsPerRow();
        ++known;
    }
    if (known == 0) return std::nullopt;
    const double perRow = paces / known;
    double left = 0;
    for (std::size_t j = 0; j < jobs.size(); ++j) {
        const RowsDone& r = jobs[j];
        const std::size_t rowsLeft = r.total - r.done;
        const Seen* s = r.done > 0 && seen_[j] ? &*seen_[j] : nullptr;
        if (!s) {
            if (rowsLeft > 0) left = std::max(left, lag() + perRow * double(rowsLeft));
            continue;
        }
        if (rowsLeft == 0) {  // its last student's record may still be to come
            left = std::max(left, lag() - (seconds - s->lastAt));
            continue;
        }
        // The step under way has had the time since the last reading with more rows; the rows
        // after it have had none.
        const double after = perRow * double(rowsLeft - std::min(rowsLeft, s->lastStep));
        left = std::max(left,
                        lag() + std::max(after, perRow * double(rowsLeft) - (seconds - s->lastAt)));
    }
    return left;
}

void Pace::recordBack(double seconds, std::size_t job) {
    if (job >= seen_.size() || !seen_[job]) return;
    lagSum_ += seconds - seen_[job]->lastAt;
    ++lags_;
}

// The mean: a record is seen at the poll its rows were or at a later one (0 or a poll's interval
// or more, each student), and the mean of those is the time between them, the polls' phase
// averaged out.
double Pace::lag() const {
    return lags_ > 0 ? lagSum_ / double(lags_) : 0;
}

}  // namespace sl
