// A check result survives its JSON (how a worker's results come back), and the graders'
// formats name and describe it.
#include <gtest/gtest.h>

#include "grade/bounds.h"
#include "grade/check_run.h"
#include "grade/formats.h"
#include "grade/record.h"
#include "grade/reports.h"
#include "grade/stage_runs.h"
#include "stages/registry.h"
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
    r.status = Status::Pass;
    r.message = "as expected: no acne";
    r.reasons = {{"false_shadow_pct", 0.125, FigureReason::Side::AtMost, 1, true},
                 {"mirror_psnr_db", NAN, FigureReason::Side::AtLeast, 32, false}};
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
    EXPECT_EQ(back.status, Status::Pass);
    EXPECT_EQ(back.verdict(), "PASS");
    EXPECT_EQ(back.parameters.text("margin"), "0.01");
    EXPECT_EQ(back.camera.eye, r.camera.eye);
    EXPECT_TRUE(std::isnan(back.figures.mirrorPsnrDb));
    EXPECT_EQ(back.figures.falseLitPct, r.figures.falseLitPct);
    EXPECT_EQ(back.note, "a note");
    EXPECT_EQ(back.sourceNotes, r.sourceNotes);
    EXPECT_EQ(j["source_notes"].size(), 1u);
    EXPECT_EQ(back.reasons, r.reasons);
    const nlohmann::json first = {{"figure", "false_shadow_pct"},
                                  {"value", 0.125},
                                  {"side", "<="},
                                  {"bound", 1.0},
                                  {"passed", true}};
    EXPECT_EQ(j["reasons"][0], first);
    EXPECT_TRUE(j["reasons"][1]["value"].is_null());
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
    r.status = Status::Timeout;
    r.message = "stage margin (legacy): used up its time budget of 5 s of CPU time";
    nlohmann::json j = checkJson(r);
    EXPECT_EQ(j["verdict"], "TIMEOUT");
    EXPECT_TRUE(j["expectation"].is_null());
    CheckResult back = checkResultFromJson(j);
    EXPECT_EQ(back.status, Status::Timeout);
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
    badEntry["expectation"]["id"] = "margin-0-07";
    EXPECT_THROW(checkResultFromJson(badEntry), std::invalid_argument);
    nlohmann::json noId = j;  // a row of an older shadowlab, named by its label alone
    noId["expectation"].erase("id");
    EXPECT_THROW(checkResultFromJson(noId), std::invalid_argument);
    nlohmann::json badSide = j;
    badSide["reasons"][0]["side"] = "in";
    EXPECT_THROW(checkResultFromJson(badSide), std::invalid_argument);
    nlohmann::json noValue = j;
    noValue["reasons"][0].erase("value");
    EXPECT_THROW(checkResultFromJson(noValue), std::invalid_argument);
}

// The shipped data with the entry `stage`/`id` given other settings (as an edit of
// expectations.json would): its label changes, its id does not.
std::vector<Expectation> bookWithSettings(const std::string& stage, const std::string& id,
                                          const nlohmann::json& set) {
    nlohmann::json data = nlohmann::json::parse(readStageData(expectationsPath()));
    bool found = false;
    for (auto& e : data["expectations"])
        if (e["stage"] == stage && e["id"] == id) {
            e["set"] = set;
            found = true;
        }
    EXPECT_TRUE(found) << stage << "/" << id;
    return parseExpectations(data.dump(), "a test copy of expectations.json");
}

// A row names its entry by id: an entry whose settings (its label) changed since the row was
// written is found again, so a class's kept records stay valid (issue 34: by the label, renaming
// a lesson silently regraded a class).
TEST(CheckJson, ARowFindsItsEntryByIdAfterItsSettingsChanged) {
    CheckResult r = judgedRgb();  // the entry "rgb margin=0.01", id "margin"
    ASSERT_NE(r.expectation.entry, nullptr);
    ASSERT_EQ(r.expectation.entry->id, "margin");
    nlohmann::json j = checkJson(r);
    EXPECT_EQ(j["expectation"]["id"], "margin");
    EXPECT_EQ(j["expectation"]["entry"], "rgb margin=0.01");  // the label stays, for people
    std::vector<Expectation> edited = bookWithSettings("rgb", "margin", {{"margin", "0.012"}});
    CheckResult back = checkResultFromJson(nlohmann::json::parse(j.dump()), edited);
    ASSERT_NE(back.expectation.entry, nullptr);
    EXPECT_EQ(back.expectation.entry->id, "margin");
    EXPECT_EQ(back.expectation.entry->label(), "rgb margin=0.012");
    EXPECT_EQ(back.expectation.entry->outcome, r.expectation.entry->outcome);
    EXPECT_TRUE(back.expectation.entry >= edited.data() &&
                back.expectation.entry < edited.data() + edited.size());
    EXPECT_TRUE(back.expectation.exact);
    // Another stage's entry of the same id is not it: ids are unique within a stage only.
    nlohmann::json depth = j;
    depth["stage"] = "depth";
    depth["parameters"] = nlohmann::json::object();
    EXPECT_THROW(checkResultFromJson(depth, edited), std::invalid_argument);
}

// A row kept before `reasons` existed (last term's records, a resume or --regrade reading them)
// loads with none; written again, it says so with an empty list.
TEST(CheckJson, ARowKeptBeforeReasonsLoadsWithNone) {
    nlohmann::json j = checkJson(judgedRgb());
    j.erase("reasons");
    CheckResult back = checkResultFromJson(j);
    EXPECT_TRUE(back.reasons.empty());
    EXPECT_EQ(back.message, judgedRgb().message);
    EXPECT_EQ(checkJson(back)["reasons"], nlohmann::json::array());
}

// The parent bounds what a worker sends back: a row past the bounds is cut, not kept whole.
TEST(CheckJson, AWorkersRowOverTheBoundIsCut) {
    CheckResult r = judgedRgb();
    r.message = std::string(100000, 'm');
    r.note = std::string(100000, 'n');
    for (int k = 0; k < 100; ++k) r.studentFiles.push_back("shader" + std::to_string(k) + ".frag");
    r.reasons.assign(1000, {std::string(1000, 'f'), 1, FigureReason::Side::AtMost, 2, true});
    WorkerOutcome outcome;
    outcome.value = {{"format", kWorkerRows.name},
                     {"version", kWorkerRows.version},
                     {"rows", {checkJson(r)}},
                     {"backend", "EGL"},
                     {"machine", "box"}};
    std::vector<CheckResult> rows = workerResults(outcome);
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0].message, capped(r.message, kMaxRowMessage));
    EXPECT_LT(rows[0].message.size(), kMaxRowMessage + 64);
    EXPECT_NE(rows[0].message.find("bytes cut]"), std::string::npos);
    EXPECT_EQ(rows[0].note, capped(r.note, kMaxRowMessage));
    EXPECT_EQ(rows[0].studentFiles.size(), kMaxListedFiles + 1);  // "... and 68 more"
    ASSERT_EQ(rows[0].reasons.size(), kMaxReasons);
    EXPECT_EQ(rows[0].reasons[0].figure, capped(std::string(1000, 'f'), kMaxReasonFigure));
    EXPECT_EQ(rows[0].backend, "EGL");
    EXPECT_EQ(rows[0].machine, "box");
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

// A record of two stages: a visible one (a PASS, a FAIL, and a hidden row that TIMEOUTs) and a
// hidden one.
StudentRecord twoStages() {
    auto row = [](Status status, const std::string& message, const std::string& visibility,
                  double points, double max) {
        RowRecord r{judgedRgb()};
        r.result.status = status;
        r.result.message = message;
        r.visibility = visibility;
        r.points = points;
        r.maxPoints = max;
        return r;
    };
    StudentRecord rec;
    rec.assignment = "lab";
    rec.student = "ann";
    StageRecord seen;
    seen.stage = "rgb";
    seen.tree = "core";
    seen.rows = {row(Status::Pass, "as expected", "visible", 2, 2),
                 row(Status::Fail, "expected no acne", "visible", 0, 2),
                 row(Status::Timeout, "used up its time budget", "hidden", 0, 2)};
    seen.status = Status::Timeout;
    seen.points = 2;
    seen.maxPoints = 6;
    StageRecord secret = seen;
    secret.stage = "margin";
    secret.visibility = "hidden";
    secret.message = "SECRET stage line";
    rec.stages = {seen, secret};
    rec.score = 4;
    rec.maxScore = 12;
    return rec;
}

TEST(CheckFormats, GradescopeShowsVisibleRowsOnlyInItsAlwaysVisibleOutput) {
    nlohmann::json g = gradescopeResults(twoStages());
    EXPECT_EQ(g["score"], 4.0);
    // Not a top-level key of Gradescope's specification: the maximum is the tests' max_score.
    EXPECT_FALSE(g.contains("max_score"));
    ASSERT_EQ(g["tests"].size(), 6u);
    EXPECT_EQ(g["tests"][0]["status"], "passed");
    EXPECT_EQ(g["tests"][1]["status"], "failed");
    EXPECT_EQ(g["tests"][2]["visibility"], "hidden");
    EXPECT_NE(g["tests"][0]["output"].get<std::string>().find("diff image: rgb-core.png"),
              std::string::npos);
    const std::string out = g["output"];
    // The visible stage counts its two visible rows; the hidden row and stage are not there.
    EXPECT_NE(out.find("rgb/core: FAIL, 2 of 4 points, 1 of 2 visible checks"), std::string::npos)
        << out;
    EXPECT_EQ(out.find("margin"), std::string::npos) << out;
    EXPECT_EQ(out.find("SECRET"), std::string::npos) << out;
    EXPECT_EQ(out.find("TIMEOUT"), std::string::npos) << out;
}

TEST(CheckFormats, ANotGradedRecordHasNoScoreAnywhere) {
    StudentRecord rec = twoStages();
    for (RowRecord& row : rec.stages[0].rows) {
        row.result.status = Status::NotGraded;
        row.points = row.maxPoints = 0;
    }
    rec.stages[0].status = Status::NotGraded;
    EXPECT_FALSE(rec.graded());
    EXPECT_EQ(rec.exitCode(), 3);
    nlohmann::json g = gradescopeResults(rec);
    EXPECT_FALSE(g.contains("score"));
    EXPECT_EQ(g["tests"].size(), 3u);  // the hidden stage's scored rows only
    EXPECT_NE(g["output"].get<std::string>().find("no score yet"), std::string::npos);
    EXPECT_NE(stageSummary(rec).find("total: not graded"), std::string::npos);
    std::string junit = junitXml(rec);
    EXPECT_NE(junit.find("<error type=\"NOT GRADED\""), std::string::npos);
}

// A worker's rows in another format, or another version of it, are refused with one line naming
// what came and what the parent reads (never read as rows of some other shape).
TEST(CheckJson, AWorkersRowsOfAnotherFormatAreRefused) {
    const nlohmann::json row = checkJson(judgedRgb());
    WorkerOutcome outcome;
    outcome.value = {{"format", kWorkerRows.name},
                     {"version", kWorkerRows.version},
                     {"rows", {row}},
                     {"backend", "EGL"},
                     {"machine", "box"}};
    ASSERT_EQ(workerResults(outcome).size(), 1u);
    auto refusal = [&](const nlohmann::json& value) {
        WorkerOutcome o = outcome;
        o.value = value;
        try {
            workerResults(o);
        } catch (const FormatError& e) {
            return std::string(e.what());
        }
        return std::string("taken");
    };
    nlohmann::json newer = outcome.value;
    newer["version"] = kWorkerRows.version + 1;
    EXPECT_EQ(refusal(newer), "a worker's rows: got \"shadowlab-worker-rows\" version " +
                                  std::to_string(kWorkerRows.version + 1) +
                                  ", reads shadowlab-worker-rows version " +
                                  std::to_string(kWorkerRows.version));
    nlohmann::json other = outcome.value;
    other["format"] = kReport.name;
    EXPECT_NE(refusal(other).find("got \"shadowlab-report\""), std::string::npos);
    // The shape before formats had names: {"results": [...]}.
    nlohmann::json unnamed = {{"results", {row}}, {"backend", "EGL"}, {"machine", "box"}};
    EXPECT_NE(refusal(unnamed).find("got no \"format\""), std::string::npos);
}

// The kept record's reader takes its own format and version only. A public report is not a kept
// record, nor is a newer one; an older one (or one from before formats had names) is refused as
// older(), which `grade` answers by grading the student again (class/class_grade.cpp).
TEST(Record, TheKeptRecordsReaderRefusesAnotherFormat) {
    const StudentRecord rec = twoStages();
    const nlohmann::json kept = keptRecordJson(rec);
    EXPECT_EQ(kept["record_format"], kKeptRecord.name);
    EXPECT_EQ(kept["report_format"], kReport.name);
    EXPECT_EQ(kept["report_version"], kReport.version);
    EXPECT_EQ(recordFromJson(kept).student, rec.student);
    auto refusal = [](const nlohmann::json& j, bool& older) {
        try {
            recordFromJson(j);
        } catch (const FormatError& e) {
            older = e.older();
            return std::string(e.what());
        }
        return std::string("taken");
    };
    bool older = true;
    const std::string reads =
        ", reads shadowlab-kept-record version " + std::to_string(kKeptRecord.version);
    EXPECT_EQ(refusal(recordJson(rec), older),
              "a kept record: got no \"record_format\" (an older shadowlab's)" + reads);
    EXPECT_TRUE(older);  // the report's fields alone: the kept record's shape before issue 34
    nlohmann::json newer = kept;
    newer["record_version"] = kKeptRecord.version + 1;
    EXPECT_EQ(refusal(newer, older), "a kept record: got \"shadowlab-kept-record\" version " +
                                         std::to_string(kKeptRecord.version + 1) + reads);
    EXPECT_FALSE(older);
    nlohmann::json lower = kept;
    lower["record_version"] = kKeptRecord.version - 1;
    refusal(lower, older);
    EXPECT_TRUE(older);
    nlohmann::json renamed = kept;
    renamed["record_format"] = kWorkerRows.name;
    EXPECT_NE(refusal(renamed, older).find("got \"shadowlab-worker-rows\""), std::string::npos);
    EXPECT_FALSE(older);
}

TEST(Record, RoundTripsThroughItsJson) {
    StudentRecord rec = twoStages();
    rec.handInHash = "0123456789abcdef";
    rec.assignmentHash = "fedcba9876543210";
    rec.seed = 42;
    nlohmann::json j = keptRecordJson(rec);
    StudentRecord back = recordFromJson(nlohmann::json::parse(j.dump()));
    EXPECT_EQ(keptRecordJson(back), j);
    EXPECT_EQ(back.status(), Status::Timeout);
    EXPECT_EQ(j["exit_code"], 2);
    EXPECT_EQ(j["summary"]["passed"], 2);
    EXPECT_EQ(j["summary"]["failed"], 2);
    EXPECT_EQ(j["summary"]["errors"], 2);
    EXPECT_THROW(recordFromJson(nlohmann::json{{"report_version", 1}}), std::invalid_argument);
}

// A kept record whose rows have no `reasons` still loads (the row reader takes them as none). A
// record kept before formats had names is refused as older() first (TheKeptRecordsReader...).
TEST(Record, ARecordKeptBeforeReasonsLoads) {
    nlohmann::json j = keptRecordJson(twoStages());
    for (auto& st : j["stages"])
        for (auto& row : st["rows"]) row.erase("reasons");
    StudentRecord back = recordFromJson(nlohmann::json::parse(j.dump()));
    ASSERT_EQ(back.stages.size(), twoStages().stages.size());
    for (const StageRecord& st : back.stages)
        for (const RowRecord& row : st.rows) EXPECT_TRUE(row.result.reasons.empty());
}

// A hand-in name that is not UTF-8 comes back byte for byte (the record is found again under it:
// never "no record (its job failed)"), shown escaped in the record's text (issue 39).
TEST(Record, ANameThatIsNotUtf8RoundTrips) {
    StudentRecord rec = twoStages();
    rec.student = "caf\xe9 \xff";
    nlohmann::json j = recordJson(rec);
    EXPECT_EQ(j["student"], "caf\\xE9 \\xFF");
    EXPECT_EQ(j["student_bytes"], "636166e920ff");
    const std::string text =
        keptRecordJson(rec).dump(-1, ' ', false, nlohmann::json::error_handler_t::strict);
    EXPECT_EQ(recordFromJson(nlohmann::json::parse(text)).student, rec.student);
    rec.student = "ann";
    EXPECT_TRUE(recordJson(rec)["student_bytes"].is_null());
}

}  // namespace
}  // namespace sl
