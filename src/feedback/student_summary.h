// What a student's page says first and beside its pictures (feedback/feedback_html.h), drawn from
// the record's fields alone (statuses, points, missing files, expectations), never by reading
// its messages: a per-stage overview, so that an ERROR or TIMEOUT far down is seen at once, and
// the caption of a picture that shows a lesson working.
#pragma once

#include <string>

#include "grade/record.h"

namespace sl {

// The overview table: per stage the student sees, its status, points and the first thing to
// fix (linked to the stage's section). "" when no stage is shown.
std::string stagesSummary(const StudentRecord& record);

// The caption under a row's pictures: a passing row whose lesson's point is a visible fault
// (acne, inverted shadows: its expectation asks for at least some error) says the fault is
// the lesson working, not a mistake; "" for any other row.
std::string lessonCaption(const RowRecord& row);

// Why a TIMEOUT happens, in a student's words.
extern const char* const kTimeoutCause;

}  // namespace sl
