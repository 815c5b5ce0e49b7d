// A student's own check report handed in beside the shaders (an assignment's
// "own_check_report"; the JSON `check --report` and the browser page's "download report" write)
// against the grade: row by row, paired by stage, tree, view and lesson. The report is never
// trusted and never a score (`grade` renders every row itself); what it is for is the rows where
// the student's machine said something else than ours: driver differences, or a report edited
// by hand. Anything wrong with it (not JSON, another tool, another version) is a problem, said
// in one line; rows of the grade's displaced views are compared only when the report's seed is
// the grade's.
#pragma once

#include <string>
#include <vector>

#include "grade/record.h"

namespace sl {

// `report` (as the intake set it aside) against `grade`, a record with its seed set.
OwnCheck compareOwnCheck(const HandInFile& report, const StudentRecord& grade);

// The notes a student and the instructor read of `o`, each naming the file: why it was not
// compared, or how many of its rows the grade has none like. None when all went well.
std::vector<std::string> ownCheckNotes(const OwnCheck& o);

// Sets `record.ownCheck` from `report` and adds its notes to the record's.
void attachOwnCheck(StudentRecord& record, const HandInFile& report);

}  // namespace sl
