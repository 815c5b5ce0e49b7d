#include "class/class_progress.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "grade/grade_students.h"
#include "io/files.h"

namespace sl {

namespace {

// A job's file: a line of 105 bytes, and one of about 100 a stage.
constexpr std::size_t kProgressBytes = 64 * 1024;

std::string roundViews(std::size_t round, const StagePlan& st) {
    return std::to_string(round) + " " + st.stage + " " + st.tree;
}

std::string stageKey(const StagePlan& st) {
    return st.stage + "/" + st.tree;
}

const StageRows* stageOf(const std::vector<StageRows>& stages, const std::string& key) {
    for (const StageRows& s : stages)
        if (s.key == key) return &s;
    return nullptr;
}

}  // namespace

JobProgress::JobProgress(const std::string& path, const std::vector<GradingPlan>& plans,
                         const std::vector<StageStep>& order)
    : plans_(plans), order_(order), stepDone_(order.size(), false) {
    std::set<std::string> roundViewsPlanned;
    // What gradeStudents renders: nothing of a hand-in that could not be read.
    for (const StageStep& step : order) {
        const StagePlan& st = plans[step.student].stages[step.stage];
        Counts& c = stages_[stageKey(st)];
        c.total += st.rows.size();
        if (roundViewsPlanned.insert(roundViews(roundOf(step.student, plans.size()), st)).second)
            c.viewsTotal += st.rows.size();
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

bool JobProgress::roundViewsLeft(std::size_t k, const StagePlan& st) const {
    return !roundViewsDone_.count(roundViews(roundOf(k, plans_.size()), st));
}

void JobProgress::stageDone(std::size_t k, const StageRecord& stage) {
    if (const StagePlan* st = renderedStage(k, stage.stage, stage.tree)) {
        Counts& c = stages_[stageKey(*st)];
        c.done = std::min(c.total, c.done + st->rows.size());  // never more than planned
        if (roundViewsDone_.insert(roundViews(roundOf(k, plans_.size()), *st)).second)
            c.viewsDone = std::min(c.viewsTotal, c.viewsDone + st->rows.size());
        for (std::size_t i = underway_; i < order_.size(); ++i)
            if (order_[i].student == k && &plans_[k].stages[order_[i].stage] == st) {
                stepDone_[i] = true;  // a student's stage is one step of the order
                break;
            }
        while (underway_ < order_.size() && stepDone_[underway_]) ++underway_;
    }
    write();
}

// The same length at every write (fixed-width numbers, the same stages), at offset 0: a reader
// sees one whole version or the other.
void JobProgress::write() {
    if (fd_ < 0) return;  // no progress file: the lines fall back to nothing worse than no time
    std::size_t done = 0, total = 0, rows = 0, views = 0, stage = stages_.size();
    for (const auto& [key, c] : stages_) {
        done += c.done + c.viewsDone;
        total += c.total + c.viewsTotal;
    }
    if (underway_ < order_.size()) {
        const StageStep& step = order_[underway_];
        const StagePlan& st = plans_[step.student].stages[step.stage];
        rows = st.rows.size();
        views = roundViewsLeft(step.student, st) ? rows : 0;
        stage = std::size_t(std::distance(stages_.begin(), stages_.find(stageKey(st))));
    }
    char line[160];
    std::snprintf(line, sizeof line, "%20zu %20zu %20zu %20zu %20zu\n", done, total, rows, views,
                  stage);
    std::string text = line;
    for (const auto& [key, c] : stages_) {
        std::snprintf(line, sizeof line, "%20zu %20zu %20zu %20zu ", c.done, c.total, c.viewsDone,
                      c.viewsTotal);
        text += line + key + "\n";
    }
    if (::pwrite(fd_, text.data(), text.size(), 0) < 0) {
        ::close(fd_);
        fd_ = -1;
    }
}

std::vector<RowsDone> readProgress(const std::vector<std::string>& paths) {
    std::vector<RowsDone> jobs(paths.size());
    for (std::size_t j = 0; j < paths.size(); ++j) {
        std::string text;
        if (!readRegularFile(paths[j], kProgressBytes, text).empty()) continue;
        std::istringstream in(text);
        RowsDone r;
        std::size_t stage = 0;
        if (!(in >> r.done >> r.total >> r.underwayRows >> r.underwayViews >> stage) ||
            r.done > r.total)
            continue;
        StageRows st;
        std::size_t done = 0, total = 0;
        while (in >> st.done >> st.total >> st.viewsDone >> st.viewsTotal >> st.key &&
               st.done <= st.total && st.viewsDone <= st.viewsTotal) {
            done += st.done + st.viewsDone;
            total += st.total + st.viewsTotal;
            r.stages.push_back(st);
        }
        const bool summed = r.stages.empty() || (done == r.done && total == r.total);
        if (!in.eof() || !summed) continue;  // torn or foreign: counts nothing
        if (stage < r.stages.size())
            r.underwayKey = r.stages[stage].key;
        else
            r.underwayRows = r.underwayViews = 0;
        jobs[j] = std::move(r);
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
        if (!s) s = Seen{seconds, seconds, r.done, r.done, r.done, r.stages};
        if (r.done > s->lastDone) {
            timeSteps(*s, seconds, r);
            s->lastAt = seconds;
            s->lastStep = r.done - s->lastDone;
            s->lastDone = r.done;
            s->lastStages = r.stages;
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
        const bool priceable = !r.stages.empty() && timedRows_ > 0 && timedSeconds_ > 0;
        const double need = priceable ? secondsLeft(r) : perRow * double(rowsLeft);
        const Seen* s = r.done > 0 && seen_[j] ? &*seen_[j] : nullptr;
        if (!s) {
            if (rowsLeft > 0) left = std::max(left, lag() + need);
            continue;
        }
        if (rowsLeft == 0) {  // its last student's record may still be to come
            left = std::max(left, lag() - (seconds - s->lastAt));
            continue;
        }
        // The step under way has had the time since the last reading with more rows; the rows
        // after it have had none. A file that does not say the step: as many rows as the last,
        // at the rows left's mean price.
        const double step = priceable && r.underwayRows > 0
                                ? priced(r.underwayKey, r.underwayRows, r.underwayViews)
                                : need * double(std::min(rowsLeft, s->lastStep)) / double(rowsLeft);
        const double after = std::max(0.0, need - step);
        left = std::max(left, lag() + std::max(after, need - (seconds - s->lastAt)));
    }
    return left + medianRead() * double(outputReads_);
}

// The time from `before` (the job's last reading with more rows) to now goes to the stages whose
// rows came, shared by their rows; a stage's share to its steps with views if views came. A
// job's first step of a stage also measures our shaders on its cases (the calibration of its
// budgets, grade/stage_runs.h): 1.4 times a step of the next round in the recorded runs. It is
// not timed: no step after it costs that.
void Pace::timeSteps(const Seen& before, double seconds, const RowsDone& now) {
    const double step = seconds - before.lastAt, rows = double(now.done - before.lastDone);
    for (const StageRows& st : now.stages) {
        const StageRows* was = stageOf(before.lastStages, st.key);
        const bool first = !was || was->done + was->viewsDone == 0;
        const std::size_t added = st.done - (was ? std::min(was->done, st.done) : 0),
                          views = st.viewsDone - (was ? std::min(was->viewsDone, st.viewsDone) : 0);
        if (added + views == 0 || first) continue;
        StageCost& cost = stageCost_[st.key];
        const double share = step * double(added + views) / rows;
        if (views > 0) {
            cost.viewsSeconds += share;
            cost.viewsStepRows += double(added);
            cost.views += double(views);
        } else {
            cost.plainSeconds += share;
            cost.plainRows += double(added);
        }
        timedSeconds_ += share;
        timedRows_ += double(added + views);
    }
}

// A stage's student row and view: from its steps without views and with; a stage with steps with
// views only at the views' cost against a row on the stages timed both ways (none: a row's).
Pace::Prices Pace::prices(const StageCost& c) const {
    if (c.plainRows > 0) {
        const double row = c.plainSeconds / c.plainRows;
        return {row, c.views > 0 ? std::max(0.0, c.viewsSeconds - row * c.viewsStepRows) / c.views
                                 : row};
    }
    const double viewAsRows = viewsAgainstRows();
    const double row = c.viewsSeconds / (c.viewsStepRows + viewAsRows * c.views);
    return {row, viewAsRows * row};
}

double Pace::viewsAgainstRows() const {
    double views = 0, asRows = 0;
    for (const auto& [key, c] : stageCost_) {
        if (c.plainRows <= 0 || c.views <= 0) continue;
        const double row = c.plainSeconds / c.plainRows;
        views += std::max(0.0, c.viewsSeconds - row * c.viewsStepRows);
        asRows += row * c.views;
    }
    return asRows > 0 ? views / asRows : 1;
}

double Pace::meanRow() const {
    return timedRows_ > 0 && timedSeconds_ > 0 ? timedSeconds_ / timedRows_ : 1;
}

// The seconds `rows` of a stage's students' rows and `views` of its views' took so far (at the
// mean row where the stage is not timed yet).
double Pace::priced(const std::string& key, std::size_t rows, std::size_t views) const {
    auto cost = stageCost_.find(key);
    if (cost == stageCost_.end()) return meanRow() * double(rows + views);
    const Prices p = prices(cost->second);
    return p.row * double(rows) + p.view * double(views);
}

// Each stage's rows and views left at their prices.
double Pace::secondsLeft(const RowsDone& r) const {
    double seconds = 0;
    for (const StageRows& st : r.stages)
        seconds += priced(st.key, st.total - st.done, st.viewsTotal - st.viewsDone);
    return seconds;
}

void Pace::recordBack(double seconds, std::size_t job, double read) {
    if (job >= seen_.size() || !seen_[job]) return;
    lagSum_ += seconds - seen_[job]->lastAt;
    reads_.push_back(read);
}

// The median, not the mean: a run's first read took 0.07-0.1 s and the others 0.01-0.04 (the
// files not yet cached). At the second-to-last line of 13 busy all-stage runs (8 records) the
// mean put the outputs 0.07 s long on average (0.18 at most), the median 0.04 off on average
// (0.16 short at most).
double Pace::medianRead() const {
    if (reads_.empty()) return 0;
    std::vector<double> sorted = reads_;
    std::sort(sorted.begin(), sorted.end());
    const std::size_t mid = sorted.size() / 2;
    return sorted.size() % 2 == 1 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
}

double timeLeftWhenSaid(double estimate, double estimatedAt, double said) {
    return std::max(0.0, estimate - std::max(0.0, said - estimatedAt));
}

// The mean: a record is seen at the poll its rows were or at a later one (0 or a poll's interval
// or more, each student), and the mean of those is the time between them, the polls' phase
// averaged out.
double Pace::lag() const {
    return reads_.empty() ? 0 : lagSum_ / double(reads_.size());
}

}  // namespace sl
