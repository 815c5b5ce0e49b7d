#include "course/late_policy.h"

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <regex>

#include "course/csv.h"
#include "io/files.h"

namespace sl {

std::optional<long long> parseIsoTime(const std::string& text) {
    static const std::regex iso(
        R"((\d{4})-(\d{2})-(\d{2})[T ](\d{2}):(\d{2})(?::(\d{2})(?:\.\d+)?)?(Z|z|([+-])(\d{2}):?(\d{2})))");
    std::smatch m;
    if (!std::regex_match(text, m, iso)) return std::nullopt;
    std::tm t{};
    t.tm_year = std::stoi(m[1]) - 1900;
    t.tm_mon = std::stoi(m[2]) - 1;
    t.tm_mday = std::stoi(m[3]);
    t.tm_hour = std::stoi(m[4]);
    t.tm_min = std::stoi(m[5]);
    t.tm_sec = m[6].matched ? std::stoi(m[6]) : 0;
    if (t.tm_mon > 11 || t.tm_mday < 1 || t.tm_mday > 31 || t.tm_hour > 23 || t.tm_min > 59 ||
        t.tm_sec > 60)
        return std::nullopt;
    long long seconds = ::timegm(&t);
    if (m[8].matched) {
        long long offset = std::stoll(m[9]) * 3600 + std::stoll(m[10]) * 60;
        seconds -= m[8] == "+" ? offset : -offset;  // local time = UTC + offset
    }
    return seconds;
}

std::string isoUtc(long long seconds) {
    std::time_t t = std::time_t(seconds);
    std::tm u{};
    ::gmtime_r(&t, &u);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &u);
    return text;
}

LateRecord lateFor(const LatePolicy& p, long long handedIn, const std::string& source,
                   double maxPoints, double score) {
    LateRecord r;
    r.handedIn = isoUtc(handedIn);
    r.source = source;
    const double minutes = double(handedIn - p.deadline) / 60.0;
    if (minutes <= p.graceMinutes) return r;  // on time, or within the grace
    r.minutes = minutes;
    r.days = int(std::ceil(minutes / 1440.0));
    const double pct = std::min(p.capPct, p.penaltyPerDayPct * r.days);
    r.penalty = std::min(std::max(score, 0.0), maxPoints * pct / 100.0);
    return r;
}

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
                    "'" + printableName(r.fields[1]) +
                        "' is not ISO 8601 with a zone (2026-12-04T23:59:00+01:00)");
        if (!out.emplace(r.fields[0], *t).second)
            csvFail(path, r.line, "hand-in '" + printableName(r.fields[0]) + "' is listed twice");
    }
    return out;
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
