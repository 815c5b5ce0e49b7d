// The class's totals in the CSV formats two LMS gradebooks import (docs/assignment.md
// "Gradebook exports"), written beside grades.csv by `grade`: Canvas's Gradebook import
// (Student, ID, SIS User ID, SIS Login ID, Section, then one column per assignment) and Moodle's
// CSV grade import (a column to identify the user by, mapped at import, and the grade item's
// column). Both hold the total after any late penalty; a student not graded has an empty cell.
#pragma once

#include <string>
#include <vector>

#include "grade/record.h"

namespace sl {

std::string canvasCsv(const std::string& assignment, const std::vector<StudentRecord>& records);
std::string moodleCsv(const std::string& assignment, const std::vector<StudentRecord>& records);

}  // namespace sl
