// Every output of a graded student drawn from the one record (grade/record.h): the terminal's
// lines, Gradescope's results.json, JUnit XML (docs/check.md, "Reports for graders"). Our own
// JSON report is recordJson itself; the exit code is the record's.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "grade/record.h"

namespace sl {

// A check's name in every grader's report: "stage/tree", plus the scene and each parameter
// that differs from the stage's defaults ("rgb/core margin=0.01", "hardware/core scene=lab").
std::string checkTestName(const CheckResult& r);
// The name of a graded row: the check's name and its view ("rgb/core/lecture margin=0.01").
std::string rowName(const RowRecord& row);

// What a grader shows for one row: the verdict and message, the lesson expected, the student's
// files, the figures and the diff image's name, one per line.
std::string rowOutput(const RowRecord& row);

// The terminal's table: a header, one line per row (name, figures, verdict, points, message).
std::string tableHeader();
std::string tableLine(const RowRecord& row);
// One line per stage with its status and points, then the total (or why there is none).
std::string stageSummary(const StudentRecord& r);

// Gradescope's results.json: one test per scored row with its points and visibility. What every
// student sees at once (the top-level output) names only visible stages and counts only their
// visible rows. NOT GRADED rows are no test: the output says they are not graded, and no
// "score" is given for a record that is not a score (run_autograder then fails the run, so
// Gradescope shows no grade and the instructor reruns it).
nlohmann::json gradescopeResults(const StudentRecord& r);

// JUnit XML: one <testcase> per row; FAIL and MISSING are a <failure>, ERROR, TIMEOUT, CRASH and
// NOT GRADED an <error>, SKIP <skipped>; points and visibility as properties. Text that is not
// valid UTF-8 or not allowed in XML is replaced by U+FFFD.
std::string junitXml(const StudentRecord& r);

// `text` as an XML attribute value (line breaks and tabs as character references) or, with
// `attribute` false, as character data: escaped, invalid bytes replaced.
std::string xmlEscaped(const std::string& text, bool attribute = true);

}  // namespace sl
