// The late policy's arithmetic (gradebook/late_policy.h): ISO 8601 times with zones, the grace,
// days or parts of a day charged, the cap, never below 0 points.
#include <gtest/gtest.h>

#include "gradebook/late_policy.h"

namespace sl {
namespace {

TEST(LatePolicy, IsoTimesWithZones) {
    EXPECT_EQ(parseIsoTime("2026-12-04T23:59:00+01:00"), parseIsoTime("2026-12-04T22:59:00Z"));
    EXPECT_EQ(parseIsoTime("2026-12-04T22:59-0130"), parseIsoTime("2026-12-05 00:29:00.250Z"));
    EXPECT_EQ(*parseIsoTime("1970-01-02T00:00:00Z"), 86400);
    EXPECT_FALSE(parseIsoTime("2026-12-04T23:59:00"));  // no zone: which day is it?
    EXPECT_FALSE(parseIsoTime("2026-13-04T23:59:00Z"));
    EXPECT_FALSE(parseIsoTime("tomorrow"));
    EXPECT_EQ(isoUtc(*parseIsoTime("2026-12-04T23:59:00+01:00")), "2026-12-04T22:59:00Z");
}

TEST(LatePolicy, OneAndAHalfDaysLateLosesTwoDaysPoints) {
    LatePolicy p;
    p.deadline = *parseIsoTime("2026-12-04T23:59:00+01:00");
    p.graceMinutes = 15;
    p.penaltyPerDayPct = 10;
    p.capPct = 30;
    const long long hour = 3600;
    LateRecord late = lateFor(p, p.deadline + 36 * hour, "--times", 100, 90);
    EXPECT_EQ(late.days, 2);  // a day and a half: two days or parts of a day
    EXPECT_DOUBLE_EQ(late.minutes, 36 * 60);
    EXPECT_DOUBLE_EQ(late.penalty, 20);  // 2 x 10 % of 100 points
    EXPECT_DOUBLE_EQ(lateFor(p, p.deadline + 10 * 60, "", 100, 90).penalty, 0);  // in the grace
    EXPECT_EQ(lateFor(p, p.deadline + 10 * 60, "", 100, 90).days, 0);
    EXPECT_DOUBLE_EQ(lateFor(p, p.deadline - hour, "", 100, 90).penalty, 0);
    EXPECT_DOUBLE_EQ(lateFor(p, p.deadline + 16 * 60, "", 100, 90).penalty, 10);    // past it
    EXPECT_DOUBLE_EQ(lateFor(p, p.deadline + 96 * hour, "", 100, 90).penalty, 30);  // the cap
    EXPECT_DOUBLE_EQ(lateFor(p, p.deadline + 36 * hour, "", 100, 5).penalty, 5);    // not below 0
    EXPECT_FALSE(late.capped);                                             // 20 % is under the cap
    EXPECT_TRUE(lateFor(p, p.deadline + 96 * hour, "", 100, 90).capped);   // 40 % is over it
    EXPECT_FALSE(lateFor(p, p.deadline + 72 * hour, "", 100, 90).capped);  // 30 %: at it
}

// File times that look like a download (issue 39): all after the deadline within minutes.
TEST(LatePolicy, FileTimesOfADownloadAreTold) {
    LatePolicy p;
    p.deadline = *parseIsoTime("2026-12-04T23:59:00+01:00");
    p.graceMinutes = 15;
    const long long day = 86400, t = p.deadline + 3 * day;
    EXPECT_TRUE(looksLikeDownload(p, {t, t + 5, t + 40, t + 600}));
    EXPECT_TRUE(looksLikeDownload(p, {t, t + kDownloadSpanSeconds}));
    EXPECT_FALSE(looksLikeDownload(p, {t, t + kDownloadSpanSeconds + 1}));    // over a longer span
    EXPECT_FALSE(looksLikeDownload(p, {t, t + 5, p.deadline - 3600}));        // one on time
    EXPECT_FALSE(looksLikeDownload(p, {p.deadline + 60, p.deadline + 120}));  // within the grace
    EXPECT_FALSE(looksLikeDownload(p, {t}));  // one hand-in alone says nothing
    EXPECT_FALSE(looksLikeDownload(p, {}));
}

// Only real times (issue 38): a day the month has, a zone within +-14:00, a bounded fraction.
TEST(LatePolicy, OnlyRealDatesAndZones) {
    EXPECT_FALSE(parseIsoTime("2026-11-31T10:00:00Z"));  // November has 30 days
    EXPECT_FALSE(parseIsoTime("2026-02-29T10:00:00Z"));  // not a leap year
    EXPECT_TRUE(parseIsoTime("2028-02-29T10:00:00Z"));
    EXPECT_FALSE(parseIsoTime("2026-04-00T10:00:00Z"));
    EXPECT_FALSE(parseIsoTime("0026-02-28T12:00:00Z"));  // a typing error (the fuzzer's find)
    EXPECT_TRUE(parseIsoTime("1970-01-01T00:00:00Z"));
    EXPECT_FALSE(parseIsoTime("1970-01-01T00:30:00+01:00"));  // 1969 in UTC
    EXPECT_FALSE(parseIsoTime("2026-12-04T24:00:00Z"));
    EXPECT_FALSE(parseIsoTime("2026-12-04T23:59:00+99:99"));
    EXPECT_FALSE(parseIsoTime("2026-12-04T23:59:00-14:01"));
    EXPECT_FALSE(parseIsoTime("2026-12-04T23:59:00+01:60"));
    EXPECT_EQ(parseIsoTime("2026-12-04T23:59:00+14:00"), parseIsoTime("2026-12-04T09:59:00Z"));
    EXPECT_EQ(parseIsoTime("2026-12-04T23:59:00-1400"), parseIsoTime("2026-12-05T13:59:00Z"));
    EXPECT_EQ(parseIsoTime("2026-12-06T10:59:00.542003+00:00"),
              parseIsoTime("2026-12-06T10:59:00Z"));  // Gradescope's created_at
    EXPECT_FALSE(parseIsoTime("2026-12-04T23:59:00.Z"));
    EXPECT_FALSE(parseIsoTime("2026-12-04T23:59:00Zjunk"));
    EXPECT_FALSE(parseIsoTime("2026-12-04T23:59:00+01:00 "));
}

// 500,000 fractional digits: refused in one pass (a backtracking regular expression once
// overflowed the stack on it: SIGSEGV, for --times and Gradescope's created_at alike).
TEST(LatePolicy, AHugeFractionIsRefusedNotACrash) {
    EXPECT_FALSE(parseIsoTime("2026-12-04T23:59:00." + std::string(500000, '5') + "Z"));
    EXPECT_FALSE(parseIsoTime("2026-12-04T23:59:00.1234567890Z"));  // more than 9 digits
    EXPECT_FALSE(parseIsoTime(std::string(1000000, ' ')));
}

}  // namespace
}  // namespace sl
