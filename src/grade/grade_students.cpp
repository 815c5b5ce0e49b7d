#include "grade/grade_students.h"

#include <algorithm>
#include <chrono>
#include <optional>

#include "grade/own_check.h"

namespace sl {

// A share's first round: a quarter of it (1 to 8 students). The time left learns what a round's
// views cost only from a step with them after the first round's (that one also calibrates the
// budgets on our shaders, and is not timed: class/class_progress.h), so until the second round's
// first student is back they are priced as rows: for six of the stages they cost 0-0.25 of a
// student's rows (medians of 76 steps each, 19 busy runs), 0.62 for peers.
// In rounds of 2, 3 and 3 (15 all-stage hand-ins on 2 cores) the line after the first round, the
// class's fourth, said 51-52 s with 39 s left in 3 busy runs (issue 39). With the first round a
// quarter of each share, the first rounds' lines are the class's first quarter at most.
std::size_t firstRound(std::size_t n) {
    return std::clamp<std::size_t>(n / 4, 1, 8);
}

std::size_t roundCount(std::size_t n) {
    if (n == 0) return 0;
    const std::size_t rest = n - firstRound(n);
    return 1 + std::max(std::min<std::size_t>(2, rest), (rest + 7) / 8);
}

// After the first round, the rest as even as it goes, the extra students to the earliest rounds:
// the last is never the only round of two or more. A round's first student draws the views of
// each stage; the time left prices them apart from the students' rows once a stage's step
// without them is timed, which a round of one has none of. In rounds of 1, 1 and 2 (4 students a
// job, 8 all-stage hand-ins on 2 cores) the last round came with none timed: its views were
// priced as rows until then, and its last stage's at the other stages' rate.
std::size_t roundStart(std::size_t r, std::size_t n) {
    const std::size_t rounds = roundCount(n);
    if (r == 0 || rounds == 0) return 0;
    if (r >= rounds) return n;
    const std::size_t first = firstRound(n), rest = n - first, later = rounds - 1;
    return first + (r - 1) * (rest / later) + std::min(r - 1, rest % later);
}

std::size_t roundOf(std::size_t k, std::size_t n) {
    const std::size_t rounds = roundCount(n);
    std::size_t r = 0;
    while (r + 1 < rounds && k >= roundStart(r + 1, n)) ++r;
    return r;
}

// The order of the series: students in rounds of a few, and within a round stage by stage, so
// the views a stage renders (up to 7 per stage, 9 for all stages of lab4) are traced and drawn
// with our shaders once per round and stay in the worker's truth cache (8 views,
// Evaluator::maxTruths): student by student the cache lost the all-stage views to each other and
// every student traced them again. A round's students are done together: at least three rounds
// (a share of three or more), at most 8 students a round (roundStart).
std::vector<StageStep> renderOrder(const std::vector<GradingPlan>& plans,
                                   const std::vector<StudentWork>& students) {
    std::size_t stageCount = 0;
    for (const GradingPlan& plan : plans) stageCount = std::max(stageCount, plan.stages.size());
    const std::size_t n = std::min(plans.size(), students.size());
    const std::size_t rounds = roundCount(n);
    std::vector<StageStep> order;
    for (std::size_t r = 0; r < rounds; ++r)
        for (std::size_t j = 0; j < stageCount; ++j)
            for (std::size_t k = roundStart(r, n); k < roundStart(r + 1, n); ++k)
                if (students[k].error.empty() && j < plans[k].stages.size() &&
                    plans[k].stages[j].rendered())
                    order.push_back({k, j});
    return order;
}

void gradeStudents(const std::vector<GradingPlan>& plans, const std::vector<StudentWork>& students,
                   const GradeSettings& settings, Calibration& calibration,
                   const std::function<void(std::size_t, const StageRecord&)>& stageDone,
                   const std::function<void(std::size_t, StudentRecord)>& done) {
    using Clock = std::chrono::steady_clock;
    struct Pending {
        std::vector<std::optional<StageRecord>> stages;  // per stage of the plan, once made
        std::size_t stagesLeft = 0;
        double seconds = 0;  // the wall time of its stages' jobs (rounds interleave students)
    };
    std::vector<Pending> pending(students.size());
    std::vector<std::vector<CheckCase>> series;
    std::vector<std::pair<std::size_t, std::size_t>> owner;  // series[k]: (student, stage)
    auto made = [&](std::size_t k, std::size_t j, StageRecord st) {
        if (stageDone) stageDone(k, st);
        pending[k].stages[j] = std::move(st);
    };
    for (std::size_t k = 0; k < students.size(); ++k)
        pending[k].stages.resize(plans[k].stages.size());
    for (const auto [k, j] : renderOrder(plans, students)) {
        const std::string dir = settings.imageDir ? settings.imageDir(students[k]) : "";
        const StagePlan& p = plans[k].stages[j];
        series.emplace_back();
        bool firstShown = true;
        for (const RowPlan& row : p.rows) {
            series.back().push_back(row.check);
            RowPictures& pictures = series.back().back().pictures;
            pictures = RowPictures::Difference;
            if (!settings.pictures || dir.empty()) continue;
            const bool shown = p.visibility != "hidden" && row.visibility != "hidden";
            pictures = !settings.pagePicturesOnly || (shown && firstShown)
                           ? RowPictures::All
                           : RowPictures::AllUnlessPassing;
            firstShown = firstShown && !shown;
        }
        owner.emplace_back(k, j);
        ++pending[k].stagesLeft;
    }
    auto finish = [&](std::size_t k) {
        const StudentWork& s = students[k];
        StudentRecord record;
        if (!s.error.empty()) {
            record = unreadableRecord(plans[k], s);
        } else {
            std::vector<StageRecord> stages;
            for (std::size_t j = 0; j < plans[k].stages.size(); ++j) {
                if (!pending[k].stages[j])  // not rendered: MISSING, skipped, no rows
                    made(k, j, stageRecord(plans[k].stages[j], nullptr, s.overlay));
                stages.push_back(*pending[k].stages[j]);
            }
            record = buildRecord(plans[k], s, stages, pending[k].seconds);
        }
        record.seed = settings.seed;
        // The student's own check report: compared once the grade is made, never a score.
        if (s.error.empty() && s.ownReport) attachOwnCheck(record, *s.ownReport);
        done(k, std::move(record));
    };
    // Students with nothing to render are done before any worker starts.
    for (std::size_t k = 0; k < students.size(); ++k)
        if (pending[k].stagesLeft == 0) finish(k);
    auto diffPath = [&](const CheckCase& c) -> std::string {
        // The case belongs to the student whose overlay it carries.
        for (std::size_t k = 0; k < students.size(); ++k) {
            if (students[k].overlay.empty() || c.request.overlay != students[k].overlay) continue;
            const std::string dir = settings.imageDir ? settings.imageDir(students[k]) : "";
            if (dir.empty()) return "";
            return settings.rowImage ? settings.rowImage(students[k], c)
                                     : dir + "/" + rowSlug(c) + ".png";
        }
        // Our own shaders (check without --shaders): the first student's folder, if any.
        if (students.size() == 1 && students[0].overlay.empty() && settings.imageDir) {
            const std::string dir = settings.imageDir(students[0]);
            if (dir.empty()) return "";
            return settings.rowImage ? settings.rowImage(students[0], c)
                                     : dir + "/" + rowSlug(c) + ".png";
        }
        return "";
    };
    auto last = Clock::now();  // when the previous job came back
    checkInWorkers(
        series, diffPath, calibration, [&](std::size_t k, std::vector<CheckResult> results) {
            auto [who, j] = owner[k];
            const auto now = Clock::now();
            pending[who].seconds += std::chrono::duration<double>(now - last).count();
            last = now;
            made(who, j, stageRecord(plans[who].stages[j], &results, students[who].overlay));
            if (--pending[who].stagesLeft == 0) finish(who);
        });
}

}  // namespace sl
