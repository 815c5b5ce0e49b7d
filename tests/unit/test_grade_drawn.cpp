// Rows whose method parameters the seed draws (stages/drawn.h) and their judgement against our
// shaders at the same values (grade/judge.h): the draw is the seed's alone and stays in range,
// the data file's mistakes name the entry, --set values inside a row's ranges find the row, and
// a figure off ours by more than the tolerance fails whatever the lesson's bounds would allow.
#include <gtest/gtest.h>

#include <cstdlib>
#include <set>

#include "grade/check_run.h"
#include "grade/judge.h"
#include "stages/drawn.h"
#include "stages/stage.h"

namespace sl {
namespace {

void useSourceTree() {
    setenv("SHADOWLAB_DATA_DIR", SHADOWLAB_SOURCE_DIR, 1);
}

ParamSet valuesOf(const std::string& stage,
                  const std::vector<std::pair<std::string, std::string>>& sets) {
    ParamSet values(findStage(stage)->params);
    for (const auto& [name, value] : sets) EXPECT_EQ(values.set(name, value), "") << name;
    return values;
}

TEST(Drawn, EveryShippedRowDrawsInRangeAndIsFoundAgain) {
    useSourceTree();
    ASSERT_FALSE(drawnRows().empty());
    for (const DrawnRow& row : drawnRows())
        for (std::uint64_t seed : {0ull, 7ull, 123456789012ull}) {
            auto sets = drawnSettings(row, seed);
            EXPECT_EQ(sets, drawnSettings(row, seed)) << "the seed alone decides";
            ParamSet values = valuesOf(row.stage, sets);
            for (const DrawnParam& d : row.draw)
                if (d.choices.empty()) {
                    EXPECT_GE(values.number(d.name), d.min) << row.label();
                    EXPECT_LE(values.number(d.name), d.max) << row.label();
                }
            std::string scene = row.scene.empty() ? defaultSceneOf(row.stage) : row.scene;
            // An entry's second row is judged alone by its first's band (the same ranges).
            const DrawnRow* judgedBy = row.response ? pairedRowOf(row) : &row;
            ASSERT_NE(judgedBy, nullptr) << row.label();
            for (const char* tree : {"core", "legacy"})
                if (!drawnRowsOf(row.stage, tree).empty())
                    EXPECT_EQ(drawnRowFor(row.stage, scene, tree, values), judgedBy) << row.label();
        }
}

TEST(Drawn, SeedsDrawDifferentValues) {
    useSourceTree();
    for (const DrawnRow& row : drawnRows()) {
        std::set<std::vector<std::pair<std::string, std::string>>> seen;
        for (std::uint64_t seed = 1; seed <= 20; ++seed) seen.insert(drawnSettings(row, seed));
        EXPECT_GE(seen.size(), 10u) << row.label() << ": no constant covers the drawn rows";
    }
}

// A drawn number is never one a lesson or the default names: a shader that recognises the
// packed lesson by textureSize == 2048 passed whenever the seed drew 2048 (1 in 29 runs).
TEST(Drawn, NeverAValueALessonNames) {
    useSourceTree();
    for (const DrawnRow& row : drawnRows()) {
        ParamSet defaults(findStage(row.stage)->params);
        for (const DrawnParam& d : row.draw) {
            if (!d.choices.empty()) continue;
            std::set<double> named = {defaults.number(d.name)};
            for (const Expectation& e : expectations())
                for (const auto& [name, value] : e.set)
                    if (e.stage == row.stage && name == d.name) named.insert(std::stod(value));
            int inRange = 0;
            for (double v : named) inRange += v >= d.min && v <= d.max;
            for (std::uint64_t seed = 0; seed < 400; ++seed)
                for (const auto& [name, value] : drawnSettings(row, seed))
                    if (name == d.name)
                        EXPECT_EQ(named.count(std::stod(value)), 0u)
                            << row.label() << " seed " << seed << " drew " << name << "=" << value
                            << ", a lesson's value (" << inRange << " such in range)";
        }
    }
}

TEST(Drawn, SettingsOutsideTheRangesFindNoRow) {
    useSourceTree();
    const DrawnRow* row = drawnRowsOf("margin", "core").front();
    auto sets = drawnSettings(*row, 3);
    ParamSet values = valuesOf("margin", sets);
    ASSERT_EQ(drawnRowFor("margin", "slides", "core", values), row);
    ParamSet other = values;
    other.set("storage", "depth16");  // a parameter the row neither sets nor draws
    EXPECT_EQ(drawnRowFor("margin", "slides", "core", other), nullptr);
    EXPECT_EQ(drawnRowFor("margin", "lab", "core", values), nullptr);
    for (const DrawnParam& d : row->draw)
        if (d.choices.empty()) {
            ParamSet out = values;
            const bool integer = out.find(d.name)->kind == ParamKind::Integer;
            std::string above = integer ? std::to_string(static_cast<long long>(d.max) + 64)
                                        : std::to_string(d.max * 1.5);
            ASSERT_EQ(out.set(d.name, above), "") << d.name;
            EXPECT_EQ(drawnRowFor("margin", "slides", "core", out), nullptr) << d.name;
        }
}

TEST(Drawn, MistakesNameTheEntry) {
    auto error = [](const std::string& drawn) {
        try {
            parseDrawnRows("{\"drawn\": [" + drawn + "]}", "X.json");
        } catch (const ExpectationError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const std::string tol =
        R"("tolerance": {"false_shadow_pct": {"abs": 0.3, "factor": 2}}, "why": "w")";
    EXPECT_NE(error(R"({"stage": "margin", "draw": {"margin": [0.05, 0.01]}, )" + tol + "}")
                  .find("X.json: drawn[0]: draw.margin"),
              std::string::npos);
    EXPECT_NE(
        error(R"({"stage": "margin", "draw": {"margin": [0.0, 0.5]}, )" + tol + "}").find("within"),
        std::string::npos);
    EXPECT_NE(error(R"({"stage": "margin", "draw": {"nope": [0.0, 0.05]}, )" + tol + "}")
                  .find("no parameter 'nope'"),
              std::string::npos);
    EXPECT_NE(error(R"({"stage": "margin", "draw": {"storage": ["rgb8", "depth99"]}, )" + tol + "}")
                  .find("depth99"),
              std::string::npos);
    EXPECT_NE(error(R"({"stage": "margin", "draw": {"margin": [0.0, 0.05]}, "why": "w"})")
                  .find("tolerance"),
              std::string::npos);
    EXPECT_EQ(error(R"({"stage": "margin", "draw": {"margin": [0.0, 0.05]}, )" + tol + "}"),
              "no error");
}

TEST(Drawn, JudgedAgainstOursNotTheLessonsBounds) {
    DrawnRow row;
    row.stage = "margin";
    row.draw = {{"margin", 0.002, 0.03, {}}};
    row.tolerances = {{"false_shadow_pct", 0.3, 2.5}, {"false_lit_pct", 0.3, 2.5}};
    const std::map<std::string, double> ours = {{"false_shadow_pct", 4.0}, {"false_lit_pct", 0.0}};
    // Within a factor 2.5 of ours, 0.3 more: [1.3, 10.3].
    Judgement near =
        judgeDrawn(row, "margin=0.0023", {{"false_shadow_pct", 9.9}, {"false_lit_pct", 0.2}}, ours);
    EXPECT_EQ(near.status, Status::Pass) << near.message;
    EXPECT_NE(near.message.find("margin=0.0023"), std::string::npos);
    // A clean picture where ours shows acne fails, though any lesson's "correct" bounds hold it.
    Judgement clean = judgeDrawn(row, "margin=0.0023",
                                 {{"false_shadow_pct", 0.05}, {"false_lit_pct", 0.0}}, ours);
    EXPECT_EQ(clean.status, Status::Fail) << clean.message;
    EXPECT_NE(clean.message.find("false_shadow_pct 0.05 not in [1.3, 10.3]"), std::string::npos)
        << clean.message;
    Judgement none = judgeDrawn(row, "", {{"false_shadow_pct", 1.0}}, {});
    EXPECT_EQ(none.status, Status::Skip);
}

// An entry's second row (its "response"): the first row's values but one, moved by a ratio the
// seed draws, inside the range, to the same digits.
TEST(Drawn, ASecondRowMovesOneValueByTheDrawnRatio) {
    useSourceTree();
    int pairs = 0;
    for (const DrawnRow& row : drawnRows()) {
        if (!row.response) continue;
        ++pairs;
        const DrawnRow* first = pairedRowOf(row);
        ASSERT_NE(first, nullptr) << row.label();
        EXPECT_EQ(first->response, std::nullopt);
        EXPECT_NE(row.label(), first->label()) << "its own row of shipped figures";
        const DrawnParam* d = nullptr;
        for (const DrawnParam& p : row.draw)
            if (p.name == row.response->param) d = &p;
        ASSERT_NE(d, nullptr);
        std::set<std::string> moved;
        for (std::uint64_t seed = 0; seed < 200; ++seed) {
            auto a = drawnSettings(*first, seed), b = drawnSettings(row, seed);
            ASSERT_EQ(a.size(), b.size());
            for (std::size_t k = 0; k < a.size(); ++k) {
                EXPECT_EQ(a[k].first, b[k].first);
                if (a[k].first != row.response->param) {
                    EXPECT_EQ(a[k].second, b[k].second) << "only the response's parameter moves";
                    continue;
                }
                const double from = std::stod(a[k].second), to = std::stod(b[k].second);
                const double ratio = std::max(from, to) / std::min(from, to);
                // Two significant digits: the ratio of rounded values strays a little.
                EXPECT_GE(ratio, row.response->ratioMin * 0.9) << a[k].second << " " << b[k].second;
                EXPECT_LE(ratio, row.response->ratioMax * 1.1) << a[k].second << " " << b[k].second;
                EXPECT_GE(to, d->min);
                EXPECT_LE(to, d->max);
                moved.insert(b[k].second);
            }
        }
        EXPECT_GE(moved.size(), 20u) << "no constant covers the second rows";
    }
    EXPECT_GE(pairs, 1) << "expectations.json has a drawn entry with a response";
}

TEST(Drawn, AResponseMistakeNamesTheEntry) {
    auto error = [](const std::string& response) {
        try {
            parseDrawnRows(R"({"drawn": [{"stage": "depth", "draw": {"margin": [0.0001, 0.0008]},
                "tolerance": {"false_shadow_pct": {"abs": 0.3, "factor": 2.5}}, "why": "w",
                "response": )" +
                               response + "}]}",
                           "X.json");
        } catch (const ExpectationError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const std::string ok =
        R"({"param": "margin", "ratio": [1.6, 2.5], "figure": "false_shadow_pct", "abs": 0.3,
            "factor": 2.5})";
    EXPECT_EQ(error(ok), "no error");
    EXPECT_NE(error(R"({"param": "margin"})").find("X.json: drawn[0]: response: must be"),
              std::string::npos);
    std::string notDrawn = ok;
    notDrawn.replace(notDrawn.find("\"margin\""), 8, "\"map-size\"");
    EXPECT_NE(error(notDrawn).find("'map-size' is not a number the entry draws"), std::string::npos)
        << error(notDrawn);
    std::string wide = ok;  // 3^2 = 9 > 0.0008 / 0.0001: the moved value could leave the range
    wide.replace(wide.find("2.5]"), 3, "3.0");
    EXPECT_NE(error(wide).find("twice over"), std::string::npos) << error(wide);
    std::string figure = ok;
    figure.replace(figure.find("false_shadow_pct"), 16, "false_lit_pct");
    EXPECT_NE(error(figure).find("not one the entry's tolerance names"), std::string::npos);
}

// The pair's rule on synthetic figures: ours drops from 30 % to 20 % of false shadow between the
// two margins (change -10, so theirs within [-10 * 2.5 - 0.3, -10 / 2.5 + 0.3] = [-25.3, -3.7]).
TEST(Drawn, APairIsJudgedByHowThePictureResponds) {
    DrawnResponse response{"margin", 1.6, 2.5, {"false_shadow_pct", 0.3, 2.5}};
    auto fs = [](double v) { return std::map<std::string, double>{{"false_shadow_pct", v}}; };
    auto pair = [&](double theirsFirst, double theirsSecond) {
        return judgeResponse(response, "margin=0.0003", fs(theirsFirst), fs(theirsSecond), fs(30),
                             fs(20));
    };
    const Judgement ours = pair(30, 20);
    EXPECT_EQ(ours.status, Status::Pass) << ours.message;
    ASSERT_EQ(ours.reasons.size(), 2u);
    EXPECT_EQ(ours.reasons[0].figure, "false_shadow_pct");
    EXPECT_EQ(ours.reasons[0].changeFrom, "margin=0.0003");
    EXPECT_DOUBLE_EQ(ours.reasons[0].bound, -25.3);
    EXPECT_DOUBLE_EQ(ours.reasons[1].bound, -3.7);
    // A constant margin: the same picture at both values, each near ours on its own.
    const Judgement constant = pair(25, 25);
    EXPECT_EQ(constant.status, Status::Fail) << constant.message;
    EXPECT_NE(constant.message.find("false_shadow_pct change from margin=0.0003 0 not in "
                                    "[-25.3, -3.7]"),
              std::string::npos)
        << constant.message;
    // A valid formulation with half our acne at both values responds half as much.
    EXPECT_EQ(pair(15, 10).status, Status::Pass);
    // A quantizer whose threshold lies between the two values jumps far more than ours.
    EXPECT_EQ(pair(40, 0.5).status, Status::Fail);
    // Ours the other way round (the second value smaller): the band mirrors.
    EXPECT_EQ(judgeResponse(response, "margin=0.0003", fs(20), fs(30), fs(20), fs(30)).status,
              Status::Pass);
    EXPECT_EQ(judgeResponse(response, "margin=0.0003", fs(25), fs(25), fs(20), fs(30)).status,
              Status::Fail);
    // Ours hardly changes (0.5 <= 2.5 * 0.3): no pair of pictures tells a constant apart.
    const Judgement flat =
        judgeResponse(response, "margin=0.0003", fs(25), fs(25), fs(20), fs(20.5));
    EXPECT_EQ(flat.status, Status::Skip) << flat.message;
    EXPECT_NE(flat.message.find("not judged"), std::string::npos);
}

TEST(Drawn, ASecondRowFailsWhenItsPairFails) {
    const Judgement own{Status::Pass,
                        "our shaders' picture as expected: ...",
                        {{"false_shadow_pct", 25, FigureReason::Side::AtMost, 50, true}}};
    const Judgement failed{
        Status::Fail,
        "expected our shaders' response to margin, but ...",
        {{"false_shadow_pct", 0, FigureReason::Side::AtMost, -3.7, false, "margin=0.0003"}}};
    const Judgement both = withResponse(own, failed);
    EXPECT_EQ(both.status, Status::Fail);
    EXPECT_EQ(both.reasons.size(), 2u) << "the page names the pair's figure";
    EXPECT_EQ(both.message.find("expected our shaders' response"), 0u) << both.message;
    EXPECT_EQ(withResponse(own, {Status::Pass, "as expected", own.reasons}).status, Status::Pass);
    const Judgement notJudged = withResponse(own, {Status::Skip, "response not judged: ...", {}});
    EXPECT_EQ(notJudged.status, Status::Pass) << "the row's own verdict stands";
    EXPECT_NE(notJudged.message.find("[response not judged"), std::string::npos);
    EXPECT_EQ(withResponse({Status::Skip, "none", {}}, failed).status, Status::Skip);
}

TEST(Drawn, CheckAddsOneDrawnRowPerEntryOnlyWithASeed) {
    useSourceTree();
    RenderRequest base;
    base.stage = "margin";
    base.overlay = "submission";
    std::size_t drawn = drawnRowsOf("margin", "core").size();
    auto count = [](const std::vector<CheckCase>& cases) {
        std::size_t n = 0;
        for (const CheckCase& c : cases) n += c.view == "drawn";
        return n;
    };
    EXPECT_EQ(count(checkCases(base, false, false, 42)), drawn);
    EXPECT_EQ(count(checkCases(base, false, false, std::nullopt)), 0u);
    EXPECT_EQ(count(checkCases(base, true, false, 42)), 0u) << "--set narrows to the user's";
    RenderRequest ours = base;
    ours.overlay.clear();
    EXPECT_EQ(count(checkCases(ours, false, false, 42)), 0u) << "ours are not held to ours";
    for (const CheckCase& c : checkCases(base, false, false, 42))
        if (c.view == "drawn") {
            EXPECT_EQ(c.request.displaceSeed, std::optional<std::uint64_t>(42));
            EXPECT_NE(c.lesson.find("(drawn: "), std::string::npos) << c.lesson;
            EXPECT_NE(c.drawn, nullptr) << "the series finds a pair by its rows";
        }
}

// A pair's second row comes right after its first, each naming its entry's row.
TEST(Drawn, CheckRunsAPairsSecondRowAfterItsFirst) {
    useSourceTree();
    RenderRequest base;
    base.stage = "depth";
    base.overlay = "submission";
    const std::vector<CheckCase> cases = checkCases(base, false, false, 7);
    int seconds = 0;
    for (std::size_t k = 0; k < cases.size(); ++k) {
        if (!cases[k].drawn || !cases[k].drawn->response) continue;
        ++seconds;
        ASSERT_GT(k, 0u);
        EXPECT_EQ(cases[k - 1].drawn, pairedRowOf(*cases[k].drawn));
        EXPECT_NE(cases[k].lesson, cases[k - 1].lesson);
        EXPECT_NE(cases[k].lesson.find("response:margin"), std::string::npos) << cases[k].lesson;
    }
    EXPECT_EQ(seconds, 1);
}

}  // namespace
}  // namespace sl
