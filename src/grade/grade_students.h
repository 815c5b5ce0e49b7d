// Students graded in one series of bounded workers: every student's rendered stages in one
// series, so the worker's evaluator (its references, traced once per view) and the calibration
// of our shaders (grade/stage_runs.h) serve the whole series; a stage that kills its worker
// costs that stage only. Used by `check` (one student, a default plan), `check --assignment`
// (one student) and `grade` (a share of the class per job).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "grade/record.h"
#include "grade/stage_runs.h"

namespace sl {

// What one grading process (a class's job, a part of the solution check) may take at most: a
// worker's peak grading every core stage of lab4 at 640x480 was 437 MB (the views' truths it
// keeps), with room for the process itself.
constexpr long kMbPerGradingJob = 768;

struct GradeSettings {
    Backend backend = Backend::Auto;
    BudgetRule budget;
    bool pictures = false;  // write render, truth and diff images per row
    // With pictures: only those a feedback page shows (a stage's first shown row and every row
    // that does not pass; `grade`), not every row's (`check --diff-dir`).
    bool pagePicturesOnly = false;
    // The displaced views' seed (drawn once per run, so a class shares one view and its
    // reference is traced once); none: no displaced view.
    std::optional<std::uint64_t> seed;
    // Where a student's images go ("" = no images); `rowImage(student, case)` names one row's
    // diff image (default: DIR/rowSlug(case).png).
    std::function<std::string(const StudentWork&)> imageDir;
    std::function<std::string(const StudentWork&, const CheckCase&)> rowImage;
    // Applied to a one-student check's record before any output is drawn from it (`check
    // --assignment --submission-metadata`: the late policy; course/ knows it, grade/ does not).
    std::function<void(StudentRecord&)> annotate;
};

// Grades `students[k]` by `plans[k]` in order; `stageDone(k, stage)` as each stage's record is
// made (may be null), `done(k, record)` as each student's last stage comes back (a student with
// nothing to render at once).
void gradeStudents(const std::vector<GradingPlan>& plans, const std::vector<StudentWork>& students,
                   const GradeSettings& settings, Calibration& calibration,
                   const std::function<void(std::size_t, const StageRecord&)>& stageDone,
                   const std::function<void(std::size_t, StudentRecord)>& done);

// The rounds gradeStudents takes a series of n students in, and the round of student k: a
// round's students are done together, and each stage's views are traced and drawn with our
// shaders once a round. The first round is a quarter of the share (firstRound).
std::size_t firstRound(std::size_t n);
std::size_t roundCount(std::size_t n);
std::size_t roundStart(std::size_t r, std::size_t n);  // its first student; n for r = roundCount(n)
std::size_t roundOf(std::size_t k, std::size_t n);

// The stages gradeStudents renders, in its order: (student, index of the stage in its plan),
// round by round, within a round stage by stage. A student with an error renders nothing.
struct StageStep {
    std::size_t student, stage;
};
std::vector<StageStep> renderOrder(const std::vector<GradingPlan>& plans,
                                   const std::vector<StudentWork>& students);

}  // namespace sl
