// How far a class's grading is, for the time left on grade's progress lines. Students finish in
// rounds (grade/grade_students.h), so counting students gave bursts and estimates 2x off by the
// midpoint (issue 28); each job instead counts the rows of its rendered stages as they come
// back, in a small file the parent reads (OUT/logs/job-N.progress: "DONE TOTAL").
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "grade/plan.h"
#include "grade/record.h"

namespace sl {

// A job's side: the rows it will render (its share's plans) and those done so far.
class JobProgress {
  public:
    JobProgress(const std::string& path, const std::vector<GradingPlan>& plans);
    ~JobProgress();
    JobProgress(const JobProgress&) = delete;
    JobProgress& operator=(const JobProgress&) = delete;
    // A stage of `plan` is done: its planned rows count if it was rendered (a shader error
    // stops a stage after one row; the rest are done too).
    void stageDone(const GradingPlan& plan, const StageRecord& stage);

  private:
    void write();
    int fd_ = -1;
    std::size_t done_ = 0, total_ = 0;
};

// The rows done and to do over every job's file (jobs not started yet count nothing).
struct RowsDone {
    std::size_t done = 0, total = 0;
};
RowsDone readProgress(const std::vector<std::string>& paths);

// The time left at the pace since the first rows came back (the first ones carry the start:
// compiling, tracing the views), or at the pace so far while only one reading is known.
class Pace {
  public:
    // A reading `seconds` after the start; returns the time left, or none before any row.
    std::optional<double> timeLeft(double seconds, const RowsDone& rows);

  private:
    std::optional<std::pair<double, std::size_t>> first_;  // (seconds, rows done)
};

}  // namespace sl
