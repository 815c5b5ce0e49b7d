// The pages a class's grading writes (docs/assignment.md, "A class"): one self-contained page
// per student (every image embedded as a data: URI, so it can be mailed or uploaded) and the
// class page. Both read the student records of grade/record.h.
#pragma once

#include <string>
#include <vector>

#include "grade/record.h"

namespace sl {

// A row's figures in plain words for a student ("34.2 % of the surfaces that should be lit are
// drawn in shadow (acne?)"), after the verdict's own message.
std::string plainWords(const RowRecord& row);

// The student's page: per stage the status, points and message; one picture set per stage (the
// first visible row that lost points, else its first visible row): theirs, the truth and the
// diff with its legend, read from the row's images. A page is handed back once grades are out:
// hidden rows (and those of a hidden stage) are counted as hidden, never shown.
std::string studentPage(const StudentRecord& record);

// The class page: students by stages, coloured by points, each linked to `pageOf(student)`;
// per stage its most common failure and how many students had it; `skipped`: the class folder's
// entries left out ("NAME (why)"), listed so none is silently dropped.
std::string classPage(const std::string& assignment, const std::vector<StudentRecord>& records,
                      const std::vector<std::string>& pages,
                      const std::vector<std::string>& skipped = {});

// grades.csv (RFC 4180, CRLF): student, status, one column per due stage's points, total, max,
// and why a student is not graded (their NOT GRADED stages' cells, total and max left empty).
std::string gradesCsv(const std::vector<StudentRecord>& records);
// One CSV cell: quoted when needed, prefixed with ' when a spreadsheet would evaluate it.
std::string csvCell(const std::string& text);

// `bytes` as base64.
std::string base64(const std::string& bytes);

}  // namespace sl
