// Bounds on what grading writes: a row's message, a note, a worker's error. A student's shader
// can make the compiler say anything, as long as it likes (an include that pastes a long line a
// thousand times); every such text is cut here, saying how much was cut, so reports, JUnit files
// and the terminal stay small whatever the submission.
#pragma once

#include <string>
#include <vector>

#include "io/files.h"  // capped, kMaxErrorText

namespace sl {

constexpr std::size_t kMaxRowMessage = 4096;       // a report row's message or note
constexpr std::size_t kMaxInheritedMessage = 512;  // a row's copy of its stage's failure
constexpr std::size_t kMaxListedFiles = 32;        // student files named on one row
// A row's reasons (grade/judge.h): one per side of a lesson's limits, so at most two per figure
// of the table (13 today); a worker's row with more is cut here, each figure's name to 64 bytes.
constexpr std::size_t kMaxReasons = 32;
constexpr std::size_t kMaxReasonFigure = 64;

// The first `kMaxListedFiles` of `files`, each capped, and "... and N more" when there were more.
std::vector<std::string> cappedList(const std::vector<std::string>& files);

}  // namespace sl
