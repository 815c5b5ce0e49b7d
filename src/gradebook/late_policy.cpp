#include "gradebook/late_policy.h"

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "gradebook/csv.h"
#include "io/files.h"

namespace sl {

LateRecord lateFor(const LatePolicy& p, long long handedIn, const std::string& source,
                   double maxPoints, double score) {
    LateRecord r;
    r.handedIn = isoUtc(handedIn);
    r.source = source;
    const double minutes = double(handedIn - p.deadline) / 60.0;
    if (minutes <= p.graceMinutes) return r;  // on time, or within the grace
    r.minutes = minutes;
    r.days = int(std::ceil(minutes / 1440.0));
    r.capped = p.penaltyPerDayPct * r.days > p.capPct;
    const double pct = std::min(p.capPct, p.penaltyPerDayPct * r.days);
    r.penalty = std::min(std::max(score, 0.0), maxPoints * pct / 100.0);
    return r;
}

namespace {
// A value as a message shows it: on one line, at most 40 characters.
std::string shownValue(const std::string& value) {
    return printableName(value.size() > 40 ? value.substr(0, 37) + "..." : value);
}
}  // namespace

std::map<std::string, long long> loadTimes(const std::string& path) {
    std::vector<CsvRecord> rows = loadCsv(path, "--times", 100001);
    if (rows.empty())
        csvFail(path, 1, "empty: give a header row hand-in,time and a row per hand-in");
    const auto& head = rows.front().fields;
    if (head.size() != 2 || (head[0] != "hand-in" && head[0] != "hand_in") || head[1] != "time")
        csvFail(path, rows.front().line, "the header must be hand-in,time");
    std::map<std::string, long long> out;
    for (std::size_t k = 1; k < rows.size(); ++k) {
        const CsvRecord& r = rows[k];
        if (r.fields.size() != 2)
            csvFail(path, r.line,
                    std::to_string(r.fields.size()) + " fields, expected 2 (hand-in,time)");
        std::optional<long long> t = parseIsoTime(r.fields[1]);
        if (!t)
            csvFail(path, r.line,
                    "'" + shownValue(r.fields[1]) +
                        "' is not ISO 8601 with a zone within +-14:00 on a real date "
                        "(2026-12-04T23:59:00+01:00)");
        if (!out.emplace(r.fields[0], *t).second)
            csvFail(path, r.line, "hand-in '" + shownValue(r.fields[0]) + "' is listed twice");
    }
    return out;
}

bool looksLikeDownload(const LatePolicy& p, const std::vector<long long>& fileTimes) {
    if (fileTimes.size() < 2) return false;
    const auto [first, last] = std::minmax_element(fileTimes.begin(), fileTimes.end());
    const double lateAfter = double(p.deadline) + p.graceMinutes * 60.0;
    return double(*first) > lateAfter && *last - *first <= kDownloadSpanSeconds;
}

std::optional<long long> newestFileTime(const std::string& path) {
    namespace fs = std::filesystem;
    struct stat st;
    if (::lstat(path.c_str(), &st) != 0) return std::nullopt;
    if (S_ISREG(st.st_mode)) return st.st_mtime;
    if (!S_ISDIR(st.st_mode)) return std::nullopt;
    std::optional<long long> newest;
    std::error_code ec;
    int seen = 0;
    for (fs::recursive_directory_iterator it(path, ec), end; !ec && it != end && seen < 10000;
         it.increment(ec), ++seen) {
        struct stat f;
        if (::lstat(it->path().c_str(), &f) != 0 || !S_ISREG(f.st_mode)) continue;
        if (!newest || f.st_mtime > *newest) newest = f.st_mtime;
    }
    return newest;
}

}  // namespace sl
