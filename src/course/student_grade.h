// One student graded by an assignment: the due stages handed in are checked (through the bounded
// workers of `check`), the others are MISSING with 0 points; each row earns its share of the
// stage's points when it shows its lesson. The result is one JSON record (docs/assignment.md,
// "The student's report"), which every output reads: the terminal table, Gradescope's
// results.json, JUnit, grades.csv and the feedback pages.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "course/assignment.h"
#include "course/intake_adapter.h"

namespace sl {

// What one student's grading runs: per due stage either its rows (handed in) or why it is
// MISSING.
struct StagePlan {
    const AssignmentStage* stage = nullptr;
    std::vector<RowPlan> rows;
    std::vector<std::string> missingFiles;  // non-empty: MISSING
};
std::vector<StagePlan> planStudent(const Assignment& a, const StudentWork& s,
                                   std::optional<std::uint64_t> seed);

// The checks of the stages handed in, one list per stage, for checkInWorkers.
std::vector<std::vector<CheckCase>> checksOf(const std::vector<StagePlan>& plan);

// The student's record, once every handed-in stage's results came back (`results[k]` for the
// k-th handed-in stage of `plan`, in order).
nlohmann::json studentRecord(const Assignment& a, const StudentWork& s,
                             const std::vector<StagePlan>& plan,
                             const std::vector<std::vector<CheckResult>>& results, double seconds);
// The record of a submission that could not be read (a refused zip): every due stage ERROR.
nlohmann::json unreadableRecord(const Assignment& a, const StudentWork& s);

// Gradescope's results.json for a record: one test per row with its points and visibility,
// the message, the figures and the diff image's name; MISSING stages one 0-point test each row.
nlohmann::json gradescopeResults(const nlohmann::json& record);
// JUnit XML: a testcase per row, points and visibility as properties.
std::string recordJunit(const nlohmann::json& record);
// The terminal's lines: one per stage with its points, then the total.
std::string recordSummary(const nlohmann::json& record);

}  // namespace sl
