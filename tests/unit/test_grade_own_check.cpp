// A student's own check report against the grade (grade/own_check.h), on synthetic records: the
// rows paired by stage, tree, view and lesson; an edited verdict found; seeds, unmatched rows
// and garbage said, never a score; the record keeps it; the pages show it (hidden rows only to
// the instructor).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "feedback/class_page.h"
#include "feedback/feedback_html.h"
#include "grade/formats.h"
#include "grade/intake.h"
#include "grade/own_check.h"
#include "grade/record.h"

namespace sl {
namespace {

RowRecord row(const std::string& view, Status status, const std::string& visibility = "visible",
              std::optional<std::uint64_t> seed = std::nullopt) {
    RowRecord r;
    r.result.stage = "depth";
    r.result.tree = "core";
    r.result.view = view;
    r.result.lesson = "depth";
    r.result.status = status;
    r.result.seed = seed;
    r.visibility = visibility;
    r.points = status == Status::Pass ? 1 : 0;
    r.maxPoints = 1;
    return r;
}

// The grade: four rows of depth/core, one hidden, one displaced (seed 7).
StudentRecord graded() {
    StudentRecord rec;
    rec.assignment = "lab";
    rec.student = "ann";
    rec.seed = 7;
    StageRecord st;
    st.stage = "depth";
    st.tree = "core";
    st.rows = {row("lecture", Status::Pass), row("cube-on-cube", Status::Fail),
               row("grazing", Status::Fail, "hidden"),
               row("displaced", Status::Pass, "visible", 7)};
    st.status = Status::Fail;
    rec.stages = {st};
    rec.score = 2;
    rec.maxScore = 4;
    return rec;
}

// The student's report of `rec` as check --report writes it.
HandInFile reportOf(StudentRecord rec) {
    rec.tool = "shadowlab check";
    rec.backend = "egl";
    rec.machine = "NVIDIA H200";
    return {"check-report.json", recordJson(rec).dump(), ""};
}

std::string problemOf(const std::string& text) {
    return compareOwnCheck({"check-report.json", text, ""}, graded()).problem;
}

TEST(OwnCheck, AnHonestReportAgreesOnEveryRow) {
    OwnCheck o = compareOwnCheck(reportOf(graded()), graded());
    EXPECT_EQ(o.problem, "");
    EXPECT_EQ(o.compared, 4);
    EXPECT_EQ(o.agreed, 4);
    EXPECT_EQ(o.seenCompared, 3);  // the hidden row is compared, but not counted to the student
    EXPECT_EQ(o.seenAgreed, 3);
    EXPECT_EQ(o.disagreed, 0);
    EXPECT_EQ(o.machine, "NVIDIA H200");
    EXPECT_EQ(o.backend, "egl");
    EXPECT_TRUE(ownCheckNotes(o).empty());
}

TEST(OwnCheck, AnEditedVerdictIsADisagreementAndNoScore) {
    StudentRecord home = graded();
    home.stages[0].rows[1].result.status = Status::Pass;  // FAIL edited to PASS
    home.stages[0].rows[2].result.status = Status::Pass;  // the hidden row too
    home.score = home.maxScore = 4;
    StudentRecord grade = graded();
    attachOwnCheck(grade, reportOf(home));
    EXPECT_EQ(grade.score, 2);  // the grade is the grade's
    ASSERT_TRUE(grade.ownCheck);
    const OwnCheck& o = *grade.ownCheck;
    EXPECT_EQ(o.compared, 4);
    EXPECT_EQ(o.agreed, 2);
    EXPECT_EQ(o.disagreed, 2);
    EXPECT_EQ(o.seenCompared, 3);
    EXPECT_EQ(o.seenAgreed, 2);
    ASSERT_EQ(o.disagreements.size(), 2u);
    EXPECT_EQ(o.disagreements[0].row, "depth/core/cube-on-cube");
    EXPECT_EQ(o.disagreements[0].home, Status::Pass);
    EXPECT_EQ(o.disagreements[0].grade, Status::Fail);
    EXPECT_TRUE(o.disagreements[0].seen);
    EXPECT_FALSE(o.disagreements[1].seen);
    EXPECT_TRUE(grade.notes.empty());
}

TEST(OwnCheck, AnotherSeedIsNotComparedAndAnUnknownRowIsNoted) {
    StudentRecord home = graded();
    home.stages[0].rows[3].result.seed = 8;
    home.stages[0].rows[3].result.status = Status::Fail;
    home.stages[0].rows.push_back(row("elsewhere", Status::Pass));
    home.stages[0].rows.push_back(row("lecture", Status::Fail));  // a row twice: once counted
    StudentRecord grade = graded();
    attachOwnCheck(grade, reportOf(home));
    const OwnCheck& o = *grade.ownCheck;
    EXPECT_EQ(o.compared, 3);
    EXPECT_EQ(o.agreed, 3);
    EXPECT_EQ(o.notComparable, 1);
    EXPECT_EQ(o.unmatched, 2);
    ASSERT_EQ(grade.notes.size(), 2u);
    EXPECT_NE(grade.notes[0].find("`check-report.json`"), std::string::npos);
    EXPECT_NE(grade.notes[0].find("2 rows this assignment does not grade"), std::string::npos);
    EXPECT_NE(grade.notes[1].find("1 row not compared"), std::string::npos);
}

TEST(OwnCheck, DisagreementsKeptAreCappedButCounted) {
    StudentRecord grade = graded(), home = graded();
    grade.stages[0].rows.clear();
    home.stages[0].rows.clear();
    for (int k = 0; k < 30; ++k) {
        grade.stages[0].rows.push_back(row("v" + std::to_string(k), Status::Fail));
        home.stages[0].rows.push_back(row("v" + std::to_string(k), Status::Pass));
    }
    OwnCheck o = compareOwnCheck(reportOf(home), grade);
    EXPECT_EQ(o.disagreed, 30);
    EXPECT_EQ(o.disagreements.size(), kMaxOwnCheckRows);
}

TEST(OwnCheck, GarbageIsAProblemNamingTheFileNeverAnError) {
    EXPECT_EQ(problemOf("{not json"), "not JSON");
    EXPECT_EQ(problemOf("[1, 2]"), "not a check report (not a JSON object)");
    EXPECT_EQ(problemOf(std::string(1 << 20, '[')),
              "not a check report (nested deeper than any report)");
    nlohmann::json j = nlohmann::json::parse(reportOf(graded()).text);
    j["tool"] = "shadowlab grade";
    EXPECT_EQ(problemOf(j.dump()), "not a shadowlab check report (tool: shadowlab grade)");
    j["tool"] = "shadowlab check (browser)";  // the page's download is a check report too
    EXPECT_EQ(problemOf(j.dump()), "");
    j["report_version"] = 1;
    EXPECT_NE(problemOf(j.dump()).find("report_version 1;"), std::string::npos);
    j["report_version"] = kReport.version - 1;  // the version before: a drawn pair's figure
    EXPECT_NE(
        problemOf(j.dump()).find("this grader reads version " + std::to_string(kReport.version)),
        std::string::npos);
    j["report_version"] = kReport.version;
    j["stages"][0]["rows"][0].erase("verdict");
    EXPECT_NE(problemOf(j.dump()).find("not a check report this grader reads"), std::string::npos);
    j = nlohmann::json::parse(reportOf(graded()).text);
    for (auto& r : j["stages"][0]["rows"]) r["view"] = "nowhere";
    EXPECT_EQ(problemOf(j.dump()), "none of its 4 rows is a row this assignment grades");
    j = nlohmann::json::parse(reportOf(graded()).text);
    j["stages"][0]["rows"] = {j["stages"][0]["rows"][3]};  // the displaced row only
    j["stages"][0]["rows"][0]["seed"] = 8;
    EXPECT_EQ(problemOf(j.dump()),
              "none of its rows could be compared (1 at another displaced-view seed than the "
              "grade's, or not graded)");
    // What the intake could not read comes through as it said it.
    OwnCheck o =
        compareOwnCheck({"check-report.json", "", "it has more than 4194304 bytes"}, graded());
    EXPECT_EQ(o.problem, "it has more than 4194304 bytes");
    EXPECT_EQ(o.compared, 0);
    StudentRecord grade = graded();
    attachOwnCheck(grade, {"check-report.json", "{not json", ""});
    ASSERT_EQ(grade.notes.size(), 1u);
    EXPECT_EQ(grade.notes[0],
              "`check-report.json` (your own check report) was not compared with the grade: not "
              "JSON");
    EXPECT_EQ(grade.score, 2);
}

TEST(OwnCheck, TheRecordKeepsItAndAnOldRecordReads) {
    StudentRecord home = graded();
    home.stages[0].rows[1].result.status = Status::Pass;
    StudentRecord grade = graded();
    attachOwnCheck(grade, reportOf(home));
    nlohmann::json j = keptRecordJson(grade);  // as `grade` keeps it
    EXPECT_EQ(j["own_check"]["disagreed"], 1);
    EXPECT_EQ(j["own_check"]["disagreements"][0]["home"], "PASS");
    StudentRecord back = recordFromJson(nlohmann::json::parse(j.dump()));
    EXPECT_EQ(recordJson(back)["own_check"], j["own_check"]);
    j.erase("own_check");  // a record kept before the field existed
    EXPECT_FALSE(recordFromJson(j).ownCheck);
    EXPECT_TRUE(recordJson(graded())["own_check"].is_null());
}

TEST(OwnCheck, ThePagesShowItTheStudentsOnlyTheirSeenRows) {
    StudentRecord home = graded();
    home.stages[0].rows[1].result.status = Status::Pass;
    home.stages[0].rows[2].result.status = Status::Pass;  // hidden: the instructor's only
    StudentRecord grade = graded();
    attachOwnCheck(grade, reportOf(home));
    const std::string page = studentPage(grade);
    EXPECT_NE(page.find("agreed with the grade on 2 of 3 rows: it said PASS where the grade says "
                        "FAIL on depth/core/cube-on-cube."),
              std::string::npos)
        << page;
    EXPECT_EQ(page.find("grazing"), std::string::npos);
    EXPECT_NE(page.find("NVIDIA H200"), std::string::npos);
    const std::string klass = classPage("lab", {grade, graded()}, {"ann.html", "bo.html"}, {}, {});
    EXPECT_NE(klass.find("1 student handed in their own check report; 0 agreed"), std::string::npos)
        << klass;
    EXPECT_NE(klass.find("<td>2 of 4</td>"), std::string::npos) << klass;
    EXPECT_NE(klass.find("depth/core/cube-on-cube: PASS at home, FAIL graded; "
                         "depth/core/grazing: PASS at home, FAIL graded"),
              std::string::npos)
        << klass;
    EXPECT_EQ(classPage("lab", {graded()}, {"bo.html"}, {}, {}).find("Own check"),
              std::string::npos);
}

// The intake sets the named file aside: not copied, not listed, read within its bound; a link
// or an oversized file is a problem, never an intake error; elsewhere the name is any file.
TEST(OwnCheck, TheIntakeSetsTheReportAside) {
    namespace fs = std::filesystem;
    PrivateDir in("sl-own-check-in");
    auto put = [&](const std::string& rel, const std::string& text) {
        fs::path p = fs::path(in.path()) / rel;
        fs::create_directories(p.parent_path());
        std::ofstream(p) << text;
    };
    const std::set<std::string> shipped = {"depth/lit.frag"};
    put("depth/lit.frag", "void main() {}\n");
    put("check-report.json", "{\"tool\": 1}");
    put("depth/check-report.json", "{}");
    auto take = [&](const std::string& aside) {
        static int n = 0;
        static std::vector<std::unique_ptr<PrivateDir>> keep;
        keep.push_back(std::make_unique<PrivateDir>("sl-own-check-snap" + std::to_string(++n)));
        return takeSubmission(in.path(), keep.back()->path(), shipped, {}, {}, aside);
    };
    Submission s = take("check-report.json");
    ASSERT_TRUE(s.setAside);
    EXPECT_EQ(s.setAside->text, "{\"tool\": 1}");
    EXPECT_EQ(s.setAside->problem, "");
    EXPECT_EQ(s.files, (std::vector<std::string>{"depth/check-report.json", "depth/lit.frag"}));
    EXPECT_FALSE(fs::exists(s.root + "/check-report.json"));
    Submission plain = take("");  // the assignment names none: any file, copied as today
    EXPECT_FALSE(plain.setAside);
    EXPECT_EQ(plain.files.front(), "check-report.json");
    fs::remove(fs::path(in.path()) / "check-report.json");
    EXPECT_FALSE(take("check-report.json").setAside);
    fs::create_symlink("/etc/passwd", fs::path(in.path()) / "check-report.json");
    s = take("check-report.json");
    ASSERT_TRUE(s.setAside);
    EXPECT_NE(s.setAside->problem, "");
    EXPECT_EQ(s.setAside->text, "");
    fs::remove(fs::path(in.path()) / "check-report.json");
    put("check-report.json", std::string(kMaxSetAsideBytes + 1, ' '));
    s = take("check-report.json");
    ASSERT_TRUE(s.setAside);
    EXPECT_NE(s.setAside->problem.find("bytes"), std::string::npos);
}

}  // namespace
}  // namespace sl
