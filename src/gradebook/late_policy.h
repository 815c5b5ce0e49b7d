// The late policy (docs/assignment.md "Late policy"): when a hand-in came, from a manifest
// (`grade --times times.csv`) or else its files' times, and what the assignment's policy
// (LatePolicy, below) takes off for it. Never a grade of its own: a record's
// `late` is applied when outputs are drawn (grades.csv's total and penalty, the page).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "grade/record.h"
#include "gradebook/iso_time.h"

namespace sl {

// The assignment's late policy ("late", docs/assignment.md "Late policy"): a hand-in after the
// deadline plus the grace loses penalty_per_day percent of the assignment's points for each day
// or part of a day after the deadline, at most cap percent, never below 0 points.
struct LatePolicy {
    std::string deadlineText;  // as written: ISO 8601 with its zone
    long long deadline = 0;    // seconds since 1970-01-01 UTC
    double graceMinutes = 0;
    double penaltyPerDayPct = 0;  // percent of the assignment's points per day late
    double capPct = 100;          // the most it loses, in percent of its points
};

// What `p` takes off a hand-in made at `handedIn` (from `source`): nothing within the grace;
// after it, penalty_per_day percent of `maxPoints` for each day or part of a day after the
// deadline, at most cap percent, and never more than `score`.
LateRecord lateFor(const LatePolicy& p, long long handedIn, const std::string& source,
                   double maxPoints, double score);

// `--times FILE`: a CSV with the header hand-in,time and one row per hand-in (ISO 8601 with a
// zone). Throws UsageError naming the file and the line (exit 2).
std::map<std::string, long long> loadTimes(const std::string& path);

// Hand-ins' file times that look like when the class was downloaded, not when each was handed
// in: at least two, every one after the deadline and its grace, all within kDownloadSpanSeconds
// (an LMS's download or an unzip writes every file within moments; students hand in over days).
constexpr long long kDownloadSpanSeconds = 30 * 60;
bool looksLikeDownload(const LatePolicy& p, const std::vector<long long>& fileTimes);

// The newest modification time of the hand-in at `path`: a zip's own, a folder's newest regular
// file (at most 10,000 entries looked at); nullopt when there is none.
std::optional<long long> newestFileTime(const std::string& path);

}  // namespace sl
