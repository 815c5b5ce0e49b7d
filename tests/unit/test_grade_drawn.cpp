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
            for (const char* tree : {"core", "legacy"})
                if (!drawnRowsOf(row.stage, tree).empty())
                    EXPECT_EQ(drawnRowFor(row.stage, scene, tree, values), &row) << row.label();
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
        }
}

}  // namespace
}  // namespace sl
