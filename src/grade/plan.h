// What grading one student runs, planned before any GL work: per stage, its rows (a check
// case, the points it is worth, who sees it) or the files whose absence makes it MISSING. An
// assignment (course/assignment.h) plans its due stages; `check --stage/--all` plans a default
// one (grade/check_session.h): one path grades both.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "grade/check_run.h"

namespace sl {

struct RowPlan {
    CheckCase check;
    double points = 0;
    std::string visibility = "visible";  // Gradescope's names (visible, hidden, ...)
    bool extra = false;                  // an instructor's extra view
};

struct StagePlan {
    std::string stage, tree;                // "margin", "core"
    std::vector<std::string> files;         // what the stage needs from the student
    std::vector<std::string> missingFiles;  // of those, absent from the hand-in: MISSING
    double points = 0;
    std::string visibility = "visible";
    std::vector<RowPlan> rows;
    std::string skipped;  // why the stage is not rendered at all: every row SKIP ("" = it is)
    bool missing() const { return !missingFiles.empty(); }
    bool rendered() const { return !missing() && skipped.empty() && !rows.empty(); }
};

struct GradingPlan {
    std::string name;  // the assignment's name
    std::vector<StagePlan> stages;
};

// A file a hand-in may carry at its top level beside the shaders and that is never graded (the
// student's own check report, an assignment's "own_check_report"): set aside by the intake, not
// copied into the snapshot, read with a bound. `text` is its bytes, or `problem` why they could
// not be read ("it has more than N bytes").
struct HandInFile {
    std::string name, text, problem;
};

// A student's hand-in as it was taken in (grade/intake.h; course/intake_adapter.h for zips):
// the private snapshot graded, its files, what the intake noticed.
struct StudentWork {
    std::string name;                // the hand-in's name: a folder's name or a zip's stem
    std::string overlay;             // the private snapshot to grade ("" when refused)
    std::vector<std::string> files;  // relative paths of the student's regular files in it
    std::vector<std::string> notes;  // wrapper folders descended, near misses, links skipped, ...
    std::string error;               // why the submission could not be read at all ("" = ok)
    bool platformFailure = false;    // `error` is the grading machine's (a full disk): NOT GRADED
    std::string hash;                // the content hash of the snapshot's files ("" = none)
    std::optional<HandInFile> ownReport;  // the student's own check report, when handed in
    bool has(const std::string& rel) const;
};

}  // namespace sl
