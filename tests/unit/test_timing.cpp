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

TEST(Ratios, MedianAndQuartilesOfPerBlockRatios) {
    // Five blocks: ratios 1.1, 1.2, 1.3, 1.2, 1.0 -> sorted 1.0 1.1 1.2 1.2 1.3.
    auto r = sl::summarizeRatios({11, 12, 13, 12, 10}, {10, 10, 10, 10, 10});
    EXPECT_EQ(r.blocks, 5);
    EXPECT_DOUBLE_EQ(r.median, 1.2);
    EXPECT_DOUBLE_EQ(r.p25, 1.1);  // rank ceil(1.25) = 2
    EXPECT_DOUBLE_EQ(r.p75, 1.2);  // rank ceil(3.75) = 4
    EXPECT_NEAR(r.relativeSpread(), 0.1 / 1.2, 1e-12);
    EXPECT_TRUE(r.trusted());
}

TEST(Ratios, LoadThatHitsBothSidesOfABlockCancels) {
    // The machine slows down 3x halfway through: the per-block ratio stays 1.15 throughout, while
    // the ratio of pooled medians of unpaired runs would not.
    std::vector<double> config, base;
    for (int k = 0; k < 15; ++k) {
        double load = k < 7 ? 1.0 : 3.0;
        base.push_back(4.0 * load);
        config.push_back(4.6 * load);
    }
    auto r = sl::summarizeRatios(config, base);
    EXPECT_NEAR(r.median, 1.15, 1e-12);
    EXPECT_NEAR(r.iqr(), 0.0, 1e-12);
    EXPECT_TRUE(r.trusted());
}

TEST(Ratios, AWideSpreadIsNotTrusted) {
    auto r = sl::summarizeRatios({10, 14, 12, 16, 11, 13}, {10, 10, 10, 10, 10, 10});
    EXPECT_GT(r.relativeSpread(), 0.10);
    EXPECT_FALSE(r.trusted());
    EXPECT_TRUE(r.trusted(0.5));
}

TEST(Ratios, TooFewOrBrokenBlocks) {
    EXPECT_EQ(sl::summarizeRatios({}, {}).blocks, 0);
    EXPECT_TRUE(std::isnan(sl::summarizeRatios({}, {}).median));
    EXPECT_FALSE(sl::summarizeRatios({}, {}).trusted());
    // A zero or missing block is skipped, not divided by; unequal lengths use the shorter.
    auto r = sl::summarizeRatios({2, 3, 4, 9}, {1, 0, 2});
    EXPECT_EQ(r.blocks, 2);
    EXPECT_DOUBLE_EQ(r.median, 2.0);
    EXPECT_FALSE(r.trusted()) << "two blocks are too few to judge a spread";
}

TEST(Ratios, AbbaOrderAlternates) {
    EXPECT_FALSE(sl::configFirst(0));
    EXPECT_TRUE(sl::configFirst(1));
    EXPECT_FALSE(sl::configFirst(2));
    EXPECT_TRUE(sl::configFirst(3));
}
