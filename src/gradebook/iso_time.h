// Times as instructors and Gradescope write them (the deadline, `--times`, `created_at`): a
// parser of its own, with no dependency, so the fuzzer (tests/fuzz) runs it alone.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace sl {

// Seconds since 1970-01-01 UTC of "YYYY-MM-DDTHH:MM[:SS[.fff]](Z|+HH:MM|-HH:MM|+HHMM)" (a space
// may stand for the T); nullopt for anything else, a time without a zone included.
// Only real times: a year from 1970, a day the month has (2026-11-31 and 2026-02-29 are none), a
// zone within
// +-14:00, a fraction of at most 9 digits, at most kMaxIsoTimeBytes in all.
constexpr std::size_t kMaxIsoTimeBytes = 40;
std::optional<long long> parseIsoTime(const std::string& text);
// "YYYY-MM-DDTHH:MM:SSZ".
std::string isoUtc(long long seconds);

}  // namespace sl
