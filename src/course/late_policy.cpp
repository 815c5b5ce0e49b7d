#include "course/late_policy.h"

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <filesystem>

#include "course/csv.h"
#include "io/files.h"

namespace sl {

namespace {

// The value of text[at, at + n) when all n are ASCII digits, else -1.
int digitsAt(const std::string& text, std::size_t at, std::size_t n) {
    if (at + n > text.size()) return -1;
    int v = 0;
    for (std::size_t k = at; k < at + n; ++k) {
        if (text[k] < '0' || text[k] > '9') return -1;
        v = v * 10 + (text[k] - '0');
    }
    return v;
}

int daysIn(int year, int month) {
    static const int days[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
    return month == 2 && leap ? 29 : days[month - 1];
}

}  // namespace

std::optional<long long> parseIsoTime(const std::string& text) {
    // Read left to right, at fixed places: no backtracking, so no length can exhaust the stack.
    if (text.size() > kMaxIsoTimeBytes) return std::nullopt;
    const int year = digitsAt(text, 0, 4), month = digitsAt(text, 5, 2), day = digitsAt(text, 8, 2);
    if (year < 0 || month < 1 || month > 12 || day < 1 || text.size() < 16 || text[4] != '-' ||
        text[7] != '-' || (text[10] != 'T' && text[10] != ' ') || text[13] != ':')
        return std::nullopt;
    if (day > daysIn(year, month)) return std::nullopt;  // 2026-11-31 is no day
    const int hour = digitsAt(text, 11, 2), minute = digitsAt(text, 14, 2);
    int second = 0;
    std::size_t at = 16;
    if (at < text.size() && text[at] == ':') {
        second = digitsAt(text, at + 1, 2);
        at += 3;
        if (at < text.size() && text[at] == '.') {  // a fraction: 1 to 9 digits, ignored
            std::size_t digits = 0;
            while (at + 1 + digits < text.size() && digitsAt(text, at + 1 + digits, 1) >= 0)
                ++digits;
            if (digits < 1 || digits > 9) return std::nullopt;
            at += 1 + digits;
        }
    }
    if (hour < 0 || hour > 23 || minute < 0 || minute > 59 || second < 0 || second > 60)
        return std::nullopt;
    long long offset = 0;  // local time = UTC + offset
    const std::string zone = text.substr(std::min(at, text.size()));
    if (zone != "Z" && zone != "z") {
        const bool colon = zone.size() == 6 && zone[3] == ':';
        if ((zone.size() != 5 && !colon) || (zone[0] != '+' && zone[0] != '-')) return std::nullopt;
        const int hh = digitsAt(zone, 1, 2), mm = digitsAt(zone, colon ? 4 : 3, 2);
        // Zones on Earth lie within +-14:00: +99:99 is a typing error, not a place.
        if (hh < 0 || mm < 0 || mm > 59 || hh * 60 + mm > 14 * 60) return std::nullopt;
        offset = (zone[0] == '+' ? 1 : -1) * (hh * 3600LL + mm * 60LL);
    }
    std::tm t{};
    t.tm_year = year - 1900;
    t.tm_mon = month - 1;
    t.tm_mday = day;
    t.tm_hour = hour;
    t.tm_min = minute;
    t.tm_sec = second;
    return (long long)::timegm(&t) - offset;
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
