// The one ordered status and the verdict from figures (grade/status.h, grade/judge.h): worst of
// works because the order is the exit code's, judge reads both sides of a bound and NaN.
#include <gtest/gtest.h>

#include <cmath>

#include "grade/judge.h"
#include "grade/status.h"

namespace sl {
namespace {

TEST(Status, OrderIsWorstLastAndExitCodesFollowIt) {
    const Status order[] = {Status::Pass,  Status::Skip,    Status::Fail,  Status::Missing,
                            Status::Error, Status::Timeout, Status::Crash, Status::NotGraded};
    int lastCode = 0;
    for (std::size_t k = 0; k < std::size(order); ++k) {
        for (std::size_t j = 0; j < std::size(order); ++j)
            EXPECT_EQ(worst(order[k], order[j]), order[std::max(k, j)]);
        // The exit code never falls as the status worsens: worst-of a record is its exit code.
        EXPECT_GE(exitCodeOf(order[k]), lastCode) << statusName(order[k]);
        lastCode = exitCodeOf(order[k]);
        EXPECT_EQ(statusFromName(statusName(order[k])), order[k]);
    }
    EXPECT_EQ(exitCodeOf(Status::Skip), 0);
    EXPECT_EQ(exitCodeOf(Status::Fail), 1);
    EXPECT_EQ(exitCodeOf(Status::Missing), 2);
    EXPECT_EQ(exitCodeOf(Status::Crash), 2);
    EXPECT_EQ(exitCodeOf(Status::NotGraded), 3);
    EXPECT_STREQ(statusName(Status::NotGraded), "NOT GRADED");
    EXPECT_FALSE(statusFromName("graded").has_value());
}

TEST(Status, OnlyPassAndSkipEarnAndNotGradedIsNoScore) {
    EXPECT_TRUE(earnsPoints(Status::Pass));
    EXPECT_TRUE(earnsPoints(Status::Skip));
    for (Status s : {Status::Fail, Status::Missing, Status::Error, Status::Timeout, Status::Crash,
                     Status::NotGraded})
        EXPECT_FALSE(earnsPoints(s)) << statusName(s);
    EXPECT_FALSE(isScored(Status::NotGraded));
    EXPECT_TRUE(isScored(Status::Crash));
}

TEST(Judge, ReadsBothSidesAndNaN) {
    Expectation noAcne;
    noAcne.stage = "margin";
    noAcne.outcome = "no acne";
    noAcne.limits = {{"false_shadow_pct", NAN, 1}, {"false_lit_pct", NAN, 5}};
    auto pass = judge(noAcne, {{"false_shadow_pct", 0.5}, {"false_lit_pct", 2.0}});
    EXPECT_EQ(pass.status, Status::Pass) << pass.message;
    auto fail = judge(noAcne, {{"false_shadow_pct", 49.0}, {"false_lit_pct", 0.1}});
    EXPECT_EQ(fail.status, Status::Fail);
    EXPECT_NE(fail.message.find("false_shadow_pct 49 not <= 1"), std::string::npos) << fail.message;
    auto skip = judge(noAcne, {{"false_shadow_pct", 0.5}, {"false_lit_pct", NAN}});
    EXPECT_EQ(skip.status, Status::Skip);
    auto failWins = judge(noAcne, {{"false_shadow_pct", 5.0}, {"false_lit_pct", NAN}});
    EXPECT_EQ(failWins.status, Status::Fail);
}

TEST(Judge, ADisplacedViewIsHeldToOursWhenTheBoundIsOutOfReach) {
    Expectation e;
    e.outcome = "correct";
    e.limits = {{"edge_p95_px", NAN, 2}, {"false_shadow_speckle_pct", 40, NAN}};
    // The solution measured 6 px at most over displaced views: theirs may be a quarter more.
    DisplacedFigures ours = {{"edge_p95_px", {3, 6}}};
    EXPECT_EQ(
        judgeDisplaced(e, {{"edge_p95_px", 7.4}, {"false_shadow_speckle_pct", 50}}, &ours).status,
        Status::Pass);
    EXPECT_EQ(
        judgeDisplaced(e, {{"edge_p95_px", 7.6}, {"false_shadow_speckle_pct", 50}}, &ours).status,
        Status::Fail);
    // Where ours meet the bound, the bound stands; without data, the lesson's bounds alone.
    DisplacedFigures within = {{"edge_p95_px", {0.5, 1}}};
    EXPECT_EQ(
        judgeDisplaced(e, {{"edge_p95_px", 2.4}, {"false_shadow_speckle_pct", 50}}, &within).status,
        Status::Fail);
    EXPECT_EQ(
        judgeDisplaced(e, {{"edge_p95_px", 2.4}, {"false_shadow_speckle_pct", 50}}, nullptr).status,
        Status::Fail);
    // A lower bound widens to the lowest the solution measured, less a quarter.
    DisplacedFigures speckle = {{"false_shadow_speckle_pct", {20, 60}}};
    EXPECT_EQ(judgeDisplaced(e, {{"edge_p95_px", 1}, {"false_shadow_speckle_pct", 15.5}}, &speckle)
                  .status,
              Status::Pass);
    EXPECT_EQ(judgeDisplaced(e, {{"edge_p95_px", 1}, {"false_shadow_speckle_pct", 14.5}}, &speckle)
                  .status,
              Status::Fail);
}

// A floor above 0 (the lesson's picture shows the figure) lowered to the solution's lowest never
// reaches 0 while the solution shows any: the inverted lesson asks for false shadow, and in a view
// where ours show 0.2 % a picture with none (no shadow drawn at all) would pass.
TEST(Judge, APositiveFloorLoweredStaysAboveZero) {
    Expectation e;
    e.outcome = "inverted";
    e.limits = {{"false_lit_pct", 99, NAN}, {"false_shadow_pct", 1, NAN}};
    DisplacedFigures ours = {{"false_lit_pct", {100, 100}}, {"false_shadow_pct", {0.681, 15.7}}};
    const std::map<std::string, double> here = {{"false_lit_pct", 100}, {"false_shadow_pct", 0.2}};
    const std::map<std::string, double> none = {{"false_lit_pct", 100}, {"false_shadow_pct", 0}};
    auto noShadow = judgeDisplaced(e, none, &ours, &here);
    EXPECT_EQ(noShadow.status, Status::Fail) << noShadow.message;
    const std::map<std::string, double> asOurs = {{"false_lit_pct", 100},
                                                  {"false_shadow_pct", 0.2}};
    EXPECT_EQ(judgeDisplaced(e, asOurs, &ours, &here).status, Status::Pass);
    const std::map<std::string, double> aQuarter = {{"false_lit_pct", 100},
                                                    {"false_shadow_pct", 0.06}};
    EXPECT_EQ(judgeDisplaced(e, aQuarter, &ours, &here).status, Status::Pass);
    // Where the solution shows none, none passes (the lesson does not show in that view).
    const std::map<std::string, double> oursNone = none;
    EXPECT_EQ(judgeDisplaced(e, none, &ours, &oursNone).status, Status::Pass);
}

// A floor under a figure near its best stands where the solution clears it: 36-41 dB of PSNR
// over displaced views against a floor of 32 dB must not become 27 dB (a quarter of 36).
TEST(Judge, AFloorTheSolutionClearsIsNotLowered) {
    Expectation e;
    e.outcome = "reflection right";
    e.limits = {{"mirror_psnr_db", 32, NAN}, {"mirror_id_pct", 95, NAN}};
    DisplacedFigures ours = {{"mirror_psnr_db", {36.28, 40.68}}, {"mirror_id_pct", {99.33, 99.65}}};
    auto sixtyFour = judgeDisplaced(e, {{"mirror_psnr_db", 30.1}, {"mirror_id_pct", 99.5}}, &ours);
    EXPECT_EQ(sixtyFour.status, Status::Fail) << sixtyFour.message;
    auto idsLost = judgeDisplaced(e, {{"mirror_psnr_db", 37}, {"mirror_id_pct", 80}}, &ours);
    EXPECT_EQ(idsLost.status, Status::Fail) << idsLost.message;
    EXPECT_EQ(judgeDisplaced(e, {{"mirror_psnr_db", 33}, {"mirror_id_pct", 99}}, &ours).status,
              Status::Pass);
}

// The verdict's reasons are data: one per side of each limit, with the value and the bound as
// held (a displaced view's widened one, a drawn row's from ours), so no page reads the message.
TEST(Judge, ReasonsAreEachSideAsHeld) {
    using Side = FigureReason::Side;
    Expectation e;
    e.outcome = "some acne";
    e.limits = {{"false_shadow_speckle_pct", 2, 40}, {"false_lit_pct", NAN, 5}};
    auto fail = judge(e, {{"false_shadow_speckle_pct", 50}, {"false_lit_pct", 1}});
    ASSERT_EQ(fail.status, Status::Fail);
    const std::vector<FigureReason> expected = {
        {"false_shadow_speckle_pct", 50, Side::AtLeast, 2, true},
        {"false_shadow_speckle_pct", 50, Side::AtMost, 40, false},
        {"false_lit_pct", 1, Side::AtMost, 5, true}};
    EXPECT_EQ(fail.reasons, expected);
    // Not measured: no value, passes neither side (the row is a SKIP).
    auto skip = judge(e, {{"false_shadow_speckle_pct", 10}});
    ASSERT_EQ(skip.status, Status::Skip);
    ASSERT_EQ(skip.reasons.size(), 3u);
    EXPECT_TRUE(std::isnan(skip.reasons[2].value));
    EXPECT_FALSE(skip.reasons[2].passed);
    EXPECT_TRUE(skip.reasons[0].passed && skip.reasons[1].passed);
    // A displaced view: the reason carries the widened bound (6 + a quarter = 7.5), not 2.
    Expectation edge;
    edge.limits = {{"edge_p95_px", NAN, 2}};
    DisplacedFigures ours = {{"edge_p95_px", {3, 6}}};
    auto displaced = judgeDisplaced(edge, {{"edge_p95_px", 7.6}}, &ours);
    const std::vector<FigureReason> widened = {{"edge_p95_px", 7.6, Side::AtMost, 7.5, false}};
    EXPECT_EQ(displaced.reasons, widened);
    // A drawn row: held to ours (4) within a factor 2.5 and 0.3, both sides.
    DrawnRow row;
    row.stage = "margin";
    row.tolerances = {{"false_shadow_pct", /*abs*/ 0.3, /*factor*/ 2.5}};
    auto drawn =
        judgeDrawn(row, "margin=0.0023", {{"false_shadow_pct", 0.05}}, {{"false_shadow_pct", 4.0}});
    ASSERT_EQ(drawn.reasons.size(), 2u);
    EXPECT_EQ(drawn.reasons[0].side, Side::AtLeast);
    EXPECT_DOUBLE_EQ(drawn.reasons[0].bound, 4.0 / 2.5 - 0.3);
    EXPECT_FALSE(drawn.reasons[0].passed);
    EXPECT_DOUBLE_EQ(drawn.reasons[1].bound, 4.0 * 2.5 + 0.3);
    EXPECT_TRUE(drawn.reasons[1].passed);
    EXPECT_EQ(sideFromName(sideName(Side::AtLeast)), Side::AtLeast);
    EXPECT_EQ(sideFromName(sideName(Side::AtMost)), Side::AtMost);
    EXPECT_FALSE(sideFromName("in").has_value());
}

}  // namespace
}  // namespace sl
