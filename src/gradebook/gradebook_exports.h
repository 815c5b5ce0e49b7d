// The class's CSV files: grades.csv, and the totals in the CSV formats two LMS gradebooks import
// (docs/assignment.md "Gradebook exports"), written beside grades.csv by `grade`: Canvas's
// Gradebook import (Student, ID, SIS User ID, SIS Login ID, Section, then one column per
// assignment) and Moodle's CSV grade import (a column to identify the user by, mapped at import,
// and the grade item's column). Both hold the total after any late penalty; a student not graded
// has an empty cell.
#pragma once

#include <string>
#include <vector>

#include "grade/record.h"

namespace sl {

// grades.csv (RFC 4180, CRLF): student, roster id, name, email, status, one column per due
// stage's points, adjustments, late penalty, total, max, and why a student is not graded (their
// NOT GRADED stages' cells, total and max left empty).
std::string gradesCsv(const std::vector<StudentRecord>& records);
// One CSV cell: quoted when needed, prefixed with ' when a spreadsheet would evaluate it.
std::string csvCell(const std::string& text);

std::string canvasCsv(const std::string& assignment, const std::vector<StudentRecord>& records);
std::string moodleCsv(const std::string& assignment, const std::vector<StudentRecord>& records);

}  // namespace sl
