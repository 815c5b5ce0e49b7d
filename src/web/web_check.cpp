// The page's `check` (issue: check in the browser; docs/web.md): the native check's plan, rows,
// judge and record (grade/check_plan.h, grade/check_steps.h), run in the page a row at a time so
// it stays responsive between rows. The page calls these; each returns JSON text that stays
// valid until the next call.
#include <emscripten/emscripten.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "course/assignment.h"
#include "course/student_grade.h"
#include "eval/trace_view.h"
#include "gl/gl.h"
#include "grade/check_plan.h"
#include "grade/check_steps.h"
#include "grade/intake.h"
#include "grade/reports.h"
#include "io/files.h"
#include "io/usage_error.h"
#include "stages/expectations.h"
#include "stages/registry.h"
#include "web/taken_folder.h"

namespace {

constexpr const char* kPictures = "/check";  // the rows' pictures, in the page's memory
// The assignment file the page found beside it or the student picked (index.html writes it).
constexpr const char* kAssignment = "/assignment/assignment.json";

struct PageCheck {
    std::unique_ptr<sl::CheckSteps> steps;
    std::vector<unsigned char> given;  // a reference's bytes from a worker (sl_web_check_buffer)
    std::string snapshot, shown;       // the checked folder's snapshot, named as picked
    bool namesRelative = false;  // an assignment's check names files as in the hand-in, as natively
    int snapshots = 0;
    std::string text;
};

PageCheck& pageCheck() {
    static PageCheck c;
    return c;
}

const char* handOver(const nlohmann::json& j) {
    pageCheck().text = j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    return pageCheck().text.c_str();
}

// What the page lists of a stage's record: its line and its rows', as `check` prints them.
nlohmann::json stageJson(const sl::StageRecord& st) {
    nlohmann::json rows = nlohmann::json::array();
    for (const sl::RowRecord& row : st.rows)
        rows.push_back({{"name", sl::checkTestName(row.result)},
                        {"verdict", row.result.verdict()},
                        {"points", row.points},
                        {"max_points", row.maxPoints},
                        {"message", row.result.message},
                        {"diff", row.result.diffFile}});
    return {{"stage", st.stage},
            {"tree", st.tree},
            {"status", sl::statusName(st.status)},
            {"points", st.points},
            {"max_points", st.maxPoints},
            {"message", st.message},
            {"rows", rows}};
}

// The folder last picked, taken again by the intake for `stages` (and an assignment's `listed`
// files), as `check --shaders` takes it, into `work` (our shaders when none is picked). Returns
// whether one was; a refusal throws IntakeError naming the folder as picked.
bool takePicked(const std::vector<std::string>& stages, const std::set<std::string>& listed,
                sl::StudentWork& work, sl::Submission& submission) {
    PageCheck& c = pageCheck();
    const sl::web::PickedFolder picked = sl::web::pickedFolder();
    work.name = "shipped shaders";
    if (picked.path.empty()) return false;
    if (!c.snapshot.empty()) std::filesystem::remove_all(c.snapshot);
    c.snapshot = "/student/check-" + std::to_string(++c.snapshots);
    std::filesystem::create_directories(c.snapshot);
    work.name = picked.name;
    try {
        submission =
            sl::takeSubmission(picked.path, c.snapshot, sl::shippedTrees().both, stages, listed);
    } catch (const sl::IntakeError& e) {
        throw sl::IntakeError(sl::web::asPicked(e.what()));
    }
    c.shown = sl::web::shownAsPicked(picked, submission.folder);
    for (std::string& note : submission.notes) note = sl::web::asPicked(note);
    work.overlay = c.snapshot;
    work.files = submission.files;
    work.notes = submission.notes;
    work.hash = submission.hash;
    return true;
}

// The plan `check --stage STAGE` (or `--all`) grades over the folder last picked (a refusal is
// its UsageError).
sl::GradingPlan planFor(const std::string& what, std::uint64_t seed, sl::StudentWork& work,
                        std::vector<std::string>& notes) {
    sl::StageCheckArgs args;
    args.all = what == "all";
    args.base.stage = args.all ? sl::stageRegistry().front().id : what;
    args.glslGiven = true;  // the browser runs the core tree only
    args.settings.seed = seed;
    std::vector<sl::RenderRequest> requests;
    std::vector<std::string> stages;
    for (sl::RenderRequest& r : sl::checkRequests(args, notes)) {
        const sl::StageInfo* info = sl::findStage(r.stage);
        if (info && info->legacyOnly) {
            notes.push_back("stage " + r.stage + " runs in the native program only: not checked");
            continue;
        }
        sl::validateRequest(r);
        requests.push_back(r);
        stages.push_back(r.stage);
    }
    if (requests.empty()) throw sl::UsageError("stage " + what + ": nothing the browser can check");
    sl::Submission submission;
    bool picked = false;
    try {
        picked = takePicked(stages, {}, work, submission);
    } catch (const sl::IntakeError& e) {
        throw sl::UsageError(e.what());
    }
    notes.insert(notes.end(), work.notes.begin(), work.notes.end());
    for (sl::RenderRequest& r : requests) r.overlay = work.overlay;
    return sl::defaultPlan(args, requests, picked ? &submission : nullptr);
}

// The plan `check --assignment A.json --shaders FOLDER` grades: the assignment's due stages, its
// points and views (the file the course publishes beside the page, kAssignment). A stage due in
// the legacy tree is the native program's: left out, and the notes say so. A folder that replaces
// no shipped file is every stage MISSING, as natively.
sl::GradingPlan assignmentPlan(std::uint64_t seed, sl::StudentWork& work,
                               std::vector<std::string>& notes) {
    sl::Assignment a = sl::loadAssignment(kAssignment);
    for (sl::AssignmentStage& st : a.stages) {
        const sl::StageInfo* info = sl::findStage(st.stage);
        if (!st.due || (st.tree != "legacy" && !(info && info->legacyOnly))) continue;
        st.due = false;
        char points[32];
        std::snprintf(points, sizeof points, "%g", st.points);
        notes.push_back("stage " + st.stage + " (" + st.tree + " tree, " + points +
                        " points) is checked by the native program only: not in this total");
    }
    if (a.due().empty()) throw sl::UsageError(a.name + ": nothing due that the browser can check");
    std::set<std::string> listed;
    for (const sl::AssignmentStage* st : a.due()) listed.insert(st->files.begin(), st->files.end());
    sl::Submission submission;
    try {
        if (!takePicked(sl::dueStageNames(a), listed, work, submission))
            throw sl::UsageError("check by " + a.name + ": pick your folder first (as --shaders)");
    } catch (const sl::IntakeError& e) {
        work.error = e.what();  // every due stage MISSING, as `check --assignment` grades it
    }
    for (const std::string& note : sl::unlistedFileNotes(a, work)) work.notes.push_back(note);
    notes.insert(notes.end(), work.notes.begin(), work.notes.end());
    if (!work.error.empty()) notes.push_back(work.error);
    return sl::planStudent(a, work, seed);
}

}  // namespace

extern "C" {

// Plans `check --stage WHAT` (or every stage the browser runs: "all") over the student's folder
// on screen (ours when none), with the displaced views' seed `seed` (decimal; "" draws one).
// {"rows", "seed", "notes", "plan"} or {"error"}.
EMSCRIPTEN_KEEPALIVE const char* sl_web_check_begin(const char* what, const char* seed) {
    PageCheck& c = pageCheck();
    c.steps.reset();
    try {
        std::uint64_t drawn = *seed ? std::stoull(seed) : sl::drawSeed();
        sl::StudentWork work;
        std::vector<std::string> notes;
        c.namesRelative = std::string(what) == "assignment";
        sl::GradingPlan plan = c.namesRelative ? assignmentPlan(drawn, work, notes)
                                               : planFor(what, drawn, work, notes);
        // A row that does not pass keeps its render, truth and difference for the page to show.
        for (sl::StagePlan& st : plan.stages)
            for (sl::RowPlan& row : st.rows) row.check.pictures = sl::RowPictures::AllUnlessPassing;
        std::filesystem::remove_all(kPictures);
        std::filesystem::create_directories(kPictures);
        // Named by what the row checks, as native `check --diff-dir` names them.
        auto picture = [](const sl::CheckCase& c) {
            return std::string(kPictures) + "/" + sl::rowSlug(c) + ".png";
        };
        c.steps = std::make_unique<sl::CheckSteps>(plan, work, drawn, picture);
        return handOver({{"rows", c.steps->rowCount()},
                         {"seed", std::to_string(drawn)},
                         {"notes", notes},
                         {"plan", plan.name}});
    } catch (const std::exception& e) {
        return handOver({{"error", e.what()}});
    }
}

// Runs the next row: {"done", "rows", "row" (its check JSON, or null), "stages" (records made by
// this step), "finished"}.
EMSCRIPTEN_KEEPALIVE const char* sl_web_check_step() {
    PageCheck& c = pageCheck();
    if (!c.steps) return handOver({{"error", "no check running"}});
    nlohmann::json made = nlohmann::json::array();
    if (c.namesRelative)
        sl::showFolderAs("", "");
    else if (!c.snapshot.empty())
        sl::showFolderAs(c.snapshot, c.shown);  // messages name its files
    for (const sl::StageRecord& st : c.steps->step()) made.push_back(stageJson(st));
    sl::web::nameDrawnFolder();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);  // the page's own picture is the canvas's
    const auto& row = c.steps->lastRow();
    return handOver({{"done", c.steps->rowsDone()},
                     {"rows", c.steps->rowCount()},
                     {"traced_here", c.steps->tracedHere()},
                     {"traced_by_workers", c.steps->givenUsed()},
                     {"row", row ? sl::checkJson(*row) : nlohmann::json()},
                     {"name", row ? sl::checkTestName(*row) : ""},
                     {"stages", made},
                     {"finished", c.steps->done()}});
}

// The views the next stage's references are traced from, for the page's Web Workers (before
// that stage's first step; eval/trace_view.h): [{"key", "view"}], empty when there are none.
EMSCRIPTEN_KEEPALIVE const char* sl_web_check_views() {
    PageCheck& c = pageCheck();
    nlohmann::json views = nlohmann::json::array();
    if (c.steps)
        for (const sl::TraceView& v : c.steps->viewsToTrace())
            views.push_back({{"key", sl::traceKey(v)}, {"view", sl::traceViewJson(v)}});
    return handOver(views);
}

// Room for `bytes` of a reference a worker traced: the page copies them there, then gives them.
EMSCRIPTEN_KEEPALIVE unsigned char* sl_web_check_buffer(int bytes) {
    PageCheck& c = pageCheck();
    c.given.assign(std::size_t(std::max(bytes, 0)), 0);
    return c.given.data();
}

// The reference of the view `key` as a worker traced it (its bytes in sl_web_check_buffer's
// room): {} when taken, else {"error"} (the row then traces it on the page's thread).
EMSCRIPTEN_KEEPALIVE const char* sl_web_check_give(const char* key, int width, int height,
                                                   int mirrorObjectId) {
    PageCheck& c = pageCheck();
    if (!c.steps) return handOver({{"error", "no check running"}});
    try {
        c.steps->giveReference(key, sl::referenceFromBytes(width, height, mirrorObjectId,
                                                           c.given.data(), c.given.size()));
        c.given.clear();
        c.given.shrink_to_fit();
        return handOver(nlohmann::json::object());
    } catch (const std::exception& e) {
        return handOver({{"error", e.what()}});
    }
}

// The report `check --report` writes for the same run (its record and the expectations file),
// and the summary lines `check` prints: {"report", "summary", "exit"}.
EMSCRIPTEN_KEEPALIVE const char* sl_web_check_report() {
    PageCheck& c = pageCheck();
    if (!c.steps) return handOver({{"error", "no check has run"}});
    sl::StudentRecord record = c.steps->record();
    record.tool = "shadowlab check (browser)";
    nlohmann::json report = sl::recordJson(record);
    report["expectations"] = sl::expectationsPath();
    return handOver(
        {{"report", report.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n"},
         {"summary", sl::stageSummary(record)},
         {"exit", record.exitCode()}});
}

}  // extern "C"
