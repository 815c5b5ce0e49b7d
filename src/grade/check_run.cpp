#include "grade/check_run.h"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <random>
#include <sstream>

#include "gl/machine.h"
#include "grade/bounds.h"
#include "grade/case_judge.h"
#include "grade/judge.h"
#include "grade/reports.h"
#include "io/data_paths.h"
#include "io/files.h"
#include "io/json_fields.h"
#include "io/png.h"
#include "io/usage_error.h"
#include "metrics/figures.h"
#include "metrics/mirror_metrics.h"
#include "metrics/shadow_metrics.h"
#include "scene/scene_json.h"
#include "stages/drawn.h"
#include "stages/drawn_figures.h"
#include "stages/registry.h"
#include "stages/stage.h"

namespace sl {

std::string rowSlug(const CheckCase& c) {
    std::string slug =
        c.request.stage + "-" + treeName(c.request.tree) + "-" + c.view + "-" + c.lesson;
    for (char& ch : slug)
        if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '.' && ch != '-') ch = '_';
    return slug;
}

namespace {

nlohmann::json number(double v) {
    return std::isnan(v) ? nlohmann::json() : nlohmann::json(v);
}

// The compiler's own words in one line: the first line naming a line number (file:line:col:
// error ...), else the first line.
std::string errorLine(const std::string& text) {
    std::istringstream in(text);
    std::string first, line;
    std::getline(in, first);
    // A link error's first line names both files ("a.vert + b.frag: program did not link:"),
    // the driver's line does not: keep both.
    std::string prefix = first.find("did not link") != std::string::npos ? first + " " : "";
    while (std::getline(in, line))
        if (line.find("error") != std::string::npos) return prefix + line;
    return first;
}

}  // namespace

std::uint64_t drawSeed() {
    std::random_device device;
    return (std::uint64_t(device()) << 32 | device()) % 1000000000000ull;  // 12 digits to type
}

std::vector<CheckCase> checkCases(const RenderRequest& base, bool narrowed, bool customView,
                                  std::optional<std::uint64_t> seed) {
    std::vector<std::pair<RenderRequest, std::string>> lessons;  // request, lesson label
    if (narrowed) {
        lessons.emplace_back(base, "");
    } else {
        for (const Expectation* e : lessonsOf(expectations(), base.stage, treeName(base.tree))) {
            RenderRequest r = base;
            r.sets = e->set;
            if (!e->scene.empty()) {
                r.scene = e->scene;
                r.sceneGiven = true;
            }
            lessons.emplace_back(r, e->label());
        }
        if (lessons.empty()) lessons.emplace_back(base, "");  // no entry: judged as a SKIP
    }
    std::vector<CheckCase> cases;
    // View by view, so lessons seen from the same camera share a context and a reference.
    std::vector<std::string> scenes;
    for (const auto& [request, label] : lessons) {
        std::string scene = effectiveScene(request);
        if (std::find(scenes.begin(), scenes.end(), scene) == scenes.end()) scenes.push_back(scene);
    }
    for (const std::string& scene : scenes) {
        std::vector<GradingView> views = gradingViews(scene);
        if (customView) views = {{"custom", {}, {}, {}, {}, ""}};
        for (const GradingView& view : views)
            for (const auto& [request, label] : lessons) {
                if (effectiveScene(request) != scene) continue;
                RenderRequest r = request;
                if (!customView) {
                    r.eye = view.eye;
                    r.at = view.at;
                    r.light = view.light;
                    r.fovy = view.fovy;
                }
                cases.push_back({r, view.name, label});
            }
        // Only in the stage's own scene: a lesson scene such as the lab's (its light on the
        // receiver's normal, so it cannot turn) gains little from it and doubles its cost. A
        // scene with a mirror is displaced its own way (camera and mirror: displacedViewOf).
        if (!seed || customView || !findStage(base.stage) || scene != effectiveScene(base))
            continue;
        for (const auto& [request, label] : lessons) {
            if (effectiveScene(request) != scene) continue;
            RenderRequest r = request;
            r.displaceSeed = seed;
            cases.push_back({r, "displaced", label});
        }
    }
    // The rows whose method parameters the seed draws, seen from the displaced view (its truth
    // is traced once for both), each held to our shaders at the same values (judgeDrawn). Only
    // for a submission: our own shaders would be held to themselves. A student edition's shaders
    // are stubs: it draws at a seed of the shipped set (stages/drawn_figures.h), whose figures
    // of ours are data, and judges by the same rule (docs/check.md "Drawn rows").
    if (narrowed || customView || !seed || base.overlay.empty()) return cases;
    const std::uint64_t drawSeed = isStudentEdition(base.tree) ? shippedDrawnSeed(*seed) : *seed;
    for (const DrawnRow* row : drawnRowsOf(base.stage, treeName(base.tree))) {
        RenderRequest r = base;
        r.sets = drawnSettings(*row, drawSeed);
        if (!row->scene.empty()) {
            r.scene = row->scene;
            r.sceneGiven = true;
        }
        r.displaceSeed = drawSeed;
        cases.push_back({r, "drawn",
                         row->label() + " (drawn: " + drawnValuesText(*row, drawSeed) + ")",
                         RowPictures::Difference, row});
    }
    return cases;
}

CaseSeries::CaseSeries(Evaluator& rig, std::vector<CheckCase> cases,
                       std::function<std::string(const CheckCase&)> diffPath)
    : rig_(rig), cases_(std::move(cases)), diffPath_(std::move(diffPath)) {}

bool CaseSeries::done() const {
    return results_.size() == cases_.size() ||
           (!results_.empty() && unjudged(results_.back().status));
}

// Our shaders' figures in the seeded views (displaced and drawn rows, and an instructor's extra
// views of drawn rows), where our shaders are the solution: measured in one go (one context for
// ours, one for theirs: switching per row rebuilt both and traced the reference again each
// time), once the submission's first rows have run (a shader that does not build ends the stage
// before: no render of ours in its worker). A student edition's shaders are stubs: its displaced
// and drawn rows are judged by the data alone (runCheck).
bool CaseSeries::needsOurs(const CheckCase& c) {
    return c.request.displaceSeed && !c.request.overlay.empty() &&
           !isStudentEdition(c.request.tree);
}

void CaseSeries::measureOurs() {
    measured_ = true;
    for (std::size_t k = 0; k < cases_.size(); ++k) {
        if (!needsOurs(cases_[k])) continue;
        RenderRequest shipped = cases_[k].request;
        shipped.overlay.clear();
        rig_.prepare(shipped);
        CheckResult mine;
        mine.figures = rig_.accuracy();
        ours_[k] = mine.figureMap();
    }
}

// The first row of case k's pair, run before it in this series: the same entry and seed, judged.
std::optional<PairedRow> CaseSeries::pairOf(std::size_t k, std::string& note) const {
    const CheckCase& c = cases_.at(k);
    const DrawnRow* first = c.drawn ? pairedRowOf(*c.drawn) : nullptr;
    if (!first) return std::nullopt;
    for (std::size_t j = 0; j < k; ++j) {
        if (cases_[j].drawn != first || cases_[j].request.displaceSeed != c.request.displaceSeed)
            continue;
        const CheckResult& before = results_[j];
        if (before.status != Status::Pass && before.status != Status::Fail) {
            note = "response to " + c.drawn->response->param +
                   " not judged: its first row was not judged";
            return std::nullopt;
        }
        PairedRow p{c.drawn, "", before.parameters, before.figureMap(), {}};
        for (const DrawnParam& d : first->draw)
            if (d.name == c.drawn->response->param)
                p.from = d.name + "=" + before.parameters.text(d.name);
        auto ours = ours_.find(j);
        if (ours != ours_.end()) p.ours = ours->second;
        return p;
    }
    note = "response to " + c.drawn->response->param +
           " not judged: its first row is not in this check";
    return std::nullopt;
}

const CheckResult& CaseSeries::next() {
    const std::size_t k = results_.size();
    const CheckCase& c = cases_.at(k);
    if (!measured_ && needsOurs(c)) measureOurs();
    auto found = ours_.find(k);
    std::string pairNote;
    const std::optional<PairedRow> paired = pairOf(k, pairNote);
    CheckResult r =
        runCheck(rig_, c.request, diffPath_(c), found == ours_.end() ? nullptr : &found->second,
                 c.pictures, paired ? &*paired : nullptr);
    if (!pairNote.empty())
        r.note = capped(r.note + (r.note.empty() ? "" : "; ") + pairNote, kMaxRowMessage);
    r.view = c.view;
    r.lesson = c.lesson.empty() && r.expectation.entry ? r.expectation.entry->label() : c.lesson;
    results_.push_back(std::move(r));
    return results_.back();
}

std::vector<CheckResult> runCheckCases(Evaluator& rig, const std::vector<CheckCase>& cases,
                                       const std::function<std::string(const CheckCase&)>& diffPath,
                                       const std::function<void(const CheckResult&)>& progress) {
    CaseSeries series(rig, cases, diffPath);
    while (!series.done()) progress(series.next());
    return series.results();
}

std::map<std::string, double> CheckResult::figureMap() const {
    std::map<std::string, double> out;
    for (const FigureInfo& f : figureTable()) out[f.name] = figures.*f.field;
    return out;
}

CheckResult checkResultFor(const RenderRequest& request) {
    CheckResult r;
    r.stage = request.stage;
    r.tree = treeName(request.tree);
    r.overlay = request.overlay;
    r.width = request.width;
    r.height = request.height;
    return r;
}

namespace {

// The camera, light and scene a stage would have been rendered with, for a stage whose worker
// returned nothing. The scene is read again only when it is a regular file: a FIFO or a device
// is the scene loader's to refuse, never the parent's to block on.
void describeUnrendered(const RenderRequest& r, CheckResult& out) {
    out.scene = effectiveScene(r);
    std::string path = out.scene;
    if (path.find('/') == std::string::npos && path.find(".json") == std::string::npos)
        path = dataDir() + "/scenes/" + path + ".json";
    struct stat st;
    if (::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode)) {
        try {
            Scene scene = loadScene(out.scene);
            out.scene = scene.name;
            out.camera = scene.camera;
            out.light = scene.light.position;
        } catch (const std::exception&) {  // the worker's error would have said why
        }
    }
    if (r.eye) out.camera.eye = *r.eye;
    if (r.at) out.camera.at = *r.at;
    if (r.fovy) out.camera.fovyDegrees = *r.fovy;
    if (r.light) out.light = *r.light;
}

}  // namespace

CheckResult unrenderedResult(const RenderRequest& r) {
    CheckResult out = checkResultFor(r);
    if (const StageInfo* info = findStage(r.stage)) out.parameters = ParamSet(info->params);
    for (const auto& [name, value] : r.sets) out.parameters.set(name, value);
    describeUnrendered(r, out);
    out.expectation =
        findExpectation(expectations(), out.stage, out.scene, out.tree, out.parameters);
    return out;
}

namespace {

// The truth as a picture: the reference's own shading, blocked where the light is blocked.
Image truthPicture(const ReferenceImage& ref, const ReferenceShades& shades) {
    Image out = shades.reached;
    for (int j = 0; j < out.height; ++j)
        for (int i = 0; i < out.width; ++i)
            if (ref.at(i, j).blocked) std::copy_n(shades.blocked.at(i, j), 4, out.at(i, j));
    return out;
}

std::string besideDiff(const std::string& diffPath, const std::string& kind) {
    std::string stem = diffPath;
    if (stem.size() > 4 && stem.compare(stem.size() - 4, 4, ".png") == 0)
        stem.resize(stem.size() - 4);
    return stem + "." + kind + ".png";
}

// A row's pictures once it is judged (which it writes: RowPictures): the difference at `diffPath`
// and, for a feedback page, the render and the truth beside it (DIFF.render.png, DIFF.truth.png;
// the mirror's truth is our stencil reflection, its difference taken inside the mirror). A full
// disk costs the pictures, not the grade nor the report: a note on the row.
void writePictures(Evaluator& rig, const std::optional<ShadowEvidence>& e,
                   const std::string& diffPath, RowPictures pictures, CheckResult& r) {
    if (diffPath.empty()) return;
    if (pictures == RowPictures::AllUnlessPassing && r.status == Status::Pass) return;
    const bool beside = pictures != RowPictures::Difference;
    std::string err;
    if (!e) {
        const Evaluator::MirrorPictures& p = rig.mirrorPictures();
        err = writePng(diffPath, mirrorDifferencePicture(p.shown, p.exact, p.mask));
        if (err.empty() && beside) err = writePng(besideDiff(diffPath, "render"), p.shown);
        if (err.empty() && beside) err = writePng(besideDiff(diffPath, "truth"), p.exact);
    } else {
        err = writePng(diffPath, diffImage(rig.reference(), e->shadowed, e->withShadows,
                                           e->figures.evaluatedMask, e->figures.band));
        if (err.empty() && beside) err = writePng(besideDiff(diffPath, "render"), e->withShadows);
        if (err.empty() && beside)
            err = writePng(besideDiff(diffPath, "truth"),
                           truthPicture(rig.reference(), rig.shades()));
    }
    if (err.empty())
        r.diffFile = diffPath;
    else
        r.note += (r.note.empty() ? "" : "; ") + ("no diff image: " + err);
}

// The context lost under the row (the browser's WebGL: platform/headless.h lost()): the
// platform's failure (NOT GRADED), whatever the row drew or failed to compile.
void throwIfLost(Evaluator& rig, const std::string& stage) {
    if (rig.contextLost()) throw std::runtime_error(contextLostMessage(stage));
}

}  // namespace

std::string contextLostMessage(const std::string& stage) {
    return "the WebGL context was lost during the check of stage " + stage +
           " (the browser's, not your shaders': reload the page)";
}

CheckResult runCheck(Evaluator& rig, const RenderRequest& request, const std::string& diffPath,
                     const std::map<std::string, double>* shipped, RowPictures pictures,
                     const PairedRow* paired) {
    if (request.view != ViewMode::Final)
        throw UsageError("--view " + std::string(viewName(request.view)) +
                         ": check judges the final picture; use --view final (or leave it out)");
    auto start = std::chrono::steady_clock::now();
    CheckResult r = checkResultFor(request);
    resetGlErrorCount();  // this check's errors only
    Renderer& renderer = rig.prepare(request);
    r.backend = rig.context().backendName();
    r.machine = machineLine();
    r.scene = renderer.scene().name;
    r.parameters = renderer.params();
    r.camera = renderer.camera;
    r.light = renderer.lightPosition;
    r.seed = request.displaceSeed;
    r.expectation = findExpectation(expectations(), r.stage, r.scene, r.tree, r.parameters);
    std::optional<ShadowEvidence> evidence;  // a shadow stage's renders, for its pictures
    try {
        if (stageNeedsMirror(request.stage)) {
            r.figures = rig.accuracy();
        } else {
            evidence = rig.shadowEvidence();
            const ShadowFigures& f = evidence->figures;
            r.figures = shadowAccuracy(f);
            r.evaluated = f.evaluated;
            r.truthLit = f.truthLit;
            r.truthShadow = f.truthShadow;
            const Scene& scene = renderer.scene();
            for (std::size_t i = 0; i < scene.objects.size(); ++i)
                if (std::size_t(objectId(i)) < f.byObject.size())
                    r.objects.push_back({scene.objects[i].name, f.byObject[objectId(i)]});
        }
        throwIfLost(rig, r.stage);
        // A GL error while a student's program drew is theirs (ERROR), else the platform's.
        throwGlFailure(!SL_CHECK_GL(), "the check of stage " + r.stage);
    } catch (const ShaderError& e) {
        throwIfLost(rig, r.stage);  // a lost context fails every compile: not the student's
        std::string text = capped(e.what(), kMaxErrorText);
        std::cerr << "shadowlab: shader error: " << text << (text.back() == '\n' ? "" : "\n");
        r.studentFiles = renderer.shaders().overlayFiles(r.stage);
        rig.reset();
        r.status = Status::Error;
        r.message = capped("shader error: " + errorLine(e.what()), kMaxRowMessage);
        r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return r;
    }
    r.studentFiles = renderer.shaders().overlayFiles(r.stage);
    if (const StageDefinition* info = findStage(r.stage))
        r.sourceNotes = cappedList(renderer.shaders().sourceNotes(r.stage, info->sourceRules));
    for (const std::string& n : renderer.shaders().unsetUniformNotes(r.stage))
        r.note += (r.note.empty() ? "" : "; ") + n;
    r.note = capped(r.note, kMaxRowMessage);
    if (!r.expectation.entry) {  // a stage or tree the data file does not cover: nothing to judge
        r.status = Status::Skip;
        r.message = "no entry in " + expectationsPath() + " for this stage and tree";
        writePictures(rig, evidence, diffPath, pictures, r);
        r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return r;
    }
    const Judgement j = judgeCase(request, r, shipped, paired);
    r.status = j.status;
    r.message = j.message;
    r.reasons = j.reasons;
    writePictures(rig, evidence, diffPath, pictures, r);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

namespace {

nlohmann::json reasonsJson(const std::vector<FigureReason>& reasons) {
    nlohmann::json out = nlohmann::json::array();
    for (const FigureReason& f : reasons) {
        out.push_back({{"figure", f.figure},
                       {"value", number(f.value)},
                       {"side", sideName(f.side)},
                       {"bound", number(f.bound)},
                       {"passed", f.passed}});
        if (!f.changeFrom.empty()) out.back()["change_from"] = f.changeFrom;
    }
    return out;
}

nlohmann::json objectsJson(const std::vector<CheckResult::ObjectPixels>& objects) {
    nlohmann::json out = nlohmann::json::array();
    for (const CheckResult::ObjectPixels& o : objects)
        out.push_back({{"name", o.name},
                       {"lit", o.counts.lit},
                       {"false_shadow", o.counts.falseShadow},
                       {"shadow", o.counts.shadow},
                       {"false_lit", o.counts.falseLit}});
    return out;
}

}  // namespace

nlohmann::json checkJson(const CheckResult& r) {
    nlohmann::json params = nlohmann::json::object();
    for (const ParamSpec& p : r.parameters.specs()) params[p.name] = r.parameters.text(p.name);
    nlohmann::json figures = nlohmann::json::object();
    for (const auto& [name, value] : r.figureMap()) figures[name] = number(value);
    nlohmann::json expectation;
    if (r.expectation.entry) {
        const Expectation& e = *r.expectation.entry;
        nlohmann::json limits = nlohmann::json::object();
        for (const Limit& l : e.limits)
            limits[l.figure] = {{"min", number(l.min)}, {"max", number(l.max)}};
        expectation = {{"id", e.id},
                       {"entry", e.label()},
                       {"matched", r.expectation.exact ? "exact" : "defaults"},
                       {"outcome", e.outcome},
                       {"why", e.why},
                       {"limits", limits}};
    }
    return {
        {"stage", r.stage},
        {"tree", r.tree},
        {"view", r.view},
        {"lesson", r.lesson},
        {"name", checkTestName(r)},
        {"scene", r.scene},
        {"shaders", r.overlay.empty() ? nlohmann::json() : nlohmann::json(r.overlay)},
        {"size", {r.width, r.height}},
        {"parameters", params},
        {"camera",
         {{"eye", vec3Json(r.camera.eye)},
          {"at", vec3Json(r.camera.at)},
          {"fovy", r.camera.fovyDegrees}}},
        {"light", vec3Json(r.light)},
        {"figures", figures},
        {"pixels",
         {{"evaluated", r.evaluated}, {"truth_lit", r.truthLit}, {"truth_shadow", r.truthShadow}}},
        {"objects", objectsJson(r.objects)},
        {"expectation", expectation},
        {"student_files", r.studentFiles},
        {"verdict", r.verdict()},
        {"message", r.message},
        {"reasons", reasonsJson(r.reasons)},
        {"diff", r.diffFile.empty() ? nlohmann::json() : nlohmann::json(r.diffFile)},
        {"note", r.note.empty() ? nlohmann::json() : nlohmann::json(r.note)},
        {"source_notes", r.sourceNotes},
        {"seconds", r.seconds},
        {"seed", r.seed ? nlohmann::json(*r.seed) : nlohmann::json()}};
}

namespace {

double numberFrom(const nlohmann::json& v) {
    return v.is_null() ? NAN : v.get<double>();
}

std::string textOrEmpty(const nlohmann::json& v) {
    return v.is_null() ? std::string() : v.get<std::string>();
}

// The entry a row names: its stable id among the stage's entries that apply to the tree (its
// label is for people: an entry's settings may change, its id does not).
const Expectation* expectationOfRow(const std::vector<Expectation>& book, const std::string& stage,
                                    const std::string& id, const std::string& tree) {
    if (const Expectation* e = expectationById(book, stage, id, tree)) return e;
    throw std::invalid_argument("no entry with the id '" + id + "' of stage " + stage +
                                " for the " + tree + " tree in " + expectationsPath());
}

// A record kept before `reasons` existed has none: read as empty (its page shows the message).
std::vector<FigureReason> reasonsFrom(const nlohmann::json& j) {
    std::vector<FigureReason> out;
    if (!j.contains("reasons")) return out;
    for (const auto& f : j.at("reasons")) {
        const std::string side = f.at("side").get<std::string>();
        std::optional<FigureReason::Side> s = sideFromName(side);
        if (!s) throw std::invalid_argument("a reason's side '" + side + "' is not >= or <=");
        out.push_back({f.at("figure").get<std::string>(), numberFrom(f.at("value")), *s,
                       numberFrom(f.at("bound")), f.at("passed").get<bool>(),
                       textOrEmpty(f.value("change_from", nlohmann::json()))});
    }
    return out;
}

}  // namespace

CheckResult checkResultFromJson(const nlohmann::json& j, const std::vector<Expectation>& book) {
    try {
        CheckResult r;
        r.stage = j.at("stage").get<std::string>();
        r.tree = j.at("tree").get<std::string>();
        r.view = j.value("view", std::string());
        r.lesson = j.value("lesson", std::string());
        r.scene = j.at("scene").get<std::string>();
        r.overlay = textOrEmpty(j.at("shaders"));
        r.width = j.at("size").at(0).get<int>();
        r.height = j.at("size").at(1).get<int>();
        if (const StageInfo* info = findStage(r.stage)) r.parameters = ParamSet(info->params);
        for (const auto& [name, value] : j.at("parameters").items()) {
            std::string err = r.parameters.set(name, value.get<std::string>());
            if (!err.empty()) throw std::invalid_argument("parameter " + name + ": " + err);
        }
        const auto& camera = j.at("camera");
        r.camera.eye = vec3FromJson(camera.at("eye"));
        r.camera.at = vec3FromJson(camera.at("at"));
        r.camera.fovyDegrees = camera.at("fovy").get<float>();
        r.light = vec3FromJson(j.at("light"));
        const auto& f = j.at("figures");
        Accuracy& a = r.figures;
        for (const FigureInfo& fig : figureTable())
            a.*fig.field =
                fig.inEveryRecord || f.contains(fig.name) ? numberFrom(f.at(fig.name)) : NAN;
        if (!std::isnan(a.falseShadowPct)) a.errorPct = 0.5 * (a.falseShadowPct + a.falseLitPct);
        if (!std::isnan(a.mirrorIdPct)) a.errorPct = 100.0 - a.mirrorIdPct;
        const auto& pixels = j.at("pixels");
        r.evaluated = pixels.at("evaluated").get<long>();
        r.truthLit = pixels.at("truth_lit").get<long>();
        r.truthShadow = pixels.at("truth_shadow").get<long>();
        for (const auto& o : j.value("objects", nlohmann::json::array()))
            r.objects.push_back({o.at("name").get<std::string>(),
                                 {o.at("lit").get<long>(), o.at("false_shadow").get<long>(),
                                  o.at("shadow").get<long>(), o.at("false_lit").get<long>()}});
        const auto& e = j.at("expectation");
        if (!e.is_null()) {
            r.expectation.entry =
                expectationOfRow(book, r.stage, e.at("id").get<std::string>(), r.tree);
            r.expectation.exact = e.at("matched").get<std::string>() == "exact";
        }
        const std::string verdict = j.at("verdict").get<std::string>();
        std::optional<Status> status = statusFromName(verdict);
        if (!status) throw std::invalid_argument("unknown verdict '" + verdict + "'");
        r.status = *status;
        r.message = j.at("message").get<std::string>();
        r.reasons = reasonsFrom(j);
        if (j.contains("student_files"))
            r.studentFiles = j["student_files"].get<std::vector<std::string>>();
        r.diffFile = textOrEmpty(j.at("diff"));
        if (j.contains("note")) r.note = textOrEmpty(j["note"]);
        if (j.contains("source_notes"))
            r.sourceNotes = j["source_notes"].get<std::vector<std::string>>();
        r.seconds = j.at("seconds").get<double>();
        if (j.contains("seed") && !j["seed"].is_null()) r.seed = j["seed"].get<std::uint64_t>();
        return r;
    } catch (const nlohmann::json::exception& e) {
        throw std::invalid_argument(std::string("a check result: ") + e.what());
    }
}

void boundResult(CheckResult& r) {
    r.message = capped(r.message, kMaxRowMessage);
    r.note = capped(r.note, kMaxRowMessage);
    r.studentFiles = cappedList(r.studentFiles);
    r.sourceNotes = cappedList(r.sourceNotes);
    if (r.reasons.size() > kMaxReasons) r.reasons.resize(kMaxReasons);
    for (FigureReason& f : r.reasons) f.figure = capped(f.figure, kMaxReasonFigure);
}

}  // namespace sl
