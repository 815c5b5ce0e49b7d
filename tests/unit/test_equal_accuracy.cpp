#include <gtest/gtest.h>

#include <cmath>

#include "metrics/equal_accuracy.h"

using namespace sl;

TEST(EqualAccuracy, TheBarNeedsBothFigures) {
    AccuracyBar bar;  // edge p95 <= 2 px, error <= 0.1 %
    EXPECT_TRUE(meetsBar({"m", "", 2.0, 0.1, 1}, bar));
    EXPECT_FALSE(meetsBar({"m", "", 2.1, 0.01, 1}, bar));
    EXPECT_FALSE(meetsBar({"m", "", 1.0, 0.11, 1}, bar));
    EXPECT_FALSE(meetsBar({"m", "", NAN, 0.01, 1}, bar)) << "an undefined edge does not pass";
}

TEST(EqualAccuracy, CheapestPassingPerMethodInOrderOfAppearance) {
    std::vector<Candidate> c = {
        {"hardware", "map-size=256", 3.0, 0.05, 1.0},   // too blurry
        {"hardware", "map-size=512", 1.5, 0.05, 1.2},   // passes
        {"hardware", "map-size=1024", 1.0, 0.02, 1.6},  // passes, dearer
        {"peers", "map-size=512", 1.9, 0.09, 1.1},      // passes
        {"peers", "map-size=256", 1.8, 0.08, 1.1},      // passes, same cost: the first stays
    };
    auto v = cheapestAtEqualAccuracy(c, AccuracyBar{});
    ASSERT_EQ(v.size(), 2u);
    EXPECT_EQ(v[0].method, "hardware");
    EXPECT_EQ(v[0].cheapest, 1u);
    EXPECT_EQ(v[1].method, "peers");
    EXPECT_EQ(v[1].cheapest, 3u);
}

TEST(EqualAccuracy, NoneReachesTheBarSaysWhichCameClosest) {
    std::vector<Candidate> c = {
        {"margin", "a", 60, 0.4, 1.0},
        {"margin", "b", 58, 0.3, 2.0},
        {"margin", "c", NAN, NAN, 0.5},
    };
    auto v = cheapestAtEqualAccuracy(c, AccuracyBar{});
    ASSERT_EQ(v.size(), 1u);
    EXPECT_FALSE(v[0].cheapest.has_value());
    EXPECT_EQ(v[0].closest, 1u);
}

TEST(EqualAccuracy, AnUnknownCostIsNeverTheCheapest) {
    std::vector<Candidate> c = {{"m", "a", 1, 0.01, NAN}, {"m", "b", 1, 0.01, 3.0}};
    EXPECT_EQ(cheapestAtEqualAccuracy(c, AccuracyBar{})[0].cheapest, 1u);
}
