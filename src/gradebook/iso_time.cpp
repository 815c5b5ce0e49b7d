#include "gradebook/iso_time.h"

#include <algorithm>
#include <ctime>

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
    // Years from 1970 only: "0026" for 2026 is a typing error that would put a deadline twenty
    // centuries back (found by the fuzzer: it printed back as year 26).
    if (year < 1970 || month < 1 || month > 12 || day < 1 || text.size() < 16 || text[4] != '-' ||
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
    const long long utc = (long long)::timegm(&t) - offset;
    if (utc < 0) return std::nullopt;  // before 1970 in UTC (1970-01-01T00:30+01:00)
    return utc;
}

std::string isoUtc(long long seconds) {
    std::time_t t = std::time_t(seconds);
    std::tm u{};
    ::gmtime_r(&t, &u);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &u);
    return text;
}

}  // namespace sl
