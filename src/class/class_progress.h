// How far a class's grading is, for the time left on grade's progress lines. Students finish in
// rounds (grade/grade_students.h), so counting students gave bursts and estimates 2x off by the
// midpoint (issue 28); each job instead counts the rows of its rendered stages as they come
// back, in a small file the parent reads (OUT/logs/job-N.progress: "DONE TOTAL").
#pragma once

#include <cstddef>
#include <optional>
#include <set>
#include <string>
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
    std::size_t done_ = 0, total_ = 0;
};

// The rows done and to do of one job, from its file (none yet, or unreadable: 0 of 0).
struct RowsDone {
    std::size_t done = 0, total = 0;
};
std::vector<RowsDone> readProgress(const std::vector<std::string>& paths);

// The time left: each job's rows left at the jobs' pace, the mean of each job's since its first
// rows came back (the first ones carry the start: compiling, tracing the views), or so far while
// only one reading is known. The class is done when its job with the most rows left is: counting
// all jobs' rows together missed the end, when the last job runs alone (0.21 off). Jobs grade
// the same kind of students (dealt in turn) on the same cores, so their paces differ by which
// of them the cores ran lately, not by their work: at its own pace a job whose first round ran
// slow said 40 % too much through its next round. Replayed on 24 recorded runs of the class
// bench (tests/course/replay_progress.py, docs/results-class.md), with the records' lag below:
// the jobs' pace put 46 lines over 25 % of 399, each job's own 59, and with its first round's
// cost counted half (the rule before) 65; 78 without the lag. On 6 runs recorded after: 14
// against 22 as before.
// A job's pace runs from its first reading to the reading its rows last grew at, and the time
// since then is taken off what its rows left need, down to what the rows after the next step
// (as many as its last) need: rows come back a stage at a time, and a pace to the reading's time
// made the estimate rise between stages and fall at each (issue 39); a stage that takes longer
// than the pace says holds the estimate, it never drops to 0 with rows after it.
// A student's line comes a little after its job's rows: its record is written, the parent reads
// it at its next poll and writes the page; after the last one the class's outputs. No row counts
// that time, so the last lines said "0.3 s" with 0.9 s left and "0.0 s" with 0.4 s (issue 39).
// The mean time from a job's last rows to its students' records (their pages written), measured
// in the run, is added to each job's time left, and runs out after a job's last rows.
class Pace {
  public:
    // A reading `seconds` after the start; the time left, or none before any row came back.
    std::optional<double> timeLeft(double seconds, const std::vector<RowsDone>& jobs);
    // A student of job `job` came back at `seconds` (after the reading of the same time).
    void recordBack(double seconds, std::size_t job);

  private:
    struct Seen {
        double firstAt = 0, lastAt = 0;  // the first reading with rows, the last that had more
        std::size_t firstDone = 0, lastDone = 0, lastStep = 0;  // lastStep: the rows it added
        double secondsPerRow() const;
    };
    double lag() const;
    std::vector<std::optional<Seen>> seen_;
    double lagSum_ = 0;  // from a job's last rows to a student's record, each student
    std::size_t lags_ = 0;
};

}  // namespace sl
