// The course code's plain functions: solution markers, JSON value lines, base64, CSV cells.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "class/class_progress.h"
#include "course/assignment.h"
#include "course/json_lines.h"
#include "course/release.h"
#include "feedback/feedback_html.h"
#include "feedback/html_text.h"
#include "grade/grade_students.h"
#include "grade/record.h"
#include "gradebook/gradebook_exports.h"

namespace sl {
namespace {

TEST(SolutionMarkers, RegionReplacedByItsStub) {
    std::vector<std::string> solution;
    std::string out = stripSolutions(
        "a\n  // BEGIN SOLUTION\n  secret();\n  // END SOLUTION\n  // STUB: stub();\nb\n", "f",
        &solution);
    EXPECT_EQ(out, "a\n  stub();\nb\n");
    ASSERT_EQ(solution.size(), 1u);
    EXPECT_EQ(solution[0], "  secret();");
}

TEST(SolutionMarkers, RegionWithoutStubGetsTodo) {
    EXPECT_EQ(stripSolutions("x\n    // BEGIN SOLUTION\n    s;\n    // END SOLUTION\ny", "f"),
              "x\n    // TODO: write this part\ny");
}

TEST(SolutionMarkers, MisplacedMarkersNameTheLine) {
    try {
        stripSolutions("a\n// BEGIN SOLUTION\nb\n", "f.frag");
        FAIL();
    } catch (const AssignmentError& e) {
        EXPECT_STREQ(e.what(), "f.frag: line 2: BEGIN SOLUTION is never closed");
    }
    EXPECT_THROW(stripSolutions("// END SOLUTION\n", "f"), AssignmentError);
    EXPECT_THROW(stripSolutions("// BEGIN SOLUTION\n// BEGIN SOLUTION\n", "f"), AssignmentError);
    EXPECT_THROW(stripSolutions("a\n// STUB: b\n", "f"), AssignmentError);
}

// Every line that looks like a marker without being the exact form refuses, naming the line:
// a misspelled BEGIN would otherwise ship its region's solution as ordinary code.
TEST(SolutionMarkers, LookAlikesRefuseNamingTheLine) {
    const char* lookAlikes[] = {
        "//BEGIN SOLUTION",        "/* BEGIN SOLUTION */", "// begin solution",
        "// BEGIN  SOLUTION",      "// BEGIN_SOLUTION",    "// BEGIN SOLUTION:",
        "# BEGIN SOLUTION",        "// Begin Solution",    "x = 1; // BEGIN SOLUTION",
        "// SOLUTION BEGIN",       "/// BEGIN SOLUTION",   "//  BEGIN SOLUTION here",
        "// BEGINSOLUTION",        "// END-SOLUTION",      "//END SOLUTION",
        "/* END SOLUTION */",      "// end solution",      "// END SOLUTIONS",
        "//STUB: return 0.0;",     "// stub: return 0.0;", "// STUB return 0.0;",
        "/* STUB: return 0.0; */", " * BEGIN SOLUTION",
    };
    for (const char* line : lookAlikes) {
        std::string text = std::string("a\n  ") + line + "\n  secret();\n  // END SOLUTION\n";
        try {
            stripSolutions(text, "f.frag");
            ADD_FAILURE() << "accepted: " << line;
        } catch (const AssignmentError& e) {
            EXPECT_EQ(std::string(e.what()).rfind("f.frag: line 2: '", 0), 0u) << e.what();
            EXPECT_NE(std::string(e.what()).find("looks like a solution marker"), std::string::npos)
                << e.what();
        }
    }
    // The exact forms, with any indentation and trailing spaces, are markers.
    EXPECT_EQ(stripSolutions("\t// BEGIN SOLUTION  \nx\n    // END SOLUTION\r\n// STUB: y\n", "f"),
              "y\n");
    // Comments that merely mention solutions are not markers.
    std::string prose = "// the solution begins with the divide; the end of the solution is here\n";
    EXPECT_EQ(stripSolutions(prose, "f"), prose);
}

TEST(SolutionMarkers, AStubWhoseCodeIsAMarkerRefuses) {
    // Found by fuzz_course_text: the release held a "// BEGIN SOLUTION" line of a STUB's code.
    for (const char* code :
         {"// BEGIN SOLUTION", "// END SOLUTION", "// STUB: x", "//BEGIN SOLUTION"})
        EXPECT_THROW(
            stripSolutions(
                std::string("// BEGIN SOLUTION\nx = 1;\n// END SOLUTION\n// STUB: ") + code + "\n",
                "m.frag"),
            AssignmentError)
            << code;
    EXPECT_EQ(
        stripSolutions("// BEGIN SOLUTION\nx = 1;\n// END SOLUTION\n// STUB: x = 0;\n", "m.frag"),
        "x = 0;\n");
}

TEST(SolutionMarkers, StubInsideARegionRefuses) {
    EXPECT_THROW(stripSolutions("// BEGIN SOLUTION\n// STUB: x\n// END SOLUTION\n", "f"),
                 AssignmentError);
}

TEST(SolutionMarkers, ShippedFilesWithoutMarkersUnchanged) {
    std::string text = "void main()\n{\n    gl_FragColor = vec4(1.0);\n}\n";
    EXPECT_EQ(stripSolutions(text, "f"), text);
}

TEST(JsonLines, PathsToLines) {
    auto lines = jsonValueLines("{\n \"a\": [1,\n  {\"b/c\": 2}],\n \"d\": \"x\"\n}");
    EXPECT_EQ(lines.at(""), 1);
    EXPECT_EQ(lines.at("/a"), 2);
    EXPECT_EQ(lines.at("/a/0"), 2);
    EXPECT_EQ(lines.at("/a/1/b~1c"), 3);
    EXPECT_EQ(lines.at("/d"), 4);
}

TEST(Base64, KnownValues) {
    EXPECT_EQ(base64(""), "");
    EXPECT_EQ(base64("f"), "Zg==");
    EXPECT_EQ(base64("fo"), "Zm8=");
    EXPECT_EQ(base64("foo"), "Zm9v");
    EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
}

// A student with one stage of the given status and points.
StudentRecord oneStage(const std::string& student, const std::string& stage, Status status,
                       double points, double max) {
    StudentRecord r;
    r.student = student;
    StageRecord st;
    st.stage = stage;
    st.tree = "core";
    st.points = points;
    st.maxPoints = max;
    st.status = status;
    r.stages = {st};
    return r;
}

TEST(GradesCsv, QuotesAndNoFormulas) {
    StudentRecord r = oneStage("=cmd|x,y", "rgb", Status::Fail, 1.5, 2);
    r.score = 1.5;
    r.maxScore = 2;
    EXPECT_EQ(
        gradesCsv({r}),
        "student,id,name,email,status,rgb/core,adjustments,late_penalty,total,max,not_graded\r\n"
        "\"'=cmd|x,y\",,,,FAIL,1.500,,,1.500,2.000,\r\n");
}

TEST(GradesCsv, EveryCellASpreadsheetWouldEvaluateIsPrefixed) {
    for (const char* bad : {"=1+1", "+1", "-1", "@SUM(A1)", "\tx", "\rx",
                            "\xEF\xBC\x9D"
                            "1",
                            "\xEF\xBC\x8B"
                            "1",
                            "\xEF\xBC\x8D"
                            "1",
                            "\xEF\xBC\xA0"
                            "x"})
        EXPECT_EQ(csvCell(bad).find_first_not_of('"'), csvCell(bad).find('\'')) << bad;
    EXPECT_EQ(csvCell("plain"), "plain");
    EXPECT_EQ(csvCell("a\"b"), "\"a\"\"b\"");
}

TEST(GradesCsv, ANotGradedStageIsAnEmptyCellWithTheReason) {
    StudentRecord r = oneStage("bo", "margin", Status::NotGraded, 0, 0);
    r.stages[0].message = "our shaders could not finish";
    EXPECT_EQ(
        gradesCsv({r}),
        "student,id,name,email,status,margin/core,adjustments,late_penalty,total,max,not_graded\r\n"
        "bo,,,,NOT GRADED,,,,,,margin/core: our shaders could not finish\r\n");
}

TEST(ClassProgress, PaceSinceTheFirstRowsLeavesTheStartOut) {
    Pace pace;
    EXPECT_FALSE(pace.timeLeft(5, {{0, 100}}));  // nothing back yet: no estimate
    // The first rows came after 10 s of start (compiling, tracing): 10 rows.
    ASSERT_TRUE(pace.timeLeft(10, {{10, 100}}));
    EXPECT_NEAR(*pace.timeLeft(10, {{10, 100}}), 90.0, 1e-9);  // one reading: the pace so far
    // Then 40 rows in 20 s: 0.5 s a row for the 50 left, not (30 s / 50 rows) * 50.
    EXPECT_NEAR(*pace.timeLeft(30, {{50, 100}}), 25.0, 1e-9);
    EXPECT_NEAR(*pace.timeLeft(40, {{100, 100}}), 0.0, 1e-9);
}

TEST(ClassProgress, TheJobWithTheMostRowsLeftAtTheJobsPace) {
    Pace pace;
    ASSERT_TRUE(pace.timeLeft(10, {{10, 100}, {10, 200}, {0, 50}}));
    // Job 0 at 0.25 s a row, job 1 at 1 s a row: the jobs' pace is 0.625 s a row. Job 1 has the
    // most rows left (180: 112.5 s); job 2, not started, 50 (31.25 s). All rows added up would
    // say 60 rows in 10 s, 300 left: 50 s, under half of what job 1 needs.
    EXPECT_NEAR(*pace.timeLeft(20, {{50, 100}, {20, 200}, {0, 50}}), 112.5, 1e-9);
}

// Rows come back a stage at a time (issue 39): at a steady 10 rows every 5 s, readings between
// two stages say the true time left (it falls with the clock), where a pace taken to the
// reading's time rose between stages (0.7 s a row at 12 s: 56 s for what takes 38).
TEST(ClassProgress, BetweenStagesTheEstimateFallsWithTheClock) {
    Pace pace;
    ASSERT_TRUE(pace.timeLeft(5, {{10, 100}}));
    for (int t = 10; t <= 30; ++t) {
        const std::size_t done = std::size_t(10 + 10 * ((t - 5) / 5));  // a stage each 5 s
        const std::optional<double> left = pace.timeLeft(t, {{done, 100}});
        ASSERT_TRUE(left);
        EXPECT_NEAR(*left, 50.0 - t, 1e-9) << "at " << t << " s, " << done << " rows done";
    }
}

// A stage slower than the pace (a loop running to its budget) holds the estimate at what the
// rows after it need: never 0 with a stage after it, never rising while nothing came back.
TEST(ClassProgress, ASlowStageHoldsTheEstimateAtTheRowsAfterIt) {
    Pace pace;
    pace.timeLeft(5, {{10, 100}});
    pace.timeLeft(10, {{20, 100}});  // 0.5 s a row, a step of 10 rows
    double before = *pace.timeLeft(10, {{20, 100}});
    for (int t = 11; t <= 60; ++t) {
        const double left = *pace.timeLeft(t, {{20, 100}});
        EXPECT_LE(left, before) << "at " << t << " s";
        EXPECT_GE(left, 0.5 * 70 - 1e-9) << "at " << t << " s";  // the 70 rows after the step
        before = left;
    }
    EXPECT_NEAR(before, 35.0, 1e-9);
    // 70 rows came at last (0.7 s a row since the first reading): the 10 left are the next step
    // and nothing comes after it, so it may run out.
    EXPECT_NEAR(*pace.timeLeft(61, {{90, 100}}), 7.0, 1e-9);
    EXPECT_NEAR(*pace.timeLeft(70, {{90, 100}}), 0.0, 1e-9);
}

// A job of `students` plans of one stage of 10 rows in the core tree, with its progress file
// (`file` under the test's temporary folder) and that stage's record.
struct OneStageJob {
    OneStageJob(const std::string& stage, std::size_t students, const std::string& file)
        : plans(
              students,
              GradingPlan{
                  "lab",
                  {StagePlan{stage, "core", {}, {}, 0, "visible", std::vector<RowPlan>(10), ""}}}),
          path(::testing::TempDir() + "/" + file),
          progress(path, plans, renderOrder(plans, std::vector<StudentWork>(students))) {
        done.stage = stage;
        done.tree = "core";
    }
    std::vector<GradingPlan> plans;
    std::string path;
    JobProgress progress;
    StageRecord done;
};

// A round draws its stages' views once (traced, and drawn with our shaders), about one student's
// rows of work (issue 39): 4 students a job go in rounds of 1, 2 and 1. Here the views cost one
// student (1 s for 10 rows): the students are done at 2, 4, 5 and 7 s. After the second the
// views are priced as rows (no step without them timed yet): 3 s, what is left. After the third,
// a step of each kind is timed and the last round is priced as it comes: 2 s.
TEST(ClassProgress, ARoundsViewsCountAsOneStudentMore) {
    ASSERT_EQ(roundCount(4), 3u);
    OneStageJob job("margin", 4, "job-rounds.progress");
    Pace pace;
    auto reading = [&](double seconds) {
        std::vector<RowsDone> jobs = readProgress({job.path});
        return std::make_pair(jobs[0], pace.timeLeft(seconds, jobs));
    };
    EXPECT_EQ(reading(0).first.underwayRows, 10u);  // the first student, with its round's views
    EXPECT_EQ(reading(0).first.underwayViews, 10u);
    job.progress.stageDone(0, job.done);
    auto [first, unused] = reading(2);
    EXPECT_EQ(first.done, 20u);           // its rows and its round's views
    EXPECT_EQ(first.total, 70u);          // 40 rows, 3 rounds' views
    EXPECT_EQ(first.underwayViews, 10u);  // the next round's first student
    EXPECT_EQ(first.underwayKey, "margin/core");
    job.progress.stageDone(1, job.done);
    auto [second, left] = reading(4);
    EXPECT_EQ(second.done, 40u);
    EXPECT_EQ(second.underwayViews, 0u);  // the second of its round: the views are done
    ASSERT_TRUE(left);
    EXPECT_NEAR(*left, 3.0, 1e-9);
    job.progress.stageDone(2, job.done);
    auto [third, lastLeft] = reading(5);
    EXPECT_EQ(third.done, 50u);
    EXPECT_EQ(third.underwayRows, 10u);  // the last round's student draws its views
    EXPECT_EQ(third.underwayViews, 10u);
    ASSERT_TRUE(lastLeft);
    EXPECT_NEAR(*lastLeft, 2.0, 1e-9);
    job.progress.stageDone(3, job.done);  // each round's views counted once
    const RowsDone last = reading(7).first;
    EXPECT_EQ(last.done, 70u);
    EXPECT_EQ(last.underwayRows, 0u);
    ASSERT_EQ(last.stages.size(), 1u);  // and stage by stage
    EXPECT_EQ(last.stages[0].key, "margin/core");
    EXPECT_EQ(last.stages[0].done, 40u);  // the students' rows, and apart the rounds' views
    EXPECT_EQ(last.stages[0].total, 40u);
    EXPECT_EQ(last.stages[0].viewsDone, 30u);
    EXPECT_EQ(last.stages[0].viewsTotal, 30u);
}

// A job's rounds (grade/grade_students.h): every student in one, in order, at most 8 a round, at
// least three (a share of three or more); the first a quarter of the share (at least one), so the
// lines after the class's first quarter come after a step with views was timed; the others one
// apart, and the last never the only round of two or more: before it, a stage's step without its
// views is timed (class/class_progress.h).
TEST(ClassProgress, RoundsLeaveAStepWithoutViewsBeforeTheLast) {
    for (std::size_t n = 1; n <= 80; ++n) {
        const std::size_t rounds = roundCount(n);
        EXPECT_GE(rounds, std::min<std::size_t>(n, 3)) << n;
        ASSERT_EQ(roundStart(0, n), 0u);
        ASSERT_EQ(roundStart(rounds, n), n) << n;
        std::vector<std::size_t> sizes;
        for (std::size_t r = 0; r < rounds; ++r) {
            sizes.push_back(roundStart(r + 1, n) - roundStart(r, n));
            for (std::size_t k = roundStart(r, n); k < roundStart(r + 1, n); ++k)
                ASSERT_EQ(roundOf(k, n), r) << n << " students, student " << k;
        }
        EXPECT_EQ(sizes.front(), firstRound(n));
        EXPECT_EQ(sizes.front(), std::clamp<std::size_t>(n / 4, 1, 8)) << n;
        const auto [small, large] = std::minmax_element(sizes.begin(), sizes.end());
        EXPECT_GE(*small, 1u) << n;
        EXPECT_LE(*large, 8u) << n;
        if (rounds > 1) {
            const auto [low, high] = std::minmax_element(sizes.begin() + 1, sizes.end());
            EXPECT_LE(*high - *low, 1u) << n;
        }
        const bool twoBefore =
            std::any_of(sizes.begin(), sizes.end() - 1, [](std::size_t m) { return m >= 2; });
        if (sizes.back() >= 2 && rounds > 1) EXPECT_TRUE(twoBefore) << n << " students";
        if (n == 4) EXPECT_EQ(sizes, (std::vector<std::size_t>{1, 2, 1}));
        if (n == 7) EXPECT_EQ(sizes, (std::vector<std::size_t>{1, 3, 3}));
        if (n == 8) EXPECT_EQ(sizes, (std::vector<std::size_t>{2, 3, 3}));
    }
}

// A round's views cost what they cost, not one student's rows (issue 39): 6 students in rounds of
// 1, 3 and 2, a student's step 1 s and its round's views 0.2 s more. Once a step without views
// and one with them are timed (the first round's is not), the estimate is the time left; by rows
// it is over by more than a quarter of it.
TEST(ClassProgress, ARoundsViewsAtWhatTheyCost) {
    ASSERT_EQ(roundCount(6), 3u);
    ASSERT_EQ(roundStart(1, 6), 1u);
    ASSERT_EQ(roundStart(2, 6), 4u);
    OneStageJob job("a", 6, "job-views.progress");
    Pace priced, byRows;
    double t = 0, worstByRows = 0;
    for (std::size_t k = 0; k < 6; ++k) {
        t += roundStart(roundOf(k, 6), 6) == k ? 1.2 : 1.0;  // the first of a round draws views
        job.progress.stageDone(k, job.done);
        const RowsDone r = readProgress({job.path})[0];
        const std::optional<double> p = priced.timeLeft(t, {r}),
                                    rows = byRows.timeLeft(t, {{r.done, r.total}});
        ASSERT_TRUE(p && rows);
        if (k < 2 || k == 5) continue;  // a step of each kind timed from the third on
        EXPECT_NEAR(*p, 6.6 - t, 1e-9) << "after student " << k;
        worstByRows = std::max(worstByRows, std::abs(*rows - (6.6 - t)) / (6.6 - t));
    }
    EXPECT_GT(worstByRows, 0.25);
}

// The class's outputs read every record again after the last student's (issue 39): at the time
// a record took the parent in the run (50 ms here), 8 records are 0.4 s after the last rows;
// at the median read's, not the mean's, once the first read is slower than the rest.
TEST(ClassProgress, TheClassOutputsAfterTheLastStudent) {
    for (const std::size_t records : {0, 8}) {
        Pace pace;
        pace.outputsRead(records);
        pace.timeLeft(1, {{10, 20}});
        EXPECT_NEAR(*pace.timeLeft(2, {{20, 20}}), 0.0, 1e-9);  // no record back yet
        pace.recordBack(2, 0, 0.05);
        EXPECT_NEAR(*pace.timeLeft(2.5, {{20, 20}}), 0.05 * double(records), 1e-9);
        // The first read, from files not yet cached, took 4 times the others: the median read.
        pace.recordBack(2.5, 0, 0.0125);
        pace.recordBack(2.5, 0, 0.0125);
        EXPECT_NEAR(*pace.timeLeft(2.5, {{20, 20}}), 0.0125 * double(records), 1e-9);
        pace.recordBack(2.5, 0, 0.0175);
        EXPECT_NEAR(*pace.timeLeft(2.5, {{20, 20}}), 0.015 * double(records), 1e-9);
    }
}

// A line says the time left when it is said (issue 39): its record read and its page written
// after the poll's estimate, 0.05-0.13 s on a busy machine; never below 0.
TEST(ClassProgress, ALineSaysTheTimeLeftWhenItIsSaid) {
    EXPECT_NEAR(timeLeftWhenSaid(0.6, 10.0, 10.1), 0.5, 1e-9);
    EXPECT_NEAR(timeLeftWhenSaid(0.6, 10.0, 10.0), 0.6, 1e-9);
    EXPECT_NEAR(timeLeftWhenSaid(0.05, 10.0, 10.1), 0.0, 1e-9);
    EXPECT_NEAR(timeLeftWhenSaid(0.6, 10.0, 9.9), 0.6, 1e-9);  // a clock read before: as made
}

// The step under way is the one the job's file says (issue 39): after 2 rows of A (0.5 s a row)
// the job's 48 rows of B are under way. 18 s into them 6 s are left; the last step's 2 rows
// taken for the step under way held the estimate at the 46 rows after it, 23 s.
TEST(ClassProgress, TheStepUnderWayIsTheJobs) {
    auto reading = [](std::size_t a, bool saysStep) {
        RowsDone r{a, 52, {{"a/core", a, 4}, {"b/core", 0, 48}}};
        if (saysStep) r.underwayRows = a < 4 ? 2 : 48;
        if (saysStep) r.underwayKey = a < 4 ? "a/core" : "b/core";
        return r;
    };
    for (const bool saysStep : {true, false}) {
        Pace pace;
        pace.timeLeft(1, {reading(2, saysStep)});
        EXPECT_NEAR(*pace.timeLeft(2, {reading(4, saysStep)}), 24.0, 1e-9);
        EXPECT_NEAR(*pace.timeLeft(20, {reading(4, saysStep)}), saysStep ? 6.0 : 23.0, 1e-9);
    }
}

// A stage's rows at that stage's price (issue 39): each student renders a stage A (10 rows in
// 1 s) and then B (10 rows in 3 s). Once both are timed the estimate is the time left at every
// step; by rows alone, every row at the mean row's price, it is off by the mix of the rows left.
TEST(ClassProgress, AStagesRowsAtThatStagesPrice) {
    auto readingAt = [](int step, bool stages) {  // after `step` steps: A, B, A, B, ...
        const std::size_t a = 10 * std::size_t((step + 1) / 2), b = 10 * std::size_t(step / 2);
        RowsDone r{a + b, 100, {}};
        if (stages) r.stages = {{"a/core", a, 50}, {"b/core", b, 50}};
        return r;
    };
    auto secondsAt = [](int step) { return 4.0 * (step / 2) + (step % 2 ? 1.0 : 0.0); };
    Pace priced, byRows;
    double worstByRows = 0;
    for (int step = 1; step < 10; ++step) {
        const double t = secondsAt(step), left = secondsAt(10) - t;
        const std::optional<double> p = priced.timeLeft(t, {readingAt(step, true)}),
                                    r = byRows.timeLeft(t, {readingAt(step, false)});
        ASSERT_TRUE(p && r);
        if (step < 4)
            continue;  // A and B each timed from the fourth step on (a job's first
                       // step of a stage calibrates, and is not timed)
        EXPECT_NEAR(*p, left, 1e-9) << "after step " << step;
        worstByRows = std::max(worstByRows, std::abs(*r - left) / left);
    }
    EXPECT_GT(worstByRows, 0.25);  // its last line: 2 s said with B's 3 s left
    // A stage not timed yet costs the mean row: A timed (0.1 s a row), B's first step not (it
    // calibrates), C's 10 rows 1 s.
    Pace fresh;
    auto reading = [](std::size_t a, std::size_t b) {
        return RowsDone{a + b, 40, {{"a/core", a, 20}, {"b/core", b, 10}, {"c/core", 0, 10}}};
    };
    fresh.timeLeft(1, {reading(10, 0)});
    fresh.timeLeft(2, {reading(20, 0)});
    const std::optional<double> left = fresh.timeLeft(5, {reading(20, 10)});
    ASSERT_TRUE(left);
    EXPECT_NEAR(*left, 1.0, 1e-9);
}

// Recorded runs of the class bench (docs/results-class.md), replayed: each job's rows as its
// file said them and each student's line with its job, seconds since the jobs started.
struct RecordedRows {
    double seconds;
    std::size_t job, done;
};
struct RecordedLine {
    double seconds;
    std::size_t job;
};
struct Recording {
    std::vector<RecordedRows> rows;
    std::vector<RecordedLine> lines;
    std::size_t jobs, total;  // rows a job
    double end;
};

// 40 one-stage hand-ins (2 jobs of 20; a busy loop on each core, 2026-11-30 11:40, load 2-3).
// Job 0's first round ran at 0.080 s a row, its later rounds at 0.048; job 1's at 0.051 and 0.053.
Recording oneStageBusy() {
    return {{
                // clang-format off
        {9.592, 0, 36}, {10.316, 1, 36}, {10.987, 1, 54}, {11.450, 0, 54}, {12.225, 1, 72},
        {12.483, 0, 72}, {12.893, 1, 90}, {14.019, 0, 90}, {14.072, 1, 108}, {14.896, 1, 126},
        {15.103, 0, 108}, {16.336, 1, 162}, {16.749, 0, 126}, {17.208, 1, 180}, {17.723, 0, 162},
        {18.439, 1, 198}, {19.101, 1, 216}, {19.154, 0, 180}, {20.129, 0, 198}, {20.387, 1, 234},
        {21.161, 1, 252}, {21.470, 0, 216}, {22.140, 0, 234}, {22.810, 1, 270}, {23.376, 0, 252},
        {23.791, 1, 306}, {24.050, 0, 270}, {25.184, 0, 306}, {25.494, 1, 324}, {25.851, 0, 324},
        {26.472, 1, 342}, {26.884, 0, 342}, {27.660, 0, 360}, {28.068, 1, 360}, {28.739, 0, 378},
        {29.147, 1, 378}, {29.403, 0, 396}, {30.552, 0, 414}, {30.754, 1, 396}, {31.613, 1, 414},
                // clang-format on
            },
            {
                // clang-format off
        {9.878, 0}, {10.494, 1}, {11.124, 1}, {11.449, 0}, {12.366, 1}, {12.695, 0},
        {13.025, 1}, {14.271, 0}, {14.283, 1}, {14.926, 1}, {15.262, 0}, {16.494, 1},
        {16.816, 0}, {17.445, 1}, {17.768, 0}, {18.691, 1}, {19.312, 0}, {19.326, 1},
        {20.252, 0}, {20.571, 1}, {21.190, 1}, {21.521, 0}, {22.462, 0}, {23.090, 1},
        {23.412, 0}, {24.049, 0}, {24.068, 1}, {25.318, 0}, {25.634, 1}, {25.952, 0},
        {26.605, 1}, {26.922, 0}, {27.865, 0}, {28.174, 1}, {28.805, 0}, {29.133, 1},
        {29.459, 0}, {30.592, 0}, {30.906, 1}, {31.872, 1},
                // clang-format on
            },
            2,
            414,
            31.897};
}

// 8 all-stage hand-ins (2 jobs of 4 in rounds of 1, 1 and 2; 2026-11-29 14:43, load 8): rows
// only (the bench kept no lines then); the end is the last rows'.
Recording allStage() {
    return {{
                // clang-format off
        {1.867, 1, 12}, {1.918, 0, 12}, {3.072, 1, 50}, {3.234, 1, 64}, {3.617, 1, 102},
        {4.032, 0, 50}, {4.491, 0, 64}, {5.268, 1, 134}, {5.631, 0, 102}, {6.874, 1, 170},
        {6.975, 0, 134}, {7.878, 1, 174}, {8.338, 0, 170}, {9.054, 0, 174}, {9.750, 1, 222},
        {9.914, 1, 234}, {10.686, 1, 272}, {10.941, 1, 286}, {11.170, 0, 222}, {11.322, 1, 324},
        {11.425, 0, 234}, {11.906, 1, 356}, {12.419, 0, 272}, {12.472, 1, 392}, {12.626, 0, 286},
        {12.915, 0, 324}, {13.130, 1, 396}, {13.954, 0, 356}, {14.366, 0, 392}, {14.902, 0, 396},
        {15.278, 1, 444}, {15.550, 1, 456}, {15.874, 1, 462}, {16.706, 1, 500}, {16.862, 0, 444},
        {17.114, 0, 456}, {17.317, 1, 519}, {17.374, 0, 462}, {17.525, 1, 533}, {17.932, 1, 540},
        {17.983, 0, 500}, {18.386, 0, 519}, {18.386, 1, 578}, {18.542, 0, 533}, {18.592, 1, 597},
        {18.642, 0, 540}, {18.945, 0, 578}, {19.201, 0, 597}, {19.657, 0, 629}, {20.115, 1, 629},
        {20.166, 0, 645}, {20.525, 0, 681}, {20.625, 1, 645}, {20.831, 0, 699}, {21.137, 0, 703},
        {21.292, 0, 705}, {21.601, 1, 681}, {22.079, 1, 699}, {22.653, 1, 703}, {22.812, 1, 705},
        {23.430, 0, 753}, {24.489, 0, 777}, {24.899, 1, 753}, {25.898, 1, 777},
                // clang-format on
            },
            {},
            2,
            777,
            25.898};
}

// Replays `rec` read every 0.3 s (as grade read until issue 39's last change). `pooled`: one
// Pace for every job, as grade has; else one a job, each at its own pace, and the most any says.
// `lag`: the lines told the Pace when they came. Returns the errors |said - left| / left of the
// lines after the first quarter but the last (it says "0 s" in any case), or without lines of
// the readings after the first quarter of the time with 1 s or more left.
std::vector<double> replayErrors(const Recording& rec, bool pooled, bool lag) {
    std::vector<Pace> paces(pooled ? 1 : rec.jobs);
    std::vector<RowsDone> jobs(rec.jobs, RowsDone{0, rec.total});
    auto said = [&](double t) {
        std::optional<double> most;
        for (std::size_t p = 0; p < paces.size(); ++p) {
            const std::optional<double> left =
                pooled ? paces[p].timeLeft(t, jobs) : paces[p].timeLeft(t, {jobs[p]});
            if (left && (!most || *left > *most)) most = left;
        }
        return most;
    };
    std::vector<double> errors;
    std::size_t nextRows = 0, nextLine = 0;
    for (double t = 0.3; t < rec.end; t += 0.3) {
        for (; nextRows < rec.rows.size() && rec.rows[nextRows].seconds <= t; ++nextRows)
            jobs[rec.rows[nextRows].job].done = rec.rows[nextRows].done;
        const std::optional<double> left = said(t);
        if (rec.lines.empty() && left && 4 * t > rec.end && rec.end - t >= 1.0)
            errors.push_back(std::abs(*left - (rec.end - t)) / (rec.end - t));
        for (; nextLine < rec.lines.size() && rec.lines[nextLine].seconds <= t; ++nextLine) {
            const RecordedLine& line = rec.lines[nextLine];
            if (lag) paces[pooled ? 0 : line.job].recordBack(t, pooled ? line.job : 0, 0);
            const double real = rec.end - line.seconds;
            if (4 * (nextLine + 1) > rec.lines.size() && nextLine + 1 < rec.lines.size() && left)
                errors.push_back(std::abs(*left - real) / real);
        }
    }
    std::sort(errors.begin(), errors.end());
    return errors;
}

std::size_t over25(const std::vector<double>& errors) {
    return std::size_t(
        std::count_if(errors.begin(), errors.end(), [](double e) { return e > 0.25; }));
}

// The runs of the class bench recorded since issue 39's stop 51 (tests/course/progress_runs/,
// one JSON line a run: bench_grade.py --trace): each job's file as it changed, and the lines.
// Replayed at the run's poll, each line said at the first reading at or after it: the errors
// of the lines after the first quarter but the last. `priced`: the readings as the files say
// them; else without their stages and step (the rows alone, as before stop 51).
std::vector<double> replayRecorded(const nlohmann::json& run, bool priced) {
    const double poll = run.value("poll_s", 0.1);
    std::vector<std::pair<double, std::string>> lines;  // "[student ...]" lines: time, name
    double end = run["end_s"];
    for (const auto& l : run["lines"]) {
        const std::string text = l[1];
        if (text.rfind("graded", 0) == 0) end = l[0];
        char name[256];
        if (std::sscanf(text.c_str(), "[student %*zu of %*zu] %255s", name) == 1)
            lines.emplace_back(l[0], name);
    }
    std::vector<std::string> names;
    for (const auto& l : lines) names.push_back(l.second);
    std::sort(names.begin(), names.end());
    std::size_t jobs = 0;
    for (const auto& p : run["progress"]) jobs = std::max(jobs, std::size_t(p[1]) + 1);
    std::vector<RowsDone> files(jobs);
    Pace pace;
    std::vector<double> errors;
    std::size_t next = 0, line = 0;
    const auto& progress = run["progress"];
    for (double t = progress[0][0]; line < lines.size(); t += poll) {
        for (; next < progress.size() && double(progress[next][0]) <= t; ++next) {
            const auto& p = progress[next];
            RowsDone& r = files[std::size_t(p[1])];
            r = RowsDone{p[2], p[3]};
            if (!priced) continue;
            for (const auto& [key, n] : p[4].items())
                r.stages.push_back({key, n[0], n[1], n[2], n[3]});
            r.underwayRows = p[5][0];
            r.underwayViews = p[5][1];
            r.underwayKey = p[5][2];
        }
        const std::optional<double> said = pace.timeLeft(t, files);
        for (; line < lines.size() && lines[line].first <= t + 1e-9; ++line) {
            const std::size_t k = std::size_t(
                std::find(names.begin(), names.end(), lines[line].second) - names.begin());
            pace.recordBack(t, k % jobs, 0);  // grade deals its students in turn
            const double left = end - lines[line].first;
            if (4 * (line + 1) > lines.size() && line + 1 < lines.size() && said)
                errors.push_back(std::abs(*said - left) / std::max(left, 0.1));
        }
    }
    return errors;
}

// Each job's rows at the jobs' pace (issue 39): in the one-stage run job 0's slow first round
// said 40 % too much through its next round at its own pace; the all-stage run's readings too
// are nearer the time left at the jobs' pace. Fewer over 25 % and a smaller median, each.
TEST(ClassProgress, EveryJobAtTheJobsPace) {
    for (const Recording& rec : {oneStageBusy(), allStage()}) {
        const std::vector<double> jobs = replayErrors(rec, true, true),
                                  own = replayErrors(rec, false, true);
        ASSERT_EQ(jobs.size(), own.size());
        ASSERT_GT(jobs.size(), 20u);
        EXPECT_LT(over25(jobs), over25(own))
            << jobs.size() << (rec.lines.empty() ? " readings" : " lines");
        EXPECT_LT(jobs[jobs.size() / 2], own[own.size() / 2]);
        std::printf("over 25 %%: %zu of %zu at the jobs' pace, %zu at each job's own\n",
                    over25(jobs), jobs.size(), over25(own));
    }
}

// A line came at the poll its rows were read at or one later (0 or 0.3 s; 0.14 s on average in
// the one-stage run): no row counts that time, so without it the last lines said too little.
TEST(ClassProgress, AStudentsLineComesAfterItsRows) {
    const std::vector<double> with = replayErrors(oneStageBusy(), true, true),
                              without = replayErrors(oneStageBusy(), true, false);
    EXPECT_LT(over25(with), over25(without));
    std::printf("lines after the quarter over 25 %%: %zu with the records' lag, %zu without\n",
                over25(with), over25(without));
}

// Each stage's rows and each round's views at their prices, and the step under way (issue 39),
// replayed on the runs recorded since: fewer lines over 25 % than by rows alone, and a smaller
// median, over all of them and over the all-stage runs.
TEST(ClassProgress, RecordedRunsPricedByStageAndViews) {
    std::size_t runs = 0, allStage = 0;
    std::vector<double> priced, byRows, pricedAll, byRowsAll;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(SHADOWLAB_SOURCE_DIR) +
                                                                 "/tests/course/progress_runs")) {
        std::ifstream in(entry.path());
        for (std::string text; std::getline(in, text);) {
            const nlohmann::json run = nlohmann::json::parse(text);
            if (run["progress"].empty() || run["progress"][0].size() < 6) continue;  // before
            const std::vector<double> p = replayRecorded(run, true), r = replayRecorded(run, false);
            ASSERT_EQ(p.size(), r.size());
            priced.insert(priced.end(), p.begin(), p.end());
            byRows.insert(byRows.end(), r.begin(), r.end());
            ++runs;
            if (run["class"] != "class-all") continue;
            pricedAll.insert(pricedAll.end(), p.begin(), p.end());
            byRowsAll.insert(byRowsAll.end(), r.begin(), r.end());
            ++allStage;
        }
    }
    ASSERT_GE(runs, 10u);
    ASSERT_GE(allStage, 5u);
    for (auto* e : {&priced, &byRows, &pricedAll, &byRowsAll}) std::sort(e->begin(), e->end());
    EXPECT_LT(over25(priced), over25(byRows));
    EXPECT_LT(priced[priced.size() / 2], byRows[byRows.size() / 2]);
    EXPECT_LT(over25(pricedAll), over25(byRowsAll));
    EXPECT_LT(pricedAll[pricedAll.size() / 2], byRowsAll[byRowsAll.size() / 2]);
    std::printf(
        "%zu runs (%zu all-stage): %zu of %zu lines over 25 %% priced, %zu by rows; "
        "all-stage %zu and %zu of %zu\n",
        runs, allStage, over25(priced), priced.size(), over25(byRows), over25(pricedAll),
        over25(byRowsAll), pricedAll.size());
}

TEST(ClassProgress, JobFilesReadOneByOneBadOnesCountNothing) {
    const std::string dir = ::testing::TempDir();
    const std::string a = dir + "/job-a.progress", b = dir + "/job-b.progress",
                      bad = dir + "/job-bad.progress";
    const std::string unsummed = dir + "/job-unsummed.progress";
    auto put = [](const std::string& path, const char* text) {
        FILE* f = std::fopen(path.c_str(), "w");
        std::fputs(text, f);
        std::fclose(f);
    };
    put(a, "3 10 0 0 0\n");
    put(b, "                   7                   20 4 2 1\n 5 8 0 2 a/core\n 2 8 0 2 b/core\n");
    put(bad, "9 2 0 0 0\n");                                        // more done than planned
    put(unsummed, "7 20 4 0 1\n5 8 0 2 a/core\n1 8 0 2 b/core\n");  // the stages' are 6
    std::vector<RowsDone> jobs = readProgress({a, b, bad, unsummed, dir + "/job-none.progress"});
    ASSERT_EQ(jobs.size(), 5u);
    EXPECT_EQ(jobs[0].done, 3u);
    EXPECT_EQ(jobs[0].total, 10u);
    EXPECT_EQ(jobs[0].underwayRows, 0u);
    EXPECT_EQ(jobs[1].done, 7u);
    EXPECT_EQ(jobs[1].total, 20u);
    ASSERT_EQ(jobs[1].stages.size(), 2u);
    EXPECT_EQ(jobs[1].stages[1].key, "b/core");
    EXPECT_EQ(jobs[1].stages[1].done, 2u);
    EXPECT_EQ(jobs[1].underwayRows, 4u);
    EXPECT_EQ(jobs[1].underwayViews, 2u);
    EXPECT_EQ(jobs[1].underwayKey, "b/core");
    EXPECT_EQ(jobs[2].total, 0u);  // torn or foreign: counts nothing
    EXPECT_EQ(jobs[3].total, 0u);
    EXPECT_EQ(jobs[4].total, 0u);
}

// Markers by one tokenizer (issue 38): any run of spaces or tabs, Unicode spaces, invisible
// characters and dashes between the words is a look-alike refused naming file and line, so no
// release ships the region's solution as ordinary code.
TEST(SolutionMarkers, UnicodeAndSpacingLookAlikesRefuse) {
    std::vector<std::string> between = {
        "    ",         "\t",           " \t ",         "\xC2\xA0",     "\xE3\x80\x80",
        "\xEF\xBB\xBF", "\xE2\x80\x8B", "\xE2\x80\x8C", "\xE2\x80\x8D", " \xE2\x80\x8B"};
    for (unsigned code = 0x2000; code <= 0x200A; ++code)  // EN QUAD ... HAIR SPACE
        between.push_back(std::string{'\xE2', '\x80', char(0x80 | (code & 0x3f))});
    for (unsigned code = 0x2010; code <= 0x2015; ++code)  // HYPHEN ... HORIZONTAL BAR
        between.push_back(std::string{'\xE2', '\x80', char(0x80 | (code & 0x3f))});
    between.push_back("\xE2\x88\x92");  // MINUS SIGN
    std::vector<std::string> lines;
    for (const std::string& b : between) {
        lines.push_back("// BEGIN" + b + "SOLUTION");
        lines.push_back("//" + b + "END" + b + "SOLUTION");
    }
    // Invisible characters around or inside the exact form; a Unicode indentation.
    for (const char* line : {"// BEGIN SOLUTION\xE2\x80\x8B", "\xEF\xBB\xBF// BEGIN SOLUTION",
                             "\xC2\xA0// BEGIN SOLUTION", "// BEGIN SOLU\xE2\x80\x8BTION",
                             "// \xE2\x80\x8B"
                             "BEGIN SOLUTION",
                             "//\xC2\xA0STUB: x;"})
        lines.push_back(line);
    for (const std::string& line : lines) {
        std::string text = "a\n  " + line + "\n  secret();\n  // END SOLUTION\n";
        try {
            std::string shipped = stripSolutions(text, "f.frag");
            ADD_FAILURE() << "accepted (would ship 'secret();'): " << line;
        } catch (const AssignmentError& e) {
            EXPECT_EQ(std::string(e.what()).rfind("f.frag: line 2: '", 0), 0u) << e.what();
            EXPECT_NE(std::string(e.what()).find("looks like a solution marker"), std::string::npos)
                << e.what();
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
        }
    }
}

// A line of a million spaces (or a million dashes before a word) is an ordinary line, read in
// one pass: it once overflowed the stack of a backtracking regular expression (SIGSEGV).
TEST(SolutionMarkers, AMillionSpacesIsAnOrdinaryLine) {
    const std::string spaces(1000000, ' ');
    const std::string text = "a\n" + spaces + "\n" + std::string(1000000, '-') + "x\n";
    EXPECT_EQ(stripSolutions(text, "f"), text);
    EXPECT_THROW(stripSolutions("//" + spaces + "BEGIN" + spaces + "SOLUTION\n", "f"),
                 AssignmentError);
}

// Roster names with ESC or BEL reach no page raw (issue 38), and a student not graded is charged
// nothing by the late policy.
TEST(StudentPage, ControlCharactersAreNotText) {
    EXPECT_EQ(esc("a\x1b[31mb\x07<"), "a?[31mb?&lt;");
    StudentRecord r = oneStage("ann", "rgb", Status::Pass, 2, 2);
    r.score = r.maxScore = 2;
    r.roster = RosterInfo{"7", "Ann\x1b]0;pwned\x07 Lee", "a@b"};
    const std::string page = studentPage(r);
    EXPECT_EQ(page.find('\x1b'), std::string::npos);
    EXPECT_EQ(page.find('\x07'), std::string::npos);
    EXPECT_NE(page.find("Ann?]0;pwned? Lee"), std::string::npos);
}

TEST(StudentPage, NotGradedIsChargedNothing) {
    StudentRecord r = oneStage("ann", "rgb", Status::NotGraded, 0, 0);
    LateRecord late;
    late.days = 2;
    late.minutes = 2000;
    late.handedIn = "2026-12-06T10:59:00Z";
    r.late = late;
    const std::string page = studentPage(r);
    EXPECT_NE(page.find("not graded yet"), std::string::npos);
    EXPECT_EQ(page.find("charged by the late policy"), std::string::npos) << page;
    StudentRecord graded = oneStage("bob", "rgb", Status::Pass, 2, 2);
    graded.score = graded.maxScore = 2;
    graded.late = late;
    EXPECT_NE(studentPage(graded).find("charged by the late policy"), std::string::npos);
}

// A hidden stage's result is not on the student's page (issue 38): neither named nor scored.
TEST(StudentPage, AHiddenStageIsNotShown) {
    StudentRecord r = oneStage("ann", "rgb", Status::Pass, 2, 2);
    StageRecord secret;
    secret.stage = "margin";
    secret.tree = "core";
    secret.visibility = "hidden";
    secret.status = Status::Fail;
    secret.maxPoints = 10;
    secret.message = "0 of 5 checks show the lesson";
    r.stages.push_back(secret);
    r.score = 2;
    r.maxScore = 12;
    const std::string page = studentPage(r);
    EXPECT_EQ(page.find("2.00 of 12.00"), std::string::npos) << page;  // 12 - 2: the hidden max
    EXPECT_NE(page.find("rgb/core"), std::string::npos);
    EXPECT_EQ(page.find("margin/core"), std::string::npos) << page;
    EXPECT_EQ(page.find("0 of 5 checks"), std::string::npos) << page;
    EXPECT_NE(page.find("1 more stage is graded but hidden"), std::string::npos) << page;
}

// Hidden rows are counted nowhere a student sees (issue 39): "1 of 3 checks" beside two rows
// shown, one of them passing, would say the hidden row failed; so would its points in the
// stage's header, a count of hidden rows, or the total (less the stages shown: the hidden row's
// points), in the head line or the late policy's.
TEST(StudentPage, HiddenRowsAreCountedNowhere) {
    StagePlan plan;
    plan.stage = "rgb";
    plan.tree = "core";
    std::vector<CheckResult> results;
    for (const char* visibility : {"visible", "after_due_date", "hidden"}) {
        RowPlan row;
        row.check.view = std::string("view-") + visibility;
        row.points = 5;
        row.visibility = visibility;
        plan.rows.push_back(row);
        CheckResult r;
        r.stage = "rgb";
        r.tree = "core";
        r.status = results.empty() ? Status::Pass : Status::Fail;
        results.push_back(r);
    }
    StudentRecord rec;
    rec.student = "ann";
    rec.stages = {stageRecord(plan, &results, "")};
    rec.score = 5;
    rec.maxScore = 15;
    LateRecord late;
    late.days = 1;
    late.minutes = 600;
    late.penalty = 0.5;
    rec.late = late;
    EXPECT_EQ(rec.stages[0].message, "1 of 2 visible checks show the lesson");
    const SeenStage seen = seenStage(rec.stages[0]);
    EXPECT_EQ(seen.seen, 2);
    EXPECT_EQ(seen.hidden, 1);
    EXPECT_DOUBLE_EQ(seen.maxPoints, 10);
    const std::string page = studentPage(rec);
    EXPECT_NE(page.find("1 of 2 visible checks"), std::string::npos) << page;
    EXPECT_NE(page.find("rgb/core: 5.00 of 10.00 points"), std::string::npos) << page;
    EXPECT_EQ(page.find("of 15.00 points"), std::string::npos) << page;  // with the hidden row
    EXPECT_EQ(page.find("view-hidden"), std::string::npos) << page;
    EXPECT_EQ(page.find(" more checks"), std::string::npos) << page;  // no count of them
    EXPECT_NE(page.find("graded but hidden"), std::string::npos) << page;
    EXPECT_EQ(page.find(" of 15.00"), std::string::npos) << page;  // the total, 4.50 of 15.00
    EXPECT_EQ(page.find("after the penalty"), std::string::npos) << page;
    EXPECT_NE(page.find("charged by the late policy: 0.50 points off"), std::string::npos);
    EXPECT_NE(page.find("your total is in your course's gradebook"), std::string::npos) << page;
    // Without the hidden row the total is there, as the class page and gradebook show it.
    rec.stages[0].rows.pop_back();
    rec.maxScore = 10;
    EXPECT_NE(studentPage(rec).find("4.50 of 10.00 points"), std::string::npos);
}

// A kept record holds each row's points to 3 decimals and the stage's exactly: 19 rows of
// 20/19 points add up to 20.007 there. The page's stage shows what grades.csv and the class page
// show (20.00 of 20.00), not the rounded rows' sum (20.01), with and without a hidden row.
TEST(StudentPage, AStagesPointsAreTheStagesNotItsRoundedRowsSum) {
    for (const bool withHidden : {false, true}) {
        StagePlan plan;
        plan.stage = "rgb";
        plan.tree = "core";
        std::vector<CheckResult> results;
        const int rows = withHidden ? 20 : 19;
        for (int k = 0; k < rows; ++k) {
            RowPlan row;
            row.check.view = "view-" + std::to_string(k);
            row.points = 20.0 / 19;
            row.visibility = withHidden && k == rows - 1 ? "hidden" : "visible";
            plan.rows.push_back(row);
            CheckResult r;
            r.stage = "rgb";
            r.tree = "core";
            r.status = Status::Pass;
            results.push_back(r);
        }
        StudentRecord rec;
        rec.student = "ann";
        rec.stages = {stageRecord(plan, &results, "")};
        const StudentRecord kept = recordFromJson(keptRecordJson(rec));
        const SeenStage seen = seenStage(kept.stages[0]);
        EXPECT_NEAR(seen.maxPoints, 20, 1e-9) << (withHidden ? "with a hidden row" : "");
        EXPECT_NEAR(seen.points, 20, 1e-9) << (withHidden ? "with a hidden row" : "");
        EXPECT_NE(studentPage(kept).find("rgb/core: 20.00 of 20.00 points"), std::string::npos);
    }
}

// A failing row's page names each failing figure, its value and its bound as the record's
// reasons hold them (grade/judge.h), in the figure table's words and units; the message is never
// read: a reworded judge message changes nothing the page lists, the record's numbers do.
StudentRecord failingMirror(const std::string& message, double psnr) {
    StudentRecord r = oneStage("ann", "mirror", Status::Fail, 0, 10);
    r.maxScore = 10;
    RowRecord row;
    row.maxPoints = 10;
    row.result.stage = "mirror";
    row.result.tree = "core";
    row.result.view = "front";
    row.result.status = Status::Fail;
    row.result.message = message;
    using Side = FigureReason::Side;
    row.result.reasons = {{"mirror_psnr_db", psnr, Side::AtLeast, 32, false},
                          {"mirror_id_pct", 99.5, Side::AtLeast, 95, true},
                          {"edge_p95_px", 7.6, Side::AtMost, 7.5, false}};
    r.stages[0].rows = {row};
    return r;
}

TEST(StudentPage, AFailingRowNamesItsFiguresFromTheRecordNotTheMessage) {
    const std::string judged =
        "expected reflection right, but mirror_psnr_db 18.7 not >= 32, edge_p95_px 7.6 not <= "
        "7.5";
    const std::string page = studentPage(failingMirror(judged, 18.7));
    const std::string psnr =
        "your mirror&#39;s PSNR against the exact (stencil) reflection is 18.7 dB, and should be "
        "at least 32 dB";
    const std::string edge =
        "the distance within which 95 % of your shadow edges lie is 7.6 px, "
        "and should be at most 7.5 px";
    EXPECT_NE(page.find(psnr), std::string::npos) << page;
    EXPECT_NE(page.find(edge), std::string::npos) << page;
    EXPECT_EQ(page.find("the mirror showing the right object is"), std::string::npos) << page;
    // A reworded message (or one naming other numbers) lists the same figures.
    for (const char* reworded : {"PSNR too low; edges too far", "mirror_psnr_db 5 not >= 99",
                                 "expected reflection right, but mirror_id_pct 1 not >= 95"})
        EXPECT_EQ(studentPage(failingMirror(reworded, 18.7)), page) << reworded;
    // The record's value is what the page shows, whatever the message says.
    EXPECT_NE(studentPage(failingMirror(judged, 20.25)).find("is 20.2 dB, and should be at least"),
              std::string::npos);
}

// A drawn pair's reason (false_shadow_pct's change from margin=0.00053, judgeResponse) is worded
// from the figure table as the change from the row before, with its unit.
TEST(StudentPage, ADrawnPairsReasonIsTheChangeInItsFigure) {
    StudentRecord r = failingMirror("changes by 0, not >= 3.2", 0);
    r.stages[0].rows[0].result.reasons = {
        {"false_shadow_pct", 0, FigureReason::Side::AtLeast, 3.2, false, "margin=0.00053"}};
    const std::string page = studentPage(r);
    EXPECT_NE(page.find("the change in the surfaces the light reaches drawn in shadow from the "
                        "row before (at margin=0.00053) to this one is 0 %, and should be at "
                        "least 3.2 %"),
              std::string::npos)
        << page;
    r.stages[0].rows[0].result.reasons[0].changeFrom.clear();  // the figure itself
    EXPECT_EQ(studentPage(r).find("the change in"), std::string::npos);
}

// A row kept before reasons existed (last term's record, regraded or resumed) shows its message.
TEST(StudentPage, ARowWithoutReasonsShowsItsMessage) {
    StudentRecord r =
        failingMirror("expected reflection right, but mirror_psnr_db 18.7 not >= 32", 18.7);
    r.stages[0].rows[0].result.reasons.clear();
    const std::string page = studentPage(r);
    EXPECT_NE(page.find("That is not what this check expects: expected reflection right, but "
                        "mirror_psnr_db 18.7 not &gt;= 32."),
              std::string::npos)
        << page;
    EXPECT_EQ(page.find("should be at least"), std::string::npos) << page;
}

// The release's README tells a student how to install shadowlab and, when the assignment has
// one, its late policy (issue 39: a class charged late without having been told how).
TEST(ReleaseReadme, SaysHowToInstallAndTheLatePolicy) {
    const char* text =
        R"({"name": "lab", "stages": [{"stage": "margin", "files": ["margin/lit.frag"],
      "points": 10}], "late": {"deadline": "2026-12-04T23:59:00+01:00", "grace_minutes": 15,
      "penalty_per_day": 10, "cap": 30}})";
    const std::string dir = ::testing::TempDir() + "/release-readme";
    std::filesystem::remove_all(dir);
    writeRelease(parseAssignment(text, "lab.json"), {}, dir);
    std::ifstream in(dir + "/README.md");
    std::string readme((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(readme.find("## Install shadowlab"), std::string::npos) << readme;
    EXPECT_NE(readme.find("cmake --install build --prefix"), std::string::npos) << readme;
    EXPECT_NE(readme.find("Deadline: 2026-12-04T23:59:00+01:00, with 15 minutes of grace. After "
                          "it, each day or part of a day costs 10 % of the assignment's points, "
                          "at most 30 % in all"),
              std::string::npos)
        << readme;
    std::filesystem::remove_all(dir);
    const char* onTime = R"({"name": "lab", "stages": [{"stage": "margin",
      "files": ["margin/lit.frag"], "points": 10}]})";
    writeRelease(parseAssignment(onTime, "lab.json"), {}, dir);
    std::ifstream again(dir + "/README.md");
    readme.assign((std::istreambuf_iterator<char>(again)), std::istreambuf_iterator<char>());
    EXPECT_EQ(readme.find("Late policy"), std::string::npos) << readme;
    EXPECT_NE(readme.find("## Install shadowlab"), std::string::npos) << readme;
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sl
