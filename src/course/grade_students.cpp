#include "course/grade_students.h"

#include <chrono>
#include <map>

namespace sl {

std::string rowSlug(const CheckCase& c) {
    std::string slug =
        c.request.stage + "-" + treeName(c.request.tree) + "-" + c.view + "-" + c.lesson;
    for (char& ch : slug)
        if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '.' && ch != '-') ch = '_';
    return slug;
}

bool gradeStudents(const Assignment& a, const std::vector<StudentWork>& students,
                   const GradeSettings& settings,
                   const std::function<void(std::size_t, const nlohmann::json&)>& done) {
    struct Pending {
        std::vector<StagePlan> plan;
        std::vector<std::vector<CheckResult>> results;
        std::size_t stagesLeft = 0;
        std::chrono::steady_clock::time_point start;
    };
    std::vector<Pending> pending(students.size());
    std::vector<std::vector<CheckCase>> series;
    std::vector<std::size_t> owner;  // series[k] belongs to student owner[k]
    for (std::size_t k = 0; k < students.size(); ++k) {
        if (!students[k].error.empty()) continue;
        pending[k].plan = planStudent(a, students[k], settings.seed);
        for (auto& cases : checksOf(pending[k].plan)) {
            std::string dir = settings.imageDir ? settings.imageDir(students[k]) : "";
            for (CheckCase& c : cases) c.pictures = settings.pictures && !dir.empty();
            series.push_back(std::move(cases));
            owner.push_back(k);
            ++pending[k].stagesLeft;
        }
    }
    auto finish = [&](std::size_t k) {
        const StudentWork& s = students[k];
        if (!s.error.empty()) {
            done(k, unreadableRecord(a, s));
            return;
        }
        double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - pending[k].start)
                .count();
        nlohmann::json record = studentRecord(a, s, pending[k].plan, pending[k].results, seconds);
        if (settings.seed) record["seed"] = *settings.seed;
        done(k, record);
    };
    auto now = std::chrono::steady_clock::now();
    for (auto& p : pending) p.start = now;
    // Students with nothing to render are done before any worker starts.
    for (std::size_t k = 0; k < students.size(); ++k)
        if (pending[k].stagesLeft == 0) finish(k);
    std::size_t started = series.empty() ? 0 : owner[0];
    auto diffPath = [&](const CheckCase& c) -> std::string {
        // The case belongs to the student whose series is running (cases carry their overlay).
        for (std::size_t k = 0; k < students.size(); ++k)
            if (!students[k].overlay.empty() && c.request.overlay == students[k].overlay)
                return settings.imageDir
                           ? settings.imageDir(students[k]) + "/" + rowSlug(c) + ".png"
                           : "";
        return "";
    };
    bool platformFailure = false;
    checkInWorkers(series, diffPath, settings.backend, settings.limits, platformFailure,
                   [&](std::size_t k, std::vector<CheckResult> results) {
                       std::size_t who = owner[k];
                       if (who != started) {
                           pending[who].start = std::chrono::steady_clock::now();
                           started = who;
                       }
                       pending[who].results.push_back(std::move(results));
                       if (--pending[who].stagesLeft == 0) finish(who);
                   });
    return platformFailure;
}

}  // namespace sl
