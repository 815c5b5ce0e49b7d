// The expectations data file: the shipped file loads, each stage has its defaults entry, matching
// picks the exact entry or falls back to the defaults, and judging reads the limits right.
#include <gtest/gtest.h>

#include "stages/displaced_bounds.h"
#include "stages/expectations.h"
#include "stages/registry.h"
#include "stages/stage.h"

namespace sl {
namespace {

const char* kMinimal = R"({"expectations": [
  {"stage": "phong", "id": "defaults", "outcome": "no shadows", "why": "w", "limits": {"false_lit_pct": {"min": 99}}},
  {"stage": "rgb", "id": "defaults", "outcome": "acne", "why": "w", "limits": {"false_shadow_pct": {"min": 20}}},
  {"stage": "rgb", "id": "margin", "set": {"margin": "0.010"}, "outcome": "no acne", "why": "w",
   "limits": {"false_shadow_pct": {"max": 1}, "false_lit_pct": {"max": 2}}},
  {"stage": "depth", "id": "defaults", "outcome": "c", "why": "w", "limits": {"false_lit_pct": {"max": 2}}},
  {"stage": "bias", "id": "defaults", "outcome": "c", "why": "w", "limits": {"false_lit_pct": {"max": 2}}},
  {"stage": "margin", "id": "defaults", "outcome": "c", "why": "w", "limits": {"false_lit_pct": {"max": 2}}},
  {"stage": "hardware", "id": "defaults", "outcome": "c", "why": "w", "limits": {"false_lit_pct": {"max": 2}}},
  {"stage": "hardware", "id": "lab", "scene": "lab", "outcome": "lab", "why": "w", "limits": {"false_lit_pct": {"max": 2}}},
  {"stage": "fixed", "id": "defaults", "outcome": "c", "why": "w", "limits": {"false_lit_pct": {"max": 2}}},
  {"stage": "mirror", "id": "defaults", "outcome": "m", "why": "w", "limits": {"mirror_id_pct": {"min": 98}}},
  {"stage": "peers", "id": "defaults", "outcome": "c", "why": "w", "limits": {"false_lit_pct": {"max": 2}}}
]})";

ParamSet values(const std::string& stage, std::vector<std::pair<std::string, std::string>> sets) {
    ParamSet p(findStage(stage)->params);
    for (const auto& [n, v] : sets) EXPECT_EQ(p.set(n, v), "");
    return p;
}

TEST(Expectations, ShippedFileLoadsWithEveryStage) {
    const auto& book = expectations();
    for (const StageInfo& s : stageRegistry()) {
        std::string scene = s.defaultScene.empty() ? "slides" : s.defaultScene;
        ExpectationMatch m = findExpectation(book, s.id, scene, s.legacyOnly ? "legacy" : "core",
                                             ParamSet(s.params));
        ASSERT_NE(m.entry, nullptr) << s.id;
        EXPECT_TRUE(m.exact) << s.id;
        EXPECT_FALSE(m.entry->why.empty()) << s.id;
    }
}

TEST(Expectations, ExactMatchComparesParsedValues) {
    auto book = parseExpectations(kMinimal, "test");
    auto m = findExpectation(book, "rgb", "slides", "core", values("rgb", {{"margin", "0.01"}}));
    ASSERT_NE(m.entry, nullptr);
    EXPECT_TRUE(m.exact);
    EXPECT_EQ(m.entry->outcome, "no acne");
}

TEST(Expectations, UnlistedSettingsFallBackToTheDefaults) {
    auto book = parseExpectations(kMinimal, "test");
    auto m = findExpectation(book, "rgb", "slides", "legacy", values("rgb", {{"margin", "0.02"}}));
    ASSERT_NE(m.entry, nullptr);
    EXPECT_FALSE(m.exact);
    EXPECT_EQ(m.entry->outcome, "acne");
    auto lab = findExpectation(book, "hardware", "lab", "core", values("hardware", {}));
    EXPECT_TRUE(lab.exact);
    EXPECT_EQ(lab.entry->outcome, "lab");
}

TEST(Expectations, MistakesNameTheEntry) {
    auto expectError = [](const std::string& text, const std::string& part) {
        try {
            parseExpectations(text, "f.json");
            ADD_FAILURE() << "no error for " << text;
        } catch (const ExpectationError& e) {
            EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
        }
    };
    std::string ok = kMinimal;
    auto replaced = [&](const std::string& from, const std::string& to) {
        std::string t = ok;
        t.replace(t.find(from), from.size(), to);
        return t;
    };
    expectError(replaced("\"margin\": \"0.010\"", "\"margn\": \"0.010\""), "expectations[2]");
    expectError(replaced("\"margin\": \"0.010\"", "\"margin\": \"7\""), "margin=7");
    expectError(replaced("false_shadow_pct\": {\"min\": 20}", "false_shade\": {\"min\": 20}"),
                "unknown figure 'false_shade'");
    expectError(replaced("{\"stage\": \"depth\"", "{\"stage\": \"deep\""), "unknown stage 'deep'");
    expectError(replaced("{\"stage\": \"fixed\", \"id\": \"defaults\", \"outcome\": \"c\", "
                         "\"why\": \"w\", \"limits\": {\"false_lit_pct\": {\"max\": 2}}},",
                         ""),
                "stage fixed (legacy) needs one entry");
    expectError(replaced("\"id\": \"lab\", ", ""), "expectations[7]: missing \"id\"");
    expectError(replaced("\"id\": \"lab\"", "\"id\": \"Lab view\""),
                "'Lab view' must be lower-case");
    expectError("{\"expectations\": 3}", "needs an \"expectations\" list");
    expectError("{", "not valid JSON");
}

// An entry's id is how a kept record finds it: two entries of one stage may not share one (the
// record could not tell which it meant); entries of different stages may.
TEST(Expectations, ADuplicateIdIsRefused) {
    std::string text = kMinimal;
    const std::string from = "\"id\": \"lab\"";
    text.replace(text.find(from), from.size(), "\"id\": \"defaults\"");
    try {
        parseExpectations(text, "f.json");
        ADD_FAILURE() << "two hardware entries named 'defaults' were taken";
    } catch (const ExpectationError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "f.json: expectations[7]: the id 'defaults' of stage hardware is taken by "
                  "expectations[6]");
    }
    std::vector<Expectation> book = parseExpectations(kMinimal, "f.json");  // "defaults" per stage
    ASSERT_NE(expectationById(book, "hardware", "lab", "core"), nullptr);
    EXPECT_EQ(expectationById(book, "hardware", "lab", "core")->scene, "lab");
    EXPECT_EQ(expectationById(book, "hardware", "slope", "core"), nullptr);
}

// The shipped file: every entry has an id, unique in its stage (the loader's rule, here on the
// data itself), and the stage's defaults entry is "defaults" (the scheme its comment states).
TEST(Expectations, ShippedIdsFollowTheScheme) {
    for (const Expectation& e : expectations()) {
        EXPECT_FALSE(e.id.empty()) << e.label();
        EXPECT_EQ(e.id == "defaults", e.scene.empty() && e.set.empty())
            << e.label() << ": " << e.id;
    }
}

// The displaced views' bounds are data measured on the solution (stages/displaced_bounds.h):
// every lesson graded in a displaced view (in the stage's own scene, the mirror's too) has the
// solution's range of each figure it bounds, or a student edition would judge it by the lesson's
// bounds alone while a grader with the solutions could not tell (rerun
// scripts/measure_displaced_bounds.py when a lesson or a stage's shaders change).
TEST(DisplacedBounds, EveryDisplacedLessonHasTheSolutionsFigures) {
    int lessons = 0;
    for (const StageInfo& info : stageRegistry()) {
        for (const char* tree : {"core", "legacy"}) {
            if (info.legacyOnly && std::string(tree) == "core") continue;
            for (const Expectation* e : lessonsOf(expectations(), info.id, tree)) {
                if (!e->scene.empty() && e->scene != defaultSceneOf(info.id)) continue;
                const DisplacedFigures* ours = displacedFiguresOf(info.id, tree, e->label());
                ++lessons;
                ASSERT_NE(ours, nullptr) << info.id << "/" << tree << "/" << e->label();
                for (const Limit& l : e->limits) {
                    auto found = ours->find(l.figure);
                    ASSERT_NE(found, ours->end()) << e->label() << ": " << l.figure;
                    EXPECT_LE(found->second.lowest, found->second.highest) << e->label();
                }
            }
        }
    }
    EXPECT_GE(lessons, 10);
}

}  // namespace
}  // namespace sl
