#include "course/solution_check.h"

#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "course/student_grade.h"
#include "grade/record.h"
#include "io/box.h"
#include "io/files.h"
#include "io/usage_error.h"
#include "sandbox/job_fanout.h"
#include "sandbox/private_dir.h"
#include "stages/stage.h"

namespace sl {

namespace {

// The solution handed in as a student would: the due stages' files, copied from `trees`, and
// the other marked files of their folders (so the rows that draw with one of those show it).
StudentWork solutionWork(const Assignment& a, const SolutionTrees& trees, const std::string& dir) {
    StudentWork work;
    work.name = "solution";
    work.overlay = dir;
    for (std::size_t k = 0; k < a.stages.size(); ++k) {
        const AssignmentStage& s = a.stages[k];
        if (!s.due) continue;
        std::vector<std::string> files = s.files;
        for (const std::string& f : markedFiles(trees.root(s.tree), s.stage))
            if (std::find(files.begin(), files.end(), f) == files.end()) files.push_back(f);
        for (const std::string& f : files) {
            std::string source = trees.root(s.tree) + "/" + f, text;
            std::string err = readRegularFile(source, 1u << 20, text);
            if (!err.empty())
                throw UsageError(printableName(source) + " (" +
                                 a.at("/stages/" + std::to_string(k) + "/files") + ", from " +
                                 trees.describe() + "): " + err);
            std::error_code ec;
            std::filesystem::create_directories(std::filesystem::path(dir + "/" + f).parent_path(),
                                                ec);
            err = writeFileAtomically(dir + "/" + f, text.data(), text.size());
            if (!err.empty()) throw std::runtime_error("the solution's copy: " + err);
            work.files.push_back(f);
        }
    }
    return work;
}

// The assignment entry that made a row: its extra view, else its stage (and the view's or the
// lesson's own weight when the assignment gives one).
std::string entryOf(const Assignment& a, const StageRecord& stage, const RowRecord* row) {
    std::string view = row ? row->result.view : "", lesson = row ? row->result.lesson : "";
    if (row && row->extraView)
        for (std::size_t k = 0; k < a.extraViews.size(); ++k)
            if (a.extraViews[k].name == view) return "/extra_views/" + std::to_string(k);
    for (std::size_t k = 0; k < a.stages.size(); ++k) {
        const AssignmentStage& s = a.stages[k];
        if (!s.due || s.stage != stage.stage || s.tree != stage.tree) continue;
        std::string path = "/stages/" + std::to_string(k);
        if (s.views.count(view)) return path + "/views/" + view;
        if (s.lessons.count(lesson)) return path + "/lessons/" + lesson;
        return path;
    }
    return "";
}

// A marked file that stage k of `a` draws with (lesson `lesson`) but does not list: the one
// message of the static check and of the check after the solution's grading.
AssignmentError unlistedMarked(const Assignment& a, std::size_t k, const std::string& file,
                               const SolutionTrees& trees, const std::string& lesson) {
    const AssignmentStage& s = a.stages[k];
    return AssignmentError(a.at("/stages/" + std::to_string(k) + "/files") + ": " + file + " (" +
                           trees.describe() + ") holds a solution region and " + s.stage + "/" +
                           s.tree + " draws with it (lesson '" + lesson +
                           "'), but it is not in the stage's files: students have only a stub "
                           "of it; list it, or weigh that lesson 0");
}

// A marked file of a due stage's folder that the stage does not list but a graded row draws
// with: students' copies of it are stubs (their release has none, the student edition stubs
// it), so the row would grade our solution for them in the class and a stub at home.
void refuseUnlistedMarked(const Assignment& a, const SolutionTrees& trees,
                          const StudentRecord& record) {
    for (std::size_t k = 0; k < a.stages.size(); ++k) {
        const AssignmentStage& s = a.stages[k];
        if (!s.due) continue;
        for (const StageRecord& st : record.stages) {
            if (st.stage != s.stage || st.tree != s.tree) continue;
            for (const RowRecord& row : st.rows)
                for (const std::string& f : row.result.studentFiles) {
                    if (std::find(s.files.begin(), s.files.end(), f) != s.files.end()) continue;
                    throw unlistedMarked(a, k, f, trees, row.result.lesson);
                }
        }
    }
}

// What refuseUnlistedMarked finds after grading, found before anything is rendered where the
// stage can tell which programs a graded row draws with (Stage::passes: its settings alone): a
// mistake visible in the files costs milliseconds, not the solution's grading.
void refuseUnlistedMarkedByPlan(const Assignment& a, const SolutionTrees& trees,
                                const GradingPlan& plan) {
    for (std::size_t k = 0; k < a.stages.size(); ++k) {
        const AssignmentStage& s = a.stages[k];
        const StageInfo* info = findStage(s.stage);
        if (!s.due || !info || !info->create) continue;
        const std::unique_ptr<Stage> stage = info->create();
        const std::vector<std::string> marked = markedFiles(trees.root(s.tree), s.stage);
        auto has = [](const std::vector<std::string>& list, const std::string& f) {
            return std::find(list.begin(), list.end(), f) != list.end();
        };
        for (const StagePlan& st : plan.stages) {
            if (st.stage != s.stage || st.tree != s.tree || !st.rendered()) continue;
            for (const RowPlan& row : st.rows) {
                if (row.points <= 0) continue;
                ParamSet params(info->params);
                for (const auto& [name, value] : row.check.request.sets) params.set(name, value);
                for (const std::string& pass : stage->passes(params))
                    for (const char* ext : {".vert", ".frag"}) {
                        const std::string f = s.stage + "/" + pass + ext;
                        if (!has(marked, f) || has(s.files, f)) continue;
                        throw unlistedMarked(a, k, f, trees, row.check.lesson);
                    }
            }
        }
    }
}

// The solution graded by `plan` with its stages dealt over the box's cores: part p grades the
// stages j with j % parts == p in a process of its own (a core's share each, as a class's jobs),
// writes its record to `dir`, and the parent puts the stages back in the plan's order. It comes
// before a class is graded (a serial minute of an all-stage class on one core, issue 28).
StudentRecord gradeSolution(const GradingPlan& plan, const StudentWork& solution,
                            const GradeSettings& settings, const std::string& dir) {
    std::size_t rendered = 0;
    for (const StagePlan& st : plan.stages) rendered += st.rendered();
    const int cores = boxCores();
    // As a class's jobs: a core each, as the box's memory allows.
    const int parts = int(std::min<std::size_t>(std::size_t(boxJobs(kMbPerGradingJob)), rendered));
    auto gradePart = [&](const GradingPlan& part) {
        Calibration calibration(settings.budget, settings.backend);
        StudentRecord record;
        gradeStudents({part}, {solution}, settings, calibration, nullptr,
                      [&](std::size_t, StudentRecord r) { record = std::move(r); });
        return record;
    };
    if (parts <= 1) return gradePart(plan);
    auto partPath = [&](int p) { return dir + "/part-" + std::to_string(p) + ".json"; };
    JobFanOut fan(parts, std::max(1, cores / parts), "the solution check's part", [&](int p) {
        GradingPlan part = plan;
        part.stages.clear();
        for (std::size_t j = 0; j < plan.stages.size(); ++j)
            if (j % std::size_t(parts) == std::size_t(p)) part.stages.push_back(plan.stages[j]);
        std::string text = keptRecordJson(gradePart(part)).dump();
        std::string err = writeFileAtomically(partPath(p), text.data(), text.size());
        if (!err.empty()) throw std::runtime_error(err);
        return 0;
    });
    bool failed = false;
    for (const JobFanOut::Ended& e : fan.waitAll()) failed = failed || e.code != 0;
    std::vector<StageRecord> stages(plan.stages.size());
    for (int p = 0; p < parts && !failed; ++p) {
        std::string text;
        if (!readRegularFile(partPath(p), 64u << 20, text).empty()) {
            failed = true;
            break;
        }
        StudentRecord part = recordFromJson(nlohmann::json::parse(text));
        std::size_t next = 0;
        for (std::size_t j = std::size_t(p); j < plan.stages.size(); j += std::size_t(parts))
            stages[j] = part.stages.at(next++);
    }
    if (failed) throw std::runtime_error("the solution check's processes failed: rerun");
    return buildRecord(plan, solution, stages, 0);
}

}  // namespace

StudentRecord verifySolution(const Assignment& a, const SolutionTrees& trees,
                             const GradeSettings& settings,
                             const std::function<void()>& gradingStarts) {
    PrivateDir dir("shadowlab-solution");
    StudentWork solution = solutionWork(a, trees, dir.path() + "/hand-in");
    GradeSettings quiet = settings;
    quiet.pictures = false;
    quiet.imageDir = nullptr;
    quiet.rowImage = nullptr;
    const GradingPlan plan = planStudent(a, solution, quiet.seed);
    refuseUnlistedMarkedByPlan(a, trees, plan);
    if (gradingStarts) gradingStarts();
    StudentRecord record = gradeSolution(plan, solution, quiet, dir.path());
    refuseUnlistedMarked(a, trees, record);
    double lost = 0;
    int rowsLost = 0;
    std::string first;
    for (const StageRecord& st : record.stages) {
        std::string id = st.stage + "/" + st.tree, message = printable(st.message);
        if (st.status == Status::NotGraded || st.status == Status::Timeout ||
            st.status == Status::Crash)
            throw std::runtime_error("the solution's " + id + " (" + trees.describe() +
                                     ") could not be graded (" + statusName(st.status) + ": " +
                                     message.substr(0, 200) + "): rerun");
        if (unjudged(st.status))
            throw AssignmentError(a.at(entryOf(a, st, nullptr)) + ": the solution's " + id + " (" +
                                  trees.describe() + ") is " + statusName(st.status) + ": " +
                                  message.substr(0, 300));
        for (const RowRecord& row : st.rows) {
            double missed = row.maxPoints - row.points;
            if (missed <= 1e-9) continue;
            lost += missed;
            ++rowsLost;
            if (first.empty())
                first = a.at(entryOf(a, st, &row)) + ": " + id + " view " + row.result.view +
                        " lesson '" + row.result.lesson + "' is " + row.result.verdict() + " (" +
                        printable(row.result.message).substr(0, 300) + ")";
        }
    }
    if (rowsLost > 0) {
        std::ostringstream points;  // "8.33 of 100.00"
        points << std::fixed << std::setprecision(2) << lost << " of " << a.maxPoints();
        throw AssignmentError(first + ": the solution (" + trees.describe() + ") loses " +
                              points.str() + " points in " + std::to_string(rowsLost) +
                              (rowsLost == 1 ? " row" : " rows") +
                              ", so every correct student would; change or drop the row");
    }
    return record;
}

}  // namespace sl
