// How far a class's grading is, for the time left on grade's progress lines. Students finish in
// rounds (grade/grade_students.h), so counting students gave bursts and estimates 2x off by the
// midpoint (issue 28); each job instead counts the rows of its rendered stages as they come
// back, in a small file the parent reads (OUT/logs/job-N.progress: "DONE TOTAL FIRST", FIRST the
// rows of its first round).
#pragma once

#include <cstddef>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "grade/plan.h"
#include "grade/record.h"

namespace sl {

// A job's side: the work it will do (its share's plans, in gradeStudents' rounds) and the work
// done so far, counted in rows. A round draws each stage's views once (traced, and drawn with our
// shaders) and that costs about one student's rows of the stage: all-stage hand-ins 4 a job,
// rounds of 1, 1 and 2 students, took 8-14 s a round of one and 14-21 s a round of two (idle,
// 2 jobs). So each round's stage counts its rows once more, done with the first of its students
// to come back; by rows alone a row of a round of two cost half of one of a round of one, and
// the estimate was 20-70 % high through the last round (issue 39).
class JobProgress {
  public:
    JobProgress(const std::string& path, const std::vector<GradingPlan>& plans);
    ~JobProgress();
    JobProgress(const JobProgress&) = delete;
    JobProgress& operator=(const JobProgress&) = delete;
    // A stage of student `k`'s plan is done: its planned rows count if it was rendered (a shader
    // error stops a stage after one row; the rest are done too), and its round's views if it is
    // the first of the round's students to be done with that stage.
    void stageDone(std::size_t k, const StageRecord& stage);

  private:
    void write();
    const StagePlan* renderedStage(std::size_t k, const std::string& stage,
                                   const std::string& tree) const;
    const std::vector<GradingPlan>& plans_;
    std::set<std::string> roundViewsDone_;  // "ROUND STAGE TREE"
    int fd_ = -1;
    std::size_t done_ = 0, total_ = 0, firstRound_ = 0;
};

// The rows done and to do of one job, from its file (none yet, or unreadable: 0 of 0), and the
// rows of its first round (0: not known).
struct RowsDone {
    std::size_t done = 0, total = 0, firstRound = 0;
};
std::vector<RowsDone> readProgress(const std::vector<std::string>& paths);

// The time left: each job's at its own pace since its first rows came back (the first ones
// carry the start: compiling, tracing the views), or at its pace so far while only one reading
// is known; a job with no rows back yet at the others' mean pace. The class is done when its
// slowest job is: jobs' shares differ (a starter writes pictures for every failing row), and
// counting all jobs' rows together missed the end, when the last job runs alone (0.21 off).
// A job's pace runs from its first reading to the reading its rows last grew at, and the time
// since then is taken off what its rows left need, down to what the rows after the next step
// (as many as its last) need: rows come back a stage at a time, and a pace to the reading's time
// made the estimate rise between stages and fall at each (issue 39); a stage that takes longer
// than the pace says holds the estimate, it never drops to 0 with rows after it.
// Once a job's first round is done and rows came after it, its pace is the mean of that pace and
// the pace since the first reading that saw the round done: a first round costs more a row (every
// program compiled for the first time, the worker's caches empty; 0.059 and 0.087 s a row against
// 0.043 and 0.064 in the second, docs/results-class.md) and the pace since the first reading said
// the rest would cost that too. The later rounds alone hold fewer rows and differ in what they
// hold (a round of starters writes a picture for every failing row): replayed on 6 recorded
// runs, the mean had fewer readings over 25 % than the pace since the first reading on 5 (41
// against 39 on one) and than the later rounds' pace alone on 5 (issue 39;
// docs/results-class.md).
class Pace {
  public:
    // A reading `seconds` after the start; the time left, or none before any row came back.
    std::optional<double> timeLeft(double seconds, const std::vector<RowsDone>& jobs);

  private:
    struct Seen {
        double firstAt = 0, lastAt = 0;  // the first reading with rows, the last that had more
        std::size_t firstDone = 0, lastDone = 0, lastStep = 0;    // lastStep: the rows it added
        std::optional<std::pair<double, std::size_t>> roundDone;  // first round done: when, rows
        double secondsPerRow() const;
    };
    std::vector<std::optional<Seen>> seen_;
};

}  // namespace sl
