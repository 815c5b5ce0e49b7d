#include "grade/grade_students.h"

#include <chrono>
#include <optional>

namespace sl {

std::string rowSlug(const CheckCase& c) {
    std::string slug =
        c.request.stage + "-" + treeName(c.request.tree) + "-" + c.view + "-" + c.lesson;
    for (char& ch : slug)
        if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '.' && ch != '-') ch = '_';
    return slug;
}

void gradeStudents(const std::vector<GradingPlan>& plans, const std::vector<StudentWork>& students,
                   const GradeSettings& settings, Calibration& calibration,
                   const std::function<void(std::size_t, const StageRecord&)>& stageDone,
                   const std::function<void(std::size_t, StudentRecord)>& done) {
    using Clock = std::chrono::steady_clock;
    struct Pending {
        std::vector<std::optional<StageRecord>> stages;  // per stage of the plan, once made
        std::size_t stagesLeft = 0;
        Clock::time_point start;
    };
    std::vector<Pending> pending(students.size());
    std::vector<std::vector<CheckCase>> series;
    std::vector<std::pair<std::size_t, std::size_t>> owner;  // series[k]: (student, stage)
    auto made = [&](std::size_t k, std::size_t j, StageRecord st) {
        if (stageDone) stageDone(k, st);
        pending[k].stages[j] = std::move(st);
    };
    for (std::size_t k = 0; k < students.size(); ++k) {
        const GradingPlan& plan = plans[k];
        pending[k].stages.resize(plan.stages.size());
        if (!students[k].error.empty()) continue;
        const std::string dir = settings.imageDir ? settings.imageDir(students[k]) : "";
        for (std::size_t j = 0; j < plan.stages.size(); ++j) {
            const StagePlan& p = plan.stages[j];
            if (!p.rendered()) continue;
            series.emplace_back();
            for (const RowPlan& row : p.rows) {
                series.back().push_back(row.check);
                series.back().back().pictures = settings.pictures && !dir.empty();
            }
            owner.emplace_back(k, j);
            ++pending[k].stagesLeft;
        }
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
            double seconds =
                std::chrono::duration<double>(Clock::now() - pending[k].start).count();
            record = buildRecord(plans[k], s, stages, seconds);
        }
        record.seed = settings.seed;
        done(k, std::move(record));
    };
    const auto now = Clock::now();
    for (auto& p : pending) p.start = now;
    // Students with nothing to render are done before any worker starts.
    for (std::size_t k = 0; k < students.size(); ++k)
        if (pending[k].stagesLeft == 0) finish(k);
    std::size_t started = series.empty() ? 0 : owner[0].first;
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
    checkInWorkers(series, diffPath, calibration,
                   [&](std::size_t k, std::vector<CheckResult> results) {
                       auto [who, j] = owner[k];
                       if (who != started) {
                           pending[who].start = Clock::now();
                           started = who;
                       }
                       made(who, j,
                            stageRecord(plans[who].stages[j], &results, students[who].overlay));
                       if (--pending[who].stagesLeft == 0) finish(who);
                   });
}

}  // namespace sl
