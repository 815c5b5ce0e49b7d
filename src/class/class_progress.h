// How far a class's grading is, for the time left on grade's progress lines. Students finish in
// rounds (grade/grade_students.h), so counting students gave bursts and estimates 2x off by the
// midpoint (issue 28); each job instead counts the rows of its rendered stages as they come
// back, in a small file the parent reads (OUT/logs/job-N.progress):
//   DONE TOTAL ROWS VIEWS STAGE             all rows; the step under way: its rows, its views'
//   DONE TOTAL VIEWSDONE VIEWSTOTAL KEY     a line for each stage it renders ("margin/core")
// STAGE is the step's stage, counted from 0 in the lines after (as many as there are: none).
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "grade/grade_students.h"
#include "grade/plan.h"
#include "grade/record.h"

namespace sl {

// A job's side: the work it will do (its share's plans, in gradeStudents' rounds and order) and
// the work done so far, counted in rows. A round draws each stage's views once (traced, and drawn
// with our shaders), counted as one student's rows of the stage more, done with the first of its
// students to come back: by students' rows alone a row of a round of two cost half of one of a
// round of one, and the estimate was 20-70 % high through the last round (issue 39). The views'
// rows are counted apart: what they cost is not one student's rows (Pace).
class JobProgress {
  public:
    JobProgress(const std::string& path, const std::vector<GradingPlan>& plans,
                const std::vector<StageStep>& order);
    ~JobProgress();
    JobProgress(const JobProgress&) = delete;
    JobProgress& operator=(const JobProgress&) = delete;
    // A stage of student `k`'s plan is done: its planned rows count if it was rendered (a shader
    // error stops a stage after one row; the rest are done too), and its round's views if it is
    // the first of the round's students to be done with that stage.
    void stageDone(std::size_t k, const StageRecord& stage);

  private:
    struct Counts {
        std::size_t done = 0, total = 0, viewsDone = 0, viewsTotal = 0;
    };
    void write();
    const StagePlan* renderedStage(std::size_t k, const std::string& stage,
                                   const std::string& tree) const;
    bool roundViewsLeft(std::size_t k, const StagePlan& st) const;
    const std::vector<GradingPlan>& plans_;
    std::vector<StageStep> order_;
    std::vector<bool> stepDone_;            // of order_
    std::size_t underway_ = 0;              // the first step of order_ not done
    std::set<std::string> roundViewsDone_;  // "ROUND STAGE TREE"
    std::map<std::string, Counts> stages_;  // "STAGE/TREE"
    int fd_ = -1;
};

// The rows of one stage (its key "STAGE/TREE") a job renders, done and to do: its students' and
// its rounds' views'.
struct StageRows {
    std::string key;
    std::size_t done = 0, total = 0, viewsDone = 0, viewsTotal = 0;
};

// The rows done and to do of one job, from its file (none yet, or unreadable: 0 of 0): all of
// them, stage by stage (none in a file without them), and the step under way: a student's rows
// of stage `underwayKey` and its round's views (none: 0, 0 and "").
struct RowsDone {
    std::size_t done = 0, total = 0;
    std::vector<StageRows> stages;
    std::size_t underwayRows = 0, underwayViews = 0;
    std::string underwayKey;
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
// Once a step is timed, a job's rows left cost what their stage's rows cost so far (all jobs'
// steps), in seconds; before, the rows at the jobs' pace. The time from a job's reading to its
// next with more rows goes to the stage(s) whose rows those were; a job's first reading carries
// the start, and its first step of a stage the calibration of our shaders (stage_runs.h; 1.4
// times a step of the next round): neither is timed. A step with its round's views costs the
// student's rows at the price of the stage's steps without views, and the views the rest; a
// stage timed only with views (a class in small rounds) at what views cost against rows on the
// stages timed both ways, or as rows. A stage not timed yet costs the mean row.
// In 7 busy runs of 8 all-stage hand-ins a step with its round's views took 1.0-1.2 times one
// without for six stages, 1.6 and 2.0 for the last two, not the 2 the rows say: the last round's
// rows cost more than the rounds' before, and its lines said 1.05 s with 2.98 s left (issue 39).
// The class's outputs come after the last student's line: they read every record again and
// write the class's page and gradebooks, 0.14 s of the last 0.2-0.25 s for 8 all-stage records
// of 500 KB (busy), none of it in the rows: the second-to-last lines said 0.23-0.28 s with
// 0.54-1.07 s left. They count as the median time the parent took to read a record in the run,
// once for each record they read: 13-44 ms a record (9 ms of CPU) against 0.16 s for the 8
// (busy). Priced with the page's writing too, the last lines said 1.1 s with 0.5 s left.
// The step under way is the one the job's file says (it knows the order): taken as the last
// step's rows (2 rows of one stage, where 48 of the next were under way), the estimate held at
// the rows after it.
class Pace {
  public:
    // A reading `seconds` after the start; the time left, or none before any row came back.
    std::optional<double> timeLeft(double seconds, const std::vector<RowsDone>& jobs);
    // A student of job `job` came back at `seconds` (after the reading of the same time); the
    // parent took `read` seconds to read its record.
    void recordBack(double seconds, std::size_t job, double read);
    // After the last student the class's outputs read `records` records again (writeOutputs).
    void outputsRead(std::size_t records) { outputReads_ = records; }

  private:
    struct Seen {
        double firstAt = 0, lastAt = 0;  // the first reading with rows, the last that had more
        std::size_t firstDone = 0, lastDone = 0, lastStep = 0;  // lastStep: the rows it added
        std::vector<StageRows> lastStages;                      // at lastAt
        double secondsPerRow() const;
    };
    struct StageCost {
        double plainSeconds = 0, plainRows = 0;                 // steps without their round's views
        double viewsSeconds = 0, viewsStepRows = 0, views = 0;  // steps with them
    };
    struct Prices {
        double row, view;  // seconds
    };
    void timeSteps(const Seen& before, double seconds, const RowsDone& now);
    Prices prices(const StageCost& c) const;
    double viewsAgainstRows() const;
    double meanRow() const;
    double priced(const std::string& key, std::size_t rows, std::size_t views) const;
    double secondsLeft(const RowsDone& r) const;
    double lag() const;
    double medianRead() const;
    std::vector<std::optional<Seen>> seen_;
    std::map<std::string, StageCost> stageCost_;
    double timedSeconds_ = 0, timedRows_ = 0;  // all of stageCost_'s
    double lagSum_ = 0;          // from a job's last rows to a student's record, each student
    std::vector<double> reads_;  // the parent's read of each record back: one a lag
    std::size_t outputReads_ = 0;
};

// The time left when a line is said, from the estimate made `said - estimatedAt` seconds before:
// a poll's lines come after their records are read and their pages written: 0.03-0.31 s after
// its estimate in 12 busy all-stage runs (8 lines each, most 0.05-0.13), with 0.5-2 s left at
// the second-to-last line.
double timeLeftWhenSaid(double estimate, double estimatedAt, double said);

}  // namespace sl
