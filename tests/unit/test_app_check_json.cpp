// A check result survives its JSON (how a worker's results come back), and the graders'
// formats name and describe it.
#include <gtest/gtest.h>

#include "grade/check_formats.h"
#include "grade/check_run.h"
#include "stages/stage.h"

namespace sl {
namespace {

CheckResult judgedRgb() {
    CheckResult r;
    r.stage = "rgb";
    r.tree = "core";
    r.scene = "slides";
    r.overlay = "/tmp/student";
    r.width = 320;
    r.height = 240;
    r.parameters = ParamSet(findStage("rgb")->params);
    EXPECT_EQ(r.parameters.set("margin", "0.01"), "");
    r.camera.eye = {0.1f, 2.5f, 4.25f};
    r.camera.at = {0, 0.3f, 0};
    r.camera.fovyDegrees = 47.5f;
    r.light = {2, 1, 0};
    r.figures.falseShadowPct = 0.125;
    r.figures.falseLitPct = 1.0 / 3.0;
    r.figures.falseShadowBandPct = 2.5;
    r.figures.falseLitBandPct = 3.5;
    r.figures.edgeMeanPx = 0.75;
    r.figures.edgeP95Px = 1.5;  // the mirror figures stay NaN: null in the JSON
    r.evaluated = 12345;
    r.truthLit = 10000;
    r.truthShadow = 2345;
    r.expectation = findExpectation(expectations(), "rgb", "slides", "core", r.parameters);
    r.judgement = {Verdict::Pass, "as expected: no acne"};
    r.diffFile = "/tmp/diff/rgb-core.png";
    r.note = "a note";
    r.sourceNotes = {
        "possible gaming: /tmp/student/rgb/lit.frag:12 compares the camera "
        "position (eyePosition) with a constant; ..."};
    r.seconds = 0.4375;
    return r;
}

TEST(CheckJson, AJudgedResultRoundTrips) {
    CheckResult r = judgedRgb();
    ASSERT_NE(r.expectation.entry, nullptr);
    ASSERT_TRUE(r.expectation.exact);  // rgb margin=0.01 has an entry of its own
    nlohmann::json j = checkJson(r);
    CheckResult back = checkResultFromJson(j);
    EXPECT_EQ(checkJson(back), j);
    EXPECT_EQ(back.expectation.entry, r.expectation.entry);
    EXPECT_TRUE(back.expectation.exact);
    EXPECT_FALSE(back.error);
    EXPECT_EQ(back.verdict(), "PASS");
    EXPECT_EQ(back.parameters.text("margin"), "0.01");
    EXPECT_EQ(back.camera.eye, r.camera.eye);
    EXPECT_TRUE(std::isnan(back.figures.mirrorPsnrDb));
    EXPECT_EQ(back.figures.falseLitPct, r.figures.falseLitPct);
    EXPECT_EQ(back.note, "a note");
    EXPECT_EQ(back.sourceNotes, r.sourceNotes);
    EXPECT_EQ(j["source_notes"].size(), 1u);
    // Through text as well, as it crosses the pipe.
    EXPECT_EQ(checkJson(checkResultFromJson(nlohmann::json::parse(j.dump()))), j);
}

TEST(CheckJson, AnUnjudgedResultRoundTrips) {
    CheckResult r;
    r.stage = "margin";
    r.tree = "legacy";
    r.scene = "slides";
    r.width = 640;
    r.height = 480;
    r.parameters = ParamSet(findStage("margin")->params);
    r.error = true;
    r.errorVerdict = "TIMEOUT";
    r.judgement = {Verdict::Fail, "stage margin (legacy): no result within the time limit of 5 s"};
    nlohmann::json j = checkJson(r);
    EXPECT_EQ(j["verdict"], "TIMEOUT");
    EXPECT_TRUE(j["expectation"].is_null());
    CheckResult back = checkResultFromJson(j);
    EXPECT_TRUE(back.error);
    EXPECT_EQ(back.verdict(), "TIMEOUT");
    EXPECT_EQ(back.expectation.entry, nullptr);
    EXPECT_EQ(checkJson(back), j);
}

TEST(CheckJson, AMalformedResultIsRefused) {
    nlohmann::json j = checkJson(judgedRgb());
    nlohmann::json noStage = j;
    noStage.erase("stage");
    EXPECT_THROW(checkResultFromJson(noStage), std::invalid_argument);
    nlohmann::json badVerdict = j;
    badVerdict["verdict"] = "MAYBE";
    EXPECT_THROW(checkResultFromJson(badVerdict), std::invalid_argument);
    nlohmann::json badEntry = j;
    badEntry["expectation"]["entry"] = "rgb margin=0.07";
    EXPECT_THROW(checkResultFromJson(badEntry), std::invalid_argument);
}

TEST(CheckFormats, TheTestNameCarriesSettingsThatAreNotTheDefaults) {
    CheckResult r = judgedRgb();
    EXPECT_EQ(checkTestName(r), "rgb/core margin=0.01");
    r.parameters = ParamSet(findStage("rgb")->params);
    EXPECT_EQ(checkTestName(r), "rgb/core");
    r.scene = "lab";
    EXPECT_EQ(checkTestName(r), "rgb/core scene=lab");
}

TEST(CheckFormats, XmlTextIsEscapedAndValid) {
    EXPECT_EQ(xmlEscaped("a<b & \"c\" 'd'>"), "a&lt;b &amp; &quot;c&quot; &apos;d&apos;&gt;");
    EXPECT_EQ(xmlEscaped("bell\x07 bad\xff ok\xC3\xA9"),
              "bell\xEF\xBF\xBD bad\xEF\xBF\xBD ok\xC3\xA9");
    EXPECT_EQ(xmlEscaped("overlong \xC0\xAF, surrogate \xED\xA0\x80"),
              "overlong \xEF\xBF\xBD\xEF\xBF\xBD, surrogate \xEF\xBF\xBD\xEF\xBF\xBD\xEF\xBF\xBD");
    EXPECT_EQ(xmlEscaped("two\nlines"), "two&#10;lines");
    EXPECT_EQ(xmlEscaped("two\nlines", false), "two\nlines");
}

TEST(CheckFormats, GradescopeScoresOnePointPerPassingCheck) {
    CheckResult pass = judgedRgb();
    CheckResult fail = judgedRgb();
    fail.judgement = {Verdict::Fail, "expected no acne"};
    CheckResult timeout = judgedRgb();
    timeout.error = true;
    timeout.errorVerdict = "TIMEOUT";
    nlohmann::json g = gradescopeJson({pass, fail, timeout}, 12.6);
    EXPECT_EQ(g["score"], 1.0);
    EXPECT_EQ(g["execution_time"], 13);
    ASSERT_EQ(g["tests"].size(), 3u);
    EXPECT_EQ(g["tests"][0]["status"], "passed");
    EXPECT_EQ(g["tests"][1]["status"], "failed");
    EXPECT_EQ(g["tests"][2]["status"], "failed");
    EXPECT_EQ(g["tests"][2]["max_score"], 1.0);
    EXPECT_NE(g["tests"][0]["output"].get<std::string>().find("diff image: /tmp/diff/rgb-core.png"),
              std::string::npos);
}

}  // namespace
}  // namespace sl
