// Instructions per frame from valgrind's callgrind: a cost that repeats to a fraction of a
// percent on a loaded machine where milliseconds do not. Plain functions: the command line (no
// collection at start: sl::countedFrames in bench_run.h switches it on around the frames and
// dumps once per call) and the parsing of those dumps.
#pragma once

#include <string>

namespace sl {

// The shell command that runs `childArguments` (already quoted) of the executable `exe` under
// callgrind with llvmpipe single-threaded (LP_NUM_THREADS=0: every instruction of the
// rasteriser on the counted thread), writing dumps `outFile`.1, .2, ... one per counted call.
std::string callgrindCommand(const std::string& exe, const std::string& outFile,
                             const std::string& childArguments);

// Quotes one argument for a POSIX shell.
std::string shellQuote(const std::string& text);

// The instruction total of one callgrind output file ("totals:" or "summary:" line); -1 if none.
long long parseCallgrindTotal(const std::string& text);

// Instructions per frame from a dump's total over `frames` counted frames (NaN when unusable).
double instructionsPerFrame(long long total, int frames);

}  // namespace sl
