// The student's page a class's grading writes (docs/assignment.md, "A class"): one
// self-contained page per student (every image embedded as a data: URI, so it can be mailed or
// uploaded), drawn from the student's record (grade/record.h). The class page: class_page.h.
#pragma once

#include <string>
#include <vector>

#include "grade/record.h"

namespace sl {

// A row's figures in plain words for a student ("34.2 % of the surfaces the light reaches are
// drawn in shadow; ..."), and for a row that does not show the lesson each bound it missed, from
// the row's reasons (grade/judge.h) in the figure table's words and units: "your mirror's PSNR
// against the exact (stencil) reflection is 18.7 dB, and should be at least 32 dB". The message
// is never parsed: a row without reasons (a record kept before they existed) shows its message.
std::string plainWords(const RowRecord& row);

// The student's page: per stage the status, points and message; one picture set per stage (the
// first visible row that lost points, else its first visible row): theirs, the truth and the
// diff with its legend, read from the row's images. A page is handed back once grades are out:
// hidden rows (and those of a hidden stage) are counted as hidden, never shown.
std::string studentPage(const StudentRecord& record);

// `bytes` as base64.
std::string base64(const std::string& bytes);

}  // namespace sl
