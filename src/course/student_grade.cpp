#include "course/student_grade.h"

#include <algorithm>
#include <set>

#include "grade/bounds.h"

namespace sl {

GradingPlan planStudent(const Assignment& a, const StudentWork& s,
                        std::optional<std::uint64_t> seed) {
    GradingPlan plan;
    plan.name = a.name;
    for (const AssignmentStage* st : a.due()) {
        StagePlan p;
        p.stage = st->stage;
        p.tree = st->tree;
        p.files = st->files;
        p.points = st->points;
        p.visibility = st->visibility;
        if (s.error.empty())
            for (const std::string& f : st->files)
                if (!s.has(f)) p.missingFiles.push_back(f);
        p.rows = planStage(a, *st, p.missingFiles.empty() ? s.overlay : "", seed);
        plan.stages.push_back(std::move(p));
    }
    return plan;
}

std::vector<std::string> dueStageNames(const Assignment& a) {
    std::vector<std::string> out;
    for (const AssignmentStage* st : a.due())
        if (std::find(out.begin(), out.end(), st->stage) == out.end()) out.push_back(st->stage);
    return out;
}

std::vector<std::string> unlistedFileNotes(const Assignment& a, const StudentWork& s) {
    auto named = [&](const std::string& f) {
        for (const std::string& n : s.notes)
            if (n.find("`" + f + "`") != std::string::npos) return true;
        return false;
    };
    std::vector<std::string> out;
    for (const std::string& stage : dueStageNames(a)) {
        std::vector<std::string> listed, unlisted;
        for (const AssignmentStage* st : a.due())
            if (st->stage == stage) listed.insert(listed.end(), st->files.begin(), st->files.end());
        for (const std::string& f : s.files)
            if (f.rfind(stage + "/", 0) == 0 &&
                std::find(listed.begin(), listed.end(), f) == listed.end() && !named(f))
                unlisted.push_back("`" + f + "`");
        if (unlisted.empty()) continue;
        std::string files, wanted;
        for (const std::string& f : cappedList(unlisted)) files += (files.empty() ? "" : ", ") + f;
        for (const std::string& f : listed)
            wanted += (wanted.empty() ? "" : ", ") + ("`" + f + "`");
        out.push_back(files + (unlisted.size() == 1 ? " is" : " are") +
                      " not graded: this assignment grades only " + wanted + " of " + stage + "/");
    }
    return out;
}

}  // namespace sl
