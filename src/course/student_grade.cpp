#include "course/student_grade.h"

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

}  // namespace sl
