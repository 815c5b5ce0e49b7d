#include "grade/check_session.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <set>

#include "grade/bounds.h"
#include "grade/check_plan.h"
#include "grade/reports.h"
#include "io/files.h"
#include "io/json_fields.h"
#include "io/usage_error.h"
#include "sandbox/private_dir.h"
#include "scene/scene_json.h"
#include "stages/drawn.h"
#include "stages/drawn_figures.h"
#include "stages/registry.h"
#include "stages/stage.h"

namespace sl {

namespace {

namespace fs = std::filesystem;

std::string canonicalOutput(const std::string& path) {
    std::error_code ec;
    fs::path absolute = fs::absolute(path, ec);
    fs::path c = fs::weakly_canonical(absolute, ec);
    return (ec ? absolute.lexically_normal() : c).string();
}

void requireWritable(const std::string& option, const std::string& path) {
    if (std::string why = outputPathProblem(path); !why.empty())
        throw UsageError(option + ": " + why);
}

void writeOutput(const std::string& option, const std::string& path, const std::string& text) {
    std::string err = writeFileAtomically(path, text.data(), text.size());
    if (!err.empty()) throw UsageError(option + ": " + err);
}

// The file a row's diff image goes to: --diff-dir DIR/<stage>-<tree>-<view>[-<settings>].png;
// --diff FILE.png for the first row, FILE-<view>[-<settings>].png for the others.
std::string diffFileOf(const CheckOutputs& out, const CheckCase& c, bool first,
                       const std::string& baseScene) {
    if (stageNeedsMirror(c.request.stage))
        return out.diff;  // its difference picture: --diff as given
    std::string slug = c.view;
    for (const auto& [name, value] : c.request.sets) slug += "-" + name + "=" + value;
    if (c.request.sceneGiven && c.request.scene != baseScene) slug += "-" + c.request.scene;
    for (char& ch : slug)
        if (ch == '/' || ch == ' ' || ch == '+') ch = '_';
    if (!out.diffDir.empty())
        return out.diffDir + "/" + c.request.stage + "-" + treeName(c.request.tree) + "-" + slug +
               ".png";
    if (out.diff.empty() || first) return out.diff;
    std::string stem = out.diff, ext;
    std::size_t dot = stem.rfind('.'), slash = stem.rfind('/');
    if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) {
        ext = stem.substr(dot);
        stem.resize(dot);
    }
    return stem + "-" + slug + ext;
}

void makeDiffDir(const CheckOutputs& out) {
    if (out.diffDir.empty()) return;
    std::error_code ec;
    fs::create_directories(out.diffDir, ec);
    if (ec || !fs::is_directory(out.diffDir))
        throw UsageError("--diff-dir: cannot create the folder '" + printableName(out.diffDir) +
                         "'");
}

}  // namespace

void validateOutputs(const CheckOutputs& out, const std::string& submission) {
    if (out.format != "json" && out.format != "gradescope")
        throw UsageError("--format: '" + out.format + "' is not one of json, gradescope");
    if (out.format != "json" && out.report.empty())
        throw UsageError("--format " + out.format + ": give --report FILE to write it to");
    std::vector<std::pair<std::string, std::string>> outputs;  // option, path
    for (const auto& [option, path] : {std::pair<std::string, std::string>{"--report", out.report},
                                       {"--junit", out.junit},
                                       {"--diff", out.diff},
                                       {"--diff-dir", out.diffDir}})
        if (!path.empty()) outputs.emplace_back(option, path);
    for (std::size_t i = 0; i < outputs.size(); ++i)
        for (std::size_t j = i + 1; j < outputs.size(); ++j)
            if (canonicalOutput(outputs[i].second) == canonicalOutput(outputs[j].second))
                throw UsageError(outputs[i].first + " and " + outputs[j].first + ": both are '" +
                                 printableName(outputs[j].second) + "'; give each its own path");
    if (!submission.empty()) {
        // As written and as resolved: a link the student planted in the folder resolves
        // elsewhere (another student's folder) and is refused for where it is written.
        auto lexical = [](const std::string& p) {
            std::error_code ec;
            return fs::absolute(p, ec).lexically_normal().string();
        };
        auto inside = [](const std::string& p, const std::string& root) {
            std::string r =
                root.size() > 1 && root.back() == '/' ? root.substr(0, root.size() - 1) : root;
            return p == r || p.rfind(r + "/", 0) == 0;
        };
        for (const auto& [option, path] : outputs)
            if (inside(canonicalOutput(path), canonicalOutput(submission)) ||
                inside(lexical(path), lexical(submission)))
                throw UsageError(option + " '" + printableName(path) +
                                 "' lies inside the submission folder '" +
                                 printableName(submission) + "'; write outputs outside it");
    }
    if (!out.report.empty()) requireWritable("--report", out.report);
    if (!out.junit.empty()) requireWritable("--junit", out.junit);
    if (!out.diff.empty()) requireWritable("--diff", out.diff);
}

int gradeOneStudent(const GradingPlan& plan, const StudentWork& work, GradeSettings settings,
                    const CheckOutputs& out, const std::string& tool, const std::string& headline) {
    std::size_t total = 0;
    for (const StagePlan& st : plan.stages) total += st.rows.size();
    makeDiffDir(out);
    std::cout << headline << "\n        " << tableHeader() << std::flush;
    // Mesa's shader cache for this run's workers: private, gone with the run.
    PrivateDir shaderCache("shadowlab-shader-cache");
    useShaderCacheFolder(shaderCache.path());
    Calibration calibration(settings.budget, settings.backend);
    std::size_t done = 0;
    std::set<std::string> saidNotes;
    StudentRecord record;
    auto start = std::chrono::steady_clock::now();
    gradeStudents(
        {plan}, {work}, settings, calibration,
        [&](std::size_t, const StageRecord& st) {
            for (const RowRecord& row : st.rows) {
                char counter[32];
                std::snprintf(counter, sizeof counter, "[%3zu/%zu] ", ++done, total);
                std::cout << counter << printable(tableLine(row)) << std::flush;
                // A note (an unset uniform) holds for every row of the stage: said once.
                const std::string& note = row.result.note;
                if (!note.empty() && saidNotes.insert(note).second)
                    std::cerr << "shadowlab: note: " << printable(note) << "\n";
            }
            if (st.status == Status::Missing)
                std::cerr << "shadowlab: stage " << st.stage << " (" << st.tree
                          << ") MISSING: " << printable(st.message) << "\n";
        },
        [&](std::size_t, StudentRecord r) { record = std::move(r); });
    record.tool = tool;
    if (settings.annotate) settings.annotate(record);
    record.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const RowCounts c = countRows(record);
    std::cout << "checked " << c.total << ": " << c.passed << " passed, " << c.failed << " failed, "
              << c.skipped << " skipped, " << c.errors << " errors, " << c.missing << " missing, "
              << c.notGraded << " not graded in " << std::fixed << std::setprecision(1)
              << record.seconds << std::defaultfloat << " s ("
              << (record.machine.empty() ? "no stage rendered" : record.machine) << ")\n"
              << printable(stageSummary(record));
    if (!out.diff.empty())
        for (const StageRecord& st : record.stages)
            for (const RowRecord& row : st.rows)
                if (!row.result.diffFile.empty())
                    std::cout << "diff image: " << printableName(row.result.diffFile) << "\n";
    if (!out.report.empty()) {
        nlohmann::json written;
        if (out.format == "gradescope") {
            written = gradescopeResults(record);
        } else {
            written = recordJson(record);
            written["expectations"] = expectationsPath();
        }
        writeOutput("--report", out.report,
                    written.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
    }
    if (!out.junit.empty()) writeOutput("--junit", out.junit, junitXml(record));
    return record.exitCode();
}

int runStageCheck(const StageCheckArgs& a) {
    if (!a.out.diff.empty() && !a.out.diffDir.empty())
        throw UsageError(
            "--diff and --diff-dir: give one (--diff FILE.png for one stage, "
            "--diff-dir DIR for --all)");
    if (a.all && !a.out.diff.empty())
        throw UsageError("--diff: with --all use --diff-dir DIR (one image per stage and tree)");
    validateOutputs(a.out, a.base.overlay);
    RenderRequest base = a.base;
    std::vector<std::string> notes;
    std::vector<RenderRequest> requests = checkRequests(a, notes);
    if (!a.all) base.tree = requests.front().tree;      // a legacy-only stage runs its own tree
    for (const auto& r : requests) validateRequest(r);  // every bad value before any GL work
    expectations();                                     // and a broken data file too
    // The submission, resolved and copied before anything is compiled: what is graded is the
    // copy (grade/intake.h).
    std::unique_ptr<PrivateDir> snapshot;
    Submission submission;
    StudentWork work;
    work.name = base.overlay.empty() ? "shipped shaders" : base.overlay;
    if (!base.overlay.empty()) {
        const ShippedTrees& shipped = shippedTrees();
        if (!a.all && expectedFiles(base.stage, shipped.of(base.tree)).empty())
            throw UsageError("--stage " + base.stage +
                             ": this stage has no shaders for --shaders to replace");
        std::vector<std::string> stages;
        for (const auto& r : requests) stages.push_back(r.stage);
        snapshot = std::make_unique<PrivateDir>("shadowlab-submission");
        try {
            submission = takeSubmission(base.overlay, snapshot->path(), shipped.both, stages);
        } catch (const IntakeError& e) {
            throw UsageError(e.what());
        }
        showFolderAs(snapshot->path(), submission.folder);
        for (const auto& n : submission.notes) notes.push_back(n);
        for (RenderRequest& r : requests) r.overlay = snapshot->path();
        work.overlay = snapshot->path();
        work.files = submission.files;
        work.notes = submission.notes;
        work.hash = submission.hash;
    }
    // A student edition has no solution to render drawn rows with: it draws them at a seed of
    // the shipped set, whose figures of ours are data (stages/drawn_figures.h). Say which, so a
    // home check is not mistaken for the grader's own seed.
    if (!base.overlay.empty() && a.settings.seed && !a.narrowed && !a.customView) {
        std::size_t drawn = 0;
        for (const auto& r : requests)
            if (isStudentEdition(r.tree)) drawn += drawnRowsOf(r.stage, treeName(r.tree)).size();
        if (drawn > 0)
            notes.push_back(std::to_string(drawn) + (drawn == 1 ? " row" : " rows") +
                            " whose values the seed draws (the method's parameters) are drawn at "
                            "seed " +
                            std::to_string(shippedDrawnSeed(*a.settings.seed)) + ", one of the " +
                            std::to_string(shippedDrawnSeeds().size()) +
                            " whose solution figures this student edition ships; the grader "
                            "draws them at its own seed");
    }
    for (const auto& n : notes) std::cerr << "shadowlab: note: " << printable(n) << "\n";
    GradeSettings settings = a.settings;
    GradingPlan plan = defaultPlan(a, requests, base.overlay.empty() ? nullptr : &submission);
    for (const StagePlan& st : plan.stages)
        for (const RowPlan& row : st.rows) validateRequest(row.check.request);
    // Every diff image's path, before any GL work.
    makeDiffDir(a.out);
    const CheckCase* first = plan.stages.empty() || plan.stages.front().rows.empty()
                                 ? nullptr
                                 : &plan.stages.front().rows.front().check;
    auto diffOf = [a, first, scene = base.scene](const CheckCase& c) {
        bool isFirst = first && c.view == first->view && c.lesson == first->lesson &&
                       c.request.stage == first->request.stage &&
                       c.request.tree == first->request.tree;
        return diffFileOf(a.out, c, isFirst, scene);
    };
    for (const StagePlan& st : plan.stages)
        for (const RowPlan& row : st.rows) {
            std::string path = diffOf(row.check);
            if (!path.empty() && !stageNeedsMirror(row.check.request.stage))
                requireWritable(a.out.diffDir.empty() ? "--diff" : "--diff-dir", path);
        }
    if (!a.out.diff.empty() || !a.out.diffDir.empty()) {
        settings.imageDir = [](const StudentWork&) { return std::string("."); };
        settings.rowImage = [diffOf](const StudentWork&, const CheckCase& c) { return diffOf(c); };
    }
    const std::uint64_t seed = *settings.seed;
    std::ostringstream headline;
    headline << "check against " << expectationsPath() << ", " << base.width << "x" << base.height
             << (base.overlay.empty() ? "" : ", shaders " + printableName(base.overlay))
             << ", seed " << seed << " (--seed " << seed << " repeats the displaced views)";
    return gradeOneStudent(plan, work, settings, a.out, "shadowlab check", headline.str());
}

}  // namespace sl
