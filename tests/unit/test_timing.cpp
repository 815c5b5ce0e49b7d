#include <gtest/gtest.h>

#include "metrics/timing.h"

using sl::summarize;

TEST(Timing, MedianOfOddAndEvenCounts) {
    EXPECT_DOUBLE_EQ(summarize({5, 1, 3}).median, 3);
    EXPECT_DOUBLE_EQ(summarize({4, 1, 3, 2}).median, 2.5);
}

TEST(Timing, QuartilesAreNearestRank) {
    std::vector<double> v = {8, 1, 2, 3, 4, 5, 6, 7};  // sorted 1..8
    auto s = summarize(v);
    EXPECT_DOUBLE_EQ(s.min, 1);
    EXPECT_DOUBLE_EQ(s.max, 8);
    EXPECT_DOUBLE_EQ(s.p25, 2);  // rank ceil(0.25 * 8) = 2
    EXPECT_DOUBLE_EQ(s.p75, 6);  // rank 6
    EXPECT_DOUBLE_EQ(s.iqr(), 4);
    EXPECT_EQ(s.count, 8);
}

TEST(Timing, OneOutlierMovesNeitherMedianNorSpread) {
    std::vector<double> steady(20, 10.0);
    auto calm = summarize(steady);
    steady[7] = 500;  // a hiccup from a shared machine
    auto bumpy = summarize(steady);
    EXPECT_DOUBLE_EQ(calm.median, bumpy.median);
    EXPECT_DOUBLE_EQ(calm.iqr(), bumpy.iqr());
    EXPECT_DOUBLE_EQ(bumpy.max, 500);
}

TEST(Timing, EmptyListIsAllZero) {
    auto s = summarize({});
    EXPECT_EQ(s.count, 0);
    EXPECT_DOUBLE_EQ(s.median, 0);
    EXPECT_DOUBLE_EQ(sl::percentile({}, 0.5), 0);
}

TEST(Timing, PercentileClampsQ) {
    EXPECT_DOUBLE_EQ(sl::percentile({3, 1, 2}, -1), 1);
    EXPECT_DOUBLE_EQ(sl::percentile({3, 1, 2}, 2), 3);
}
