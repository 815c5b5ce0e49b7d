// The check's results in the formats graders load: Gradescope's autograder results.json and
// JUnit XML (docs/check.md, "Reports for graders"). Both read the same CheckResults as our own
// report; one test per check, named by checkTestName.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "grade/check_run.h"

namespace sl {

// A check's name in every grader's report: "stage/tree", plus the scene and each parameter
// that differs from the stage's defaults ("rgb/core margin=0.01", "hardware/core scene=lab").
std::string checkTestName(const CheckResult& r);

// What a grader shows for one check: the message, the verdict and the lesson expected, the
// figures and the diff image's path, one per line.
std::string checkTestOutput(const CheckResult& r);

// Gradescope's results.json: one test per check, 1 point when it passes (a SKIP is worth 0 of 0
// and shown as passed), "status" passed or failed, the overall score the sum.
nlohmann::json gradescopeJson(const std::vector<CheckResult>& results, double seconds);

// JUnit XML: <testsuites><testsuite> with one <testcase> per check; FAIL is a <failure>, ERROR,
// TIMEOUT and CRASH an <error>, SKIP <skipped>. Text that is not valid UTF-8 or not allowed in
// XML is replaced by U+FFFD.
std::string junitXml(const std::vector<CheckResult>& results, double seconds);

// `text` as an XML attribute value (line breaks and tabs as character references) or, with
// `attribute` false, as character data: escaped, invalid bytes replaced.
std::string xmlEscaped(const std::string& text, bool attribute = true);

}  // namespace sl
