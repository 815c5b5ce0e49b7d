// One student's graded record, built once from the plan and the stages' results, from which
// every output is drawn: the terminal table, --report, JUnit, Gradescope's results.json,
// grades.csv, the feedback pages and the exit code (grade/reports.h, course/). Its JSON
// (docs/assignment.md, "The student's record") is what `grade` keeps per student and reads back
// on a rerun.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "grade/formats.h"
#include "grade/plan.h"
#include "grade/status.h"

namespace sl {

struct RowRecord {
    CheckResult result;                // settings, figures, status, message, student files, images
    double points = 0, maxPoints = 0;  // both 0 for a NOT GRADED row
    std::string visibility = "visible";
    bool extraView = false;
    Status status() const { return result.status; }
};

struct StageRecord {
    std::string stage, tree, visibility = "visible";
    std::vector<std::string> files, missingFiles;
    Status status = Status::Pass;  // the worst of its rows
    std::string message;           // the stage's line: why it is what it is
    double points = 0, maxPoints = 0;
    std::vector<RowRecord> rows;
};

// Who a hand-in is, from the class roster (gradebook/roster.h): drawn into grades.csv and pages.
struct RosterInfo {
    std::string id, name, email;
    bool operator==(const RosterInfo& o) const {
        return id == o.id && name == o.name && email == o.email;
    }
};

// A late hand-in under the assignment's late policy (gradebook/late_policy.h): applied when the
// outputs are drawn (grades.csv's total, the page), the graded score is kept as it is.
struct LateRecord {
    std::string handedIn;  // ISO 8601, UTC
    std::string source;    // where the time came from: a manifest, file times, Gradescope
    double minutes = 0;    // after the deadline (0 within the grace)
    int days = 0;          // days or parts of a day charged
    double penalty = 0;    // points lost
    bool capped = false;   // the policy's cap limited the penalty (days x per day was more)
};

// A TA's adjustment of one stage (gradebook/adjustments.h): points added (or taken off, < 0) and
// the reason the student reads. Applied when the outputs are drawn.
struct Adjustment {
    std::string stage;  // as the TA wrote it: "margin" or "margin/core"
    double points = 0;
    std::string reason;
};

// A row where the student's own check report (an assignment's "own_check_report") gave another
// verdict than the grade: the grade's row name (grade/reports.h rowName) and both statuses.
struct OwnCheckRow {
    std::string stage, tree, row;
    Status home = Status::Pass, grade = Status::Pass;
    bool seen = true;  // the student sees the grade's verdict of it (seenByStudent)
};

// The student's own check report against the grade (grade/own_check.h): never a score, never
// trusted; it shows where a student's machine and ours disagreed (driver differences, or a
// report edited by hand).
struct OwnCheck {
    std::string file;              // its name in the hand-in
    std::string problem;           // why nothing was compared ("" = compared)
    std::string backend, machine;  // the report's own: where the student ran it
    int compared = 0, agreed = 0;
    int seenCompared = 0, seenAgreed = 0;  // of them, rows whose grade the student sees
    int notComparable = 0;  // paired rows not compared: another seed, or NOT GRADED on a side
    int unmatched = 0;      // the report's rows the grade has none like
    int disagreed = 0;      // all of them; `disagreements` keeps the first kMaxOwnCheckRows
    std::vector<OwnCheckRow> disagreements;
};
constexpr std::size_t kMaxOwnCheckRows = 20;

struct StudentRecord {
    std::string tool = "shadowlab grade";
    std::string assignment, student;
    std::string error;  // the hand-in could not be read at all ("" = it was)
    std::vector<std::string> notes, files;
    std::vector<StageRecord> stages;
    double score = 0, maxScore = 0;  // of the graded rows; NOT GRADED rows count in neither
    double seconds = 0;
    std::optional<std::uint64_t> seed;
    std::string backend, machine;
    // Content hashes: the hand-in's files and the assignment's text. A rerun regrades a student
    // whose hand-in or assignment changed (class/class_grade.h).
    std::string handInHash, assignmentHash;
    std::optional<RosterInfo> roster;  // --roster's entry for this hand-in, when there is one
    // Copy flags (class/copy_flags.h): due files equal to the published solution or a
    // classmate's once whitespace, comments and names are set aside. Never a score.
    std::vector<std::string> flags;
    std::optional<LateRecord> late;  // when the assignment has a late policy
    std::vector<Adjustment> adjustments;
    std::optional<OwnCheck> ownCheck;  // when the hand-in carried the student's own check report
    // The score with the adjustments and the late penalty, within [0, maxScore]: the one total
    // every output shows (pages, grades.csv, the LMS exports, results.json, progress lines).
    double total() const;
    double adjusted() const;  // the adjustments' points together

    Status status() const;  // the worst stage's (PASS when there is none)
    int exitCode() const { return exitCodeOf(status()); }
    // No row is NOT GRADED: the record is a score.
    bool graded() const { return status() != Status::NotGraded; }
};

// A stage as its student sees it: the rows neither hidden themselves nor in a hidden stage, their
// worst status, points and how many show the lesson. A count with hidden rows in it (a stage's
// "7 of 21 checks" beside 18 rows shown) would give their verdicts away, so whatever a student
// reads (the stage's message, their page) counts these only.
struct SeenStage {
    Status status = Status::Pass;  // PASS when no row is seen
    double points = 0, maxPoints = 0;
    int seen = 0, shown = 0;  // rows seen; of them, rows that show the lesson (earn points)
    int hidden = 0;           // rows left out
};
bool seenByStudent(const StageRecord& st, const RowRecord& row);
SeenStage seenStage(const StageRecord& st);
// Some of the record's points are in rows or stages the student does not see: then the total
// less the points they see is the hidden rows' points (with one hidden row, its verdict), so a
// student's page does not show it (the gradebook does, when the instructor releases it).
bool hidesPoints(const StudentRecord& record);

// A stage's record from its plan and, when it was rendered, its job's results (`got`; a job
// that gave no results is one row, whose status every row takes). MISSING stages need none.
// Messages lose the private snapshot's path (`overlay`): they name the student's own files.
StageRecord stageRecord(const StagePlan& p, const std::vector<CheckResult>* got,
                        const std::string& overlay);
// The record of `s` graded by `plan`: its stages' records, in the plan's order.
StudentRecord buildRecord(const GradingPlan& plan, const StudentWork& s,
                          const std::vector<StageRecord>& stages, double seconds);
// The record of a hand-in that could not be read (a refused zip): every due stage ERROR.
StudentRecord unreadableRecord(const GradingPlan& plan, const StudentWork& s);

// The public report (grade/formats.h: kReport): --report, the browser edition's report.
nlohmann::json recordJson(const StudentRecord& r);
// The record as kept (kKeptRecord): the report's fields plus its own name and version; what
// `grade` keeps per student and the solution check's parts carry between processes.
nlohmann::json keptRecordJson(const StudentRecord& r);
// The record keptRecordJson wrote. Throws FormatError (grade/formats.h) on another format or
// version, older() when an older shadowlab kept it; std::invalid_argument on a malformed one.
StudentRecord recordFromJson(const nlohmann::json& j);
// The record a public report holds (recordJson's: a student's own check handed in,
// grade/own_check.h): the same fields, read under the report's name and version; throws as
// recordFromJson does.
StudentRecord reportFromJson(const nlohmann::json& j);

// Counts over a record's rows, for summaries.
struct RowCounts {
    int total = 0, passed = 0, failed = 0, skipped = 0, missing = 0, errors = 0, notGraded = 0;
};
RowCounts countRows(const StudentRecord& r);

}  // namespace sl
