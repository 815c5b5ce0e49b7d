// The one ordered status of a graded row, a stage and a student (GUIDE section 6: piglit's
// lesson). Later is worse, so "worst of" is the larger: a stage's status is the worst of its
// rows', a student's the worst of their stages', and the exit code follows from it. The order:
//   PASS < SKIP < FAIL < MISSING < ERROR < TIMEOUT < CRASH < NOT GRADED
// PASS and SKIP lose nothing (exit 0); FAIL is a lesson not shown (exit 1); MISSING, ERROR,
// TIMEOUT and CRASH are the submission's (exit 2); NOT GRADED is the platform's, never a score
// (exit 3: rerun). docs/check.md ("Statuses") says the same for users.
#pragma once

#include <optional>
#include <string>

namespace sl {

enum class Status { Pass, Skip, Fail, Missing, Error, Timeout, Crash, NotGraded };

const char* statusName(Status s);  // "PASS", ..., "NOT GRADED"
std::optional<Status> statusFromName(const std::string& name);

inline Status worst(Status a, Status b) {
    return a < b ? b : a;
}

// 0 for PASS and SKIP, 1 for FAIL, 2 for the submission's faults, 3 for NOT GRADED.
int exitCodeOf(Status s);

// Whether a row with this status earns its points: PASS, and SKIP (nothing was judged, so
// nothing is lost; an assignment cannot plan a row that skips: docs/check.md).
bool earnsPoints(Status s);

// Whether the row is a score at all: a NOT GRADED row counts no points, earned or possible, in
// any output.
inline bool isScored(Status s) {
    return s != Status::NotGraded;
}

// The submission could not be judged (the row has no figures): MISSING, ERROR, TIMEOUT, CRASH,
// NOT GRADED.
inline bool unjudged(Status s) {
    return s >= Status::Missing;
}

}  // namespace sl
