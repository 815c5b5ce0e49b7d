// The late policy's arithmetic (course/late_policy.h): ISO 8601 times with zones, the grace, days
// or parts of a day charged, the cap, never below 0 points.
#include <gtest/gtest.h>

#include "course/late_policy.h"

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
}

}  // namespace
}  // namespace sl
