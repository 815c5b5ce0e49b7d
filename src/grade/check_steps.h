// One student's check graded in this process, a row at a time: the browser edition's `check`
// (a page forks no workers and must draw between rows). The same plan (grade/check_plan.h),
// cases, judge and record as the native check (gradeOneStudent): only where the rows run
// differs. No worker bounds a row here: the page's loop budget (gl/loop_guard.h) stops a loop
// that does not end, and the stage's rows are TIMEOUT as native's CPU-time budget makes them; a
// context the browser loses otherwise makes the row NOT GRADED (the machine's, never the
// student's).
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "eval/trace_view.h"
#include "grade/check_run.h"
#include "grade/record.h"

namespace sl {

class CheckSteps {
  public:
    // `diffPath(case)` names a row's diff image ("" for none); pictures as CheckCase::pictures.
    CheckSteps(GradingPlan plan, StudentWork work, std::optional<std::uint64_t> seed,
               std::function<std::string(const CheckCase&)> diffPath);
    ~CheckSteps();
    std::size_t rowCount() const { return rowCount_; }
    std::size_t rowsDone() const;
    bool done() const { return stage_ == plan_.stages.size(); }
    // Runs the next rendered row, or makes the records of stages with nothing to render. Returns
    // the stage records made by this step (a stage's record is made with its last row).
    std::vector<StageRecord> step();
    // The row the last step ran (none when it ran none).
    const std::optional<CheckResult>& lastRow() const { return lastRow_; }
    // The record so far: every stage made until now (done(): the whole record).
    StudentRecord record() const;

    // The page's Web Workers trace the references (eval/trace_view.h): before a stage's first
    // row, the views its rows are traced from that the Evaluator does not hold and that were not
    // offered for this stage yet (a view a worker could not trace is traced here when needed);
    // none while a stage is under way. giveReference hands one back by its key; what a stage
    // was given and did not use is dropped when it ends.
    std::vector<TraceView> viewsToTrace();
    void giveReference(const std::string& key, ReferenceImage reference);
    int tracedHere() const { return rig_->tracedCount(); }
    int givenUsed() const { return rig_->givenUsedCount(); }

  private:
    void finishStage(std::vector<StageRecord>& made);
    GradingPlan plan_;
    StudentWork work_;
    std::optional<std::uint64_t> seed_;
    std::function<std::string(const CheckCase&)> diffPath_;
    std::unique_ptr<Evaluator> rig_;
    std::unique_ptr<CaseSeries> series_;  // the current stage's rows
    std::size_t stage_ = 0, rowCount_ = 0, rowsBefore_ = 0;
    std::vector<StageRecord> stages_;
    std::vector<CheckResult> failed_;  // a row that threw: the stage's one result
    std::optional<CheckResult> lastRow_;
    std::set<std::string> offered_;  // viewsToTrace's keys
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace sl
