#include "course/solution_check.h"

#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "course/student_grade.h"
#include "grade/private_dir.h"
#include "io/files.h"

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
                    throw AssignmentError(
                        a.at("/stages/" + std::to_string(k) + "/files") + ": " + f + " (" +
                        trees.describe() + ") holds a solution region and " + s.stage + "/" +
                        s.tree + " draws with it (lesson '" + row.result.lesson +
                        "'), but it is not in the stage's files: students have only a stub of "
                        "it; list it, or weigh that lesson 0");
                }
        }
    }
}

}  // namespace

StudentRecord verifySolution(const Assignment& a, const SolutionTrees& trees,
                             const GradeSettings& settings) {
    PrivateDir dir("shadowlab-solution");
    StudentWork solution = solutionWork(a, trees, dir.path());
    GradeSettings quiet = settings;
    quiet.pictures = false;
    quiet.imageDir = nullptr;
    quiet.rowImage = nullptr;
    Calibration calibration(quiet.budget, quiet.backend);
    StudentRecord record;
    gradeStudents({planStudent(a, solution, quiet.seed)}, {solution}, quiet, calibration, nullptr,
                  [&](std::size_t, StudentRecord r) { record = std::move(r); });
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
