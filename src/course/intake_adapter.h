// A class's submission as the course grades it: a folder or a .zip (unpacked safely,
// course/archive.h), then issue 19's intake (grade/intake.h: wrapper folders descended, junk
// left out, near misses named, a private snapshot of the regular files). A hand-in that replaces
// no shipped file is not an error here: every due stage of it is MISSING with 0 points.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "course/assignment.h"
#include "grade/plan.h"

namespace sl {

// Reads the folder or .zip at `path` into a snapshot under `workDir` (created; emptied first).
// A zip, or a folder whose only entry (below lone wrapper folders) is a zip, is unpacked first.
// A full disk is the machine's failure: `error` says so and `platformFailure` is set (NOT
// GRADED, never a score). `stages`: the assignment's due stages, the only ones a near-miss note
// suggests; `listed`: the files it grades (a top-level file's note names only those); `ownReport`:
// the file name of the student's own check report, set aside (grade/intake.h), "" for none. Notes
// and the error name the hand-in by its own name, never by the instructor's paths (`path`,
// `workDir`).
StudentWork intakeSubmission(const std::string& path, const std::string& workDir,
                             const std::vector<std::string>& stages = {},
                             const std::set<std::string>& listed = {},
                             const std::string& ownReport = "");

// The hand-in at `path` read for `a`: near misses suggest only its due stages, and unlisted files
// of their folders are noted (course/student_grade.h unlistedFileNotes); the student's own check
// report set aside where the assignment names one (Assignment::ownCheckReport).
StudentWork intakeForAssignment(const Assignment& a, const std::string& path,
                                const std::string& workDir);

// The student's name for an entry of a class folder: its base name, without ".zip".
std::string submissionName(const std::string& path);

}  // namespace sl
