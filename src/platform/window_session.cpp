#include "platform/window_session.h"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "math/orbit.h"
#include "metrics/image.h"
#include "platform/window_text.h"
#include "scene/scene_json.h"

namespace sl {

namespace {

constexpr float kLightRadiansPerSecond = 0.6f;
constexpr auto kFlashTime = std::chrono::seconds(4);
constexpr const char* kTryingLine =
    "trying your shaders in a bounded worker first: a loop or a crash cannot freeze this window";
constexpr const char* kTryingValuesLine =
    "trying these values with your shaders in the worker first: the last ones that drew show";

// One complete line per event on the terminal, there at once (stdout is a pipe in tests).
void say(std::ostream& out, const std::string& line) {
    out << line << '\n';
    out.flush();
}

bool offers(const StageInfo& s, ViewMode v) {
    for (ViewMode w : s.views)
        if (w == v) return true;
    return false;
}

}  // namespace

WindowSession::WindowSession(const WindowArgs& args)
    : args_(args),
      request_(args.request),
      tree_(request_.tree),
      watch_({shaderTreeRoot(GlslTree::Core), shaderTreeRoot(GlslTree::Legacy), request_.overlay}) {
    const StageInfo* info = findStage(request_.stage);
    if (info && info->legacyOnly)
        request_.tree = GlslTree::Legacy;  // `--stage fixed` alone is fine here
    validateRequest(request_);
    request_.tree = tree_;
    startScene_ = effectiveScene(request_);
    trial_ = args.trial;
    // The trees as they are at the start are trusted (ours, or tried below): only files changed
    // during the session are tried before a tree draws with them.
    triedFingerprint_[GlslTree::Core] = triedFingerprint_[GlslTree::Legacy] = watch_.current();
    // A student's folder is tried before anything of it is compiled here. Live, the window
    // answers keys meanwhile and shows that it is trying (a looping stage takes the whole time
    // limit, and every stage may loop); a scripted run (--frames) waits for the verdict first.
    if (trial_ && !request_.overlay.empty()) {
        startTrial(false);
        firstTrial_ = true;
        while (args_.frames > 0 && trial_->running()) {
            finishTrial();
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
    }
    // The first renderer is the request's own (its --set, --eye, --light, --view apply).
    RenderRequest first = request_;
    if (info->legacyOnly) first.tree = GlslTree::Legacy;
    first.scene = sceneFor(*info);
    first.sceneGiven = true;
    Slot slot;
    slot.renderer = makeRenderer(first);
    slot.homeCamera = slot.renderer->camera;
    slot.homeLight = slot.renderer->lightPosition;
    std::string key = std::string(treeName(first.tree)) + "/" + first.scene;
    slot_ = &(slots_[key] = std::move(slot));
    scene_ = first.scene;
}

std::string WindowSession::sceneFor(const StageInfo& s) {
    if (lessonScene_.first == s.id && !lessonScene_.second.empty()) return lessonScene_.second;
    RenderRequest r = request_;
    r.stage = s.id;
    std::string name = effectiveScene(r);
    if (!s.needsMirror) return name;
    auto it = sceneHasMirror_.find(name);
    if (it == sceneHasMirror_.end())
        it = sceneHasMirror_.emplace(name, bool(loadScene(name).mirror)).first;
    // A scene without a mirror: the mirror stage brings its own scene (the HUD says so).
    return it->second ? name : (s.defaultScene.empty() ? "mirror" : s.defaultScene);
}

WindowSession::Slot& WindowSession::slotFor(GlslTree tree, const std::string& scene,
                                            const std::string& stage) {
    std::string key = std::string(treeName(tree)) + "/" + scene;
    auto it = slots_.find(key);
    if (it != slots_.end()) return it->second;
    RenderRequest r = request_;
    r.stage = stage;
    r.tree = tree;
    r.scene = scene;
    r.sceneGiven = true;
    r.sets.clear();
    r.view = ViewMode::Final;
    if (tree != request_.tree) r.overlay.clear();  // a student's folder is written for one tree
    if (scene != startScene_) r.eye = r.at = r.light = std::nullopt, r.fovy = std::nullopt;
    Slot slot;
    slot.renderer = makeRenderer(r);
    slot.homeCamera = slot.renderer->camera;
    slot.homeLight = slot.renderer->lightPosition;
    return slots_[key] = std::move(slot);
}

bool WindowSession::selectStage(std::size_t index, GlslTree sessionTree) {
    if (index >= stageRegistry().size()) return false;
    const StageInfo& s = stageRegistry()[index];
    GlslTree tree = s.legacyOnly ? GlslTree::Legacy : sessionTree;
    Renderer& prev = *slot_->renderer;
    Slot* next = nullptr;
    std::string scene;
    try {
        scene = sceneFor(s);
        next = &slotFor(tree, scene, s.id);
    } catch (const std::exception& e) {
        flash(std::string("cannot show stage '") + s.id + "': " + e.what(), true);
        return true;
    }
    Renderer& r = *next->renderer;
    const std::string prevStage = prev.stage().id;
    const ViewMode prevView = prev.view;
    if (&r != &prev && scene == scene_) {  // same scene, other tree: keep where we look from
        r.camera = prev.camera;
        r.lightPosition = prev.lightPosition;
    }
    r.selectStage(s.id);
    if (&r != &prev && prevStage == s.id) r.params() = prev.params();  // the same stage, other tree
    r.view = offers(s, prevView) ? prevView : ViewMode::Final;
    if (prevStage != s.id) {
        selectedParam_ = 0;
        lesson_ = 0;
        lessonScene_ = {};
    }
    slot_ = next;
    scene_ = scene;
    const bool otherTree = sessionTree != tree_;
    if (otherTree) reloadErrors_.clear();  // the other tree's: not about this picture
    tree_ = sessionTree;
    renderError_.clear();
    // Its files changed since it last drew: tried first (its stages not drawn yet wait).
    if (otherTree && trial_ && !firstTrial_ && triedFingerprint_[tree_] != watch_.current()) {
        startTrial(false);
        treeTrial_ = true;
    }
    return true;
}

bool WindowSession::key(unsigned char key, bool shift) {
    // Caps Lock or Shift on a letter is the same command (Shift only counts with + and -).
    if (key >= 'A' && key <= 'Z') key = static_cast<unsigned char>(key - 'A' + 'a');
    Renderer& r = *slot_->renderer;
    const auto& specs = r.params().specs();
    const std::size_t stages = stageRegistry().size();
    switch (key) {
        case '[':
            return selectStage((r.stageIndex() + stages - 1) % stages, tree_);
        case ']':
            return selectStage((r.stageIndex() + 1) % stages, tree_);
        case 'g':
            return selectStage(r.stageIndex(),
                               tree_ == GlslTree::Core ? GlslTree::Legacy : GlslTree::Core);
        case '\t':
            if (!specs.empty())
                selectedParam_ = (selectedParam_ + (shift ? specs.size() - 1 : 1)) % specs.size();
            return true;
        case '+':
        case '=':
        case '-':
        case '_': {
            if (specs.empty()) return false;
            const ParamSpec& p = specs[selectedParam_ % specs.size()];
            int direction = (key == '+' || key == '=') ? 1 : -1;
            int steps = shift && p.kind != ParamKind::Choice ? 10 : 1;  // Shift: tenfold
            for (int k = 0; k < steps; ++k) r.params().step(p.name, direction);
            return true;
        }
        case 's':  // the split view: the lesson's failure beside its fix
            split_ = !split_;
            if (split_ && splitHalves().empty()) {
                split_ = false;
                flash("s: this stage has no second lesson in this scene to show beside it", false);
            }
            return true;
        case 'n':  // the stage's next lesson, its settings applied
            nextLesson();
            return true;
        case 'x':  // the stage's parameters back to their defaults
            for (const ParamSpec& p : specs) r.params().set(p.name, p.defaultText());
            flash("parameters of '" + r.stage().id + "' reset", false);
            return true;
        case 'c':
            r.camera = slot_->homeCamera;
            r.lightPosition = slot_->homeLight;
            animateLight_ = false;
            flash("camera and light reset", false);
            return true;
        case 'r':
            flash(trial_ ? "r: drawing every stage with the shaders on disk in the trial worker..."
                         : "r: shaders reloaded",
                  false);
            startTrial(true);
            return true;
        case 'p':
            saveShot();
            return true;
        case 'h':
            showHelp_ = !showHelp_;
            return true;
        case 'i':
            hudMode_ = hudMode_ == HudMode::Compact ? HudMode::Full
                       : hudMode_ == HudMode::Full  ? HudMode::Hidden
                                                    : HudMode::Compact;
            return true;
        case 'l':
            animateLight_ = !animateLight_;
            lastAnimation_ = Clock::now();
            return true;
        case 'v': {
            const auto& views = r.stage().views;
            if (views.size() < 2) {
                flash("v: '" + r.stage().id + "' has one view, the final picture", false);
                return true;
            }
            std::size_t i = 0;
            while (i < views.size() && views[i] != r.view) ++i;
            r.view = views[(i + 1) % views.size()];
            return true;
        }
        default:
            if (key >= '0' && key <= '9')
                return selectStage(static_cast<std::size_t>(key - '0'), tree_);
            return false;
    }
}

bool WindowSession::drag(int dx, int dy) {
    Renderer& r = *slot_->renderer;
    r.camera = orbitCamera(r.camera, -dx * 0.01f, dy * 0.01f, sceneFloorHeight(r.scene()));
    return true;
}

bool WindowSession::zoom(int steps) {
    Renderer& r = *slot_->renderer;
    r.camera = zoomCamera(r.camera, std::pow(0.9f, float(steps)));
    return true;
}

bool WindowSession::tick(Clock::time_point now) {
    bool redraw = false;
    if (watch_.poll(now)) {
        startTrial(false);
        redraw = true;
    }
    if (trial_ && trial_->running() && finishTrial()) redraw = true;
    if (trial_ && !trial_->running() && startParamTrialIfNeeded()) redraw = true;  // says so
    if (!flash_.empty() && now >= flashUntil_) {
        flash_.clear();
        redraw = true;
    }
    return redraw;
}

void WindowSession::reload(bool force) {
    // While something is broken, rebuild everything: then "no errors" means every program builds.
    bool hadErrors = !reloadErrors_.empty() || !renderError_.empty();
    std::vector<std::string> errors;
    for (auto& [key, slot] : slots_) {
        auto e = slot.renderer->reloadShaders(force || hadErrors);
        errors.insert(errors.end(), e.begin(), e.end());
    }
    reloadErrors_ = errors;
    renderError_.clear();  // the next draw says again if the stage still has no good program
    printedRenderError_.clear();
    for (const auto& e : errors)
        say(std::cerr, "shadowlab: shader error (keeping the last good program): " + oneLine(e));
    if (errors.empty())
        say(std::cout, hadErrors ? "shadowlab: shaders reloaded; every program builds again"
                                 : "shadowlab: shaders reloaded");
}

std::vector<const WindowLesson*> WindowSession::lessons() const {
    std::vector<const WindowLesson*> list;
    Renderer& r = *slot_->renderer;
    const std::string tree = treeName(r.shaders().tree());
    for (const WindowLesson& l : args_.lessons) {
        bool inTree = l.trees.empty();
        for (const auto& t : l.trees) inTree = inTree || t == tree;
        if (l.stage == r.stage().id && inTree) list.push_back(&l);
    }
    return list;
}

void WindowSession::nextLesson() {
    auto list = lessons();
    if (list.empty()) {
        flash("n: this stage has no lessons", false);
        return;
    }
    lesson_ = (lesson_ + 1) % list.size();
    const WindowLesson& l = *list[lesson_];
    const StageInfo& s = slot_->renderer->stage();
    lessonScene_ = {s.id, l.scene};
    if (sceneFor(s) != scene_) selectStage(slot_->renderer->stageIndex(), tree_);  // its scene
    Renderer& r = *slot_->renderer;
    for (const ParamSpec& p : r.params().specs()) r.params().set(p.name, p.defaultText());
    std::string refused;
    for (const auto& [name, value] : l.sets) {
        std::string e = r.params().set(name, value);
        if (!e.empty()) refused = e;
    }
    if (offers(r.stage(), l.view)) r.view = l.view;
    if (!refused.empty()) flash("n: " + refused, true);  // else the HUD names the lesson
}

std::vector<WindowSession::Half> WindowSession::splitHalves() const {
    Renderer& r = *slot_->renderer;
    if (const ParamSpec* method = r.params().find("mirror-method")) {
        std::vector<Half> halves;
        for (const auto& choice : method->choices)
            halves.push_back({"mirror-method=" + choice, {{"mirror-method", choice}}});
        if (halves.size() >= 2) halves.resize(2);
        return halves;
    }
    auto list = lessons();
    if (list.size() < 2) return {};
    const std::size_t k = lesson_ % list.size();
    for (std::size_t step = 1; step < list.size(); ++step) {
        const WindowLesson& next = *list[(k + step) % list.size()];
        if (next.scene == list[k]->scene && next.view == list[k]->view)
            return {{list[k]->name, list[k]->sets}, {next.name, next.sets}};
    }
    return {};
}

// Both halves with the renderer's own camera and light, each with its settings (the stage's
// defaults and the lesson's); the settings on screen come back afterwards.
void WindowSession::drawSplit(int width, int height) {
    Renderer& r = *slot_->renderer;
    const auto halves = splitHalves();
    const ParamSet kept = r.params();
    const int half = width / 2;
    for (std::size_t k = 0; k < halves.size() && k < 2; ++k) {
        for (const ParamSpec& p : r.params().specs()) r.params().set(p.name, p.defaultText());
        for (const auto& [name, value] : halves[k].sets) r.params().set(name, value);
        r.sceneChanged();  // the two halves' shadow maps differ: no cached map carries over
        picture_.resize(half, height);
        drawStage(picture_.framebuffer(), half, height);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, picture_.framebuffer());
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        glBlitFramebuffer(0, 0, half, height, int(k) * half, pictureBottom_, int(k) * half + half,
                          pictureBottom_ + height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    r.params() = kept;
    r.sceneChanged();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

std::string WindowSession::lessonLine() const {
    auto list = lessons();
    if (list.empty()) return "";
    const std::size_t k = lesson_ % list.size();
    std::string line = "lesson " + std::to_string(k + 1) + "/" + std::to_string(list.size()) +
                       " (n): " + list[k]->name;
    if (!list[k]->look.empty()) line += ". Look for: " + list[k]->look;
    return line;
}

std::string WindowSession::refusedKey(const std::string& stage) const {
    return std::string(treeName(slot_ ? slot_->renderer->shaders().tree() : tree_)) + "/" + stage;
}

std::vector<TrialStage> WindowSession::trialStages() {
    std::vector<TrialStage> stages;
    for (const StageInfo& s : stageRegistry()) {
        if (s.legacyOnly && tree_ == GlslTree::Core) continue;  // runs legacy, without the folder
        TrialStage t;
        t.stage = s.id;
        try {
            t.scene = sceneFor(s);
        } catch (const std::exception&) {
            continue;  // a scene that cannot load: the stage cannot be shown either
        }
        if (slot_ && slot_->renderer->stage().id == s.id) {  // as it is on screen
            for (const ParamSpec& p : slot_->renderer->params().specs())
                t.sets.emplace_back(p.name, slot_->renderer->params().text(p.name));
        } else if (!slot_ && s.id == request_.stage) {
            t.sets = request_.sets;
        }
        if (slot_) {  // normalised as the window compares them: the values off their defaults
            ParamSet tried(s.params);
            for (const auto& [name, value] : t.sets) tried.set(name, value);
            fileTrialSets_[s.id] = nonDefault(tried);
        } else {
            fileTrialSets_[s.id] = {};
        }
        stages.push_back(std::move(t));
    }
    return stages;
}

void WindowSession::startTrial(bool force) {
    if (!trial_) {  // no watchdog: adopted at once
        reload(force);
        return;
    }
    paramTrial_ = false;  // a value trial still running is abandoned: files come first
    trialForce_ = force || !refused_.empty() || !reloadErrors_.empty() || !renderError_.empty();
    trialFingerprint_ = watch_.current();
    trialFile_ = watch_.newestFile();
    // At the window's size (its size on the command line before the first frame).
    trial_->start(tree_, tree_ == request_.tree ? request_.overlay : "", trialStages(),
                  width_ > 0 ? width_ : request_.width, height_ > 0 ? height_ : request_.height);
}

WindowSession::Sets WindowSession::nonDefault(const ParamSet& params) {
    Sets sets;
    for (const ParamSpec& p : params.specs())
        if (params.text(p.name) != p.defaultText()) sets.emplace_back(p.name, params.text(p.name));
    return sets;
}

bool WindowSession::waitingForTrial() const {
    if (!slot_ || !trial_) return false;
    Renderer& r = *slot_->renderer;
    if (firstTrial_) return !r.shaders().overlay().empty();
    return treeTrial_ && trial_->running() && r.shaders().tree() == tree_ &&
           !drewOnce_.count(refusedKey(r.stage().id));
}

bool WindowSession::drawsStudentPrograms() const {
    return trial_ && slot_ && !slot_->renderer->shaders().overlay().empty();
}

bool WindowSession::pending(const Sets& sets) const {
    if (!drawsStudentPrograms()) return false;
    auto good = goodSets_.find(refusedKey(slot_->renderer->stage().id));
    return good != goodSets_.end() && !good->second.count(sets);
}

bool WindowSession::paramsPending() const {
    return drawsStudentPrograms() && pending(nonDefault(slot_->renderer->params()));
}

std::vector<WindowSession::Sets> WindowSession::setsInUse() const {
    Renderer& r = *slot_->renderer;
    std::vector<Sets> sets{nonDefault(r.params())};
    if (split_)
        for (const Half& h : splitHalves()) {
            ParamSet half = r.params();
            for (const ParamSpec& p : half.specs()) half.set(p.name, p.defaultText());
            for (const auto& [name, value] : h.sets) half.set(name, value);
            sets.push_back(nonDefault(half));
        }
    return sets;
}

bool WindowSession::valuesPending() const {
    if (!drawsStudentPrograms()) return false;
    for (const Sets& sets : setsInUse())
        if (pending(sets)) return true;
    return false;
}

// The values on screen (and the split halves'), when the student's programs have not drawn
// with them in the worker, are tried there first; until then the last good ones draw.
bool WindowSession::startParamTrialIfNeeded() {
    if (firstTrial_ || !valuesPending()) return false;
    Renderer& r = *slot_->renderer;
    const std::string key = refusedKey(r.stage().id);
    std::vector<TrialStage> stages;
    paramTrialTried_.clear();
    for (const Sets& sets : setsInUse()) {
        if (!pending(sets) || badSets_[key].count(sets) ||
            std::find(paramTrialTried_.begin(), paramTrialTried_.end(), sets) !=
                paramTrialTried_.end())
            continue;  // good, refused before (its values were put back), or already listed
        TrialStage t;
        t.stage = r.stage().id;
        t.scene = scene_;
        t.sets = sets;
        stages.push_back(t);
        paramTrialTried_.push_back(sets);
    }
    if (stages.empty()) return false;
    paramTrial_ = true;
    paramTrialKey_ = key;
    trialFingerprint_ = watch_.current();
    trial_->start(tree_, tree_ == request_.tree ? request_.overlay : "", stages,
                  width_ > 0 ? width_ : request_.width, height_ > 0 ? height_ : request_.height);
    return true;
}

void WindowSession::adoptParams(const std::vector<TrialVerdict>& verdicts) {
    for (std::size_t k = 0; k < paramTrialTried_.size(); ++k) {
        const Sets& tried = paramTrialTried_[k];
        if (k < verdicts.size() && verdicts[k].ok) {
            goodSets_[paramTrialKey_].insert(tried);
            continue;
        }
        const std::string why = k < verdicts.size() ? verdicts[k].what : "no verdict";
        badSets_[paramTrialKey_][tried] = why;
        std::string values;
        for (const auto& [name, value] : tried)
            values += (values.empty() ? "" : ", ") + name + " = " + value;
        const std::string line = "these values did not draw in the trial worker (" +
                                 (values.empty() ? std::string("the defaults") : values) +
                                 "): " + oneLine(why) + "; the last values that drew show";
        say(std::cerr, "shadowlab: " + line);
        flash(line, true);
        // On screen, back to what drew (if the stage is still the one tried and shows these).
        Renderer& r = *slot_->renderer;
        if (refusedKey(r.stage().id) != paramTrialKey_ || nonDefault(r.params()) != tried) continue;
        for (const ParamSpec& p : r.params().specs()) r.params().set(p.name, p.defaultText());
        for (const auto& [name, value] : lastGoodSets_[paramTrialKey_]) r.params().set(name, value);
    }
}

bool WindowSession::finishTrial() {
    std::vector<TrialVerdict> verdicts;
    if (!trial_->poll(verdicts)) return false;
    const bool values = paramTrial_;
    paramTrial_ = false;
    // Saved again meanwhile: these files were not the ones tried; the next trial decides.
    if (watch_.pending() || watch_.current() != trialFingerprint_) return false;
    if (values)
        adoptParams(verdicts);
    else
        adopt(verdicts);
    return true;
}

void WindowSession::adopt(const std::vector<TrialVerdict>& verdicts) {
    const bool first = firstTrial_;
    firstTrial_ = treeTrial_ = false;
    triedFingerprint_[tree_] = trialFingerprint_;
    const bool hadErrors = !shownErrors().empty() || !renderError_.empty();
    const std::string tree = treeName(tree_);
    std::set<std::string> passed, said;
    bool all = true;
    for (const TrialVerdict& v : verdicts) {
        const std::string key = tree + "/" + v.stage;
        if (v.ok) {
            passed.insert(v.stage);
            refused_.erase(key);
            const Sets& tried = fileTrialSets_[v.stage];  // new programs: what drew is all we know
            goodSets_[key] = {tried};
            badSets_[key].clear();
            lastGoodSets_[key] = tried;
            continue;
        }
        all = false;
        std::string why = v.what;
        // A loop or a crash has no file in its message: name the one saved last.
        if (!trialFile_.empty() && why.find(trialFile_) == std::string::npos)
            why = trialFile_ + " (saved last): " + why;
        // One line per new message: a broken shared file fails every stage with the same one.
        if (refused_[key] != why && said.insert(why).second)
            say(std::cerr,
                "shadowlab: shader error (keeping the last good program): " + oneLine(why));
        refused_[key] = why;
    }
    // The stages that drew in the worker take their new programs; the shared folders (common,
    // phong, hud) only when every stage drew.
    std::vector<std::string> errors;
    for (auto& [key, slot] : slots_) {
        if (slot.renderer->shaders().tree() != tree_) continue;
        auto e = slot.renderer->reloadShaders(trialForce_, all ? nullptr : &passed);
        errors.insert(errors.end(), e.begin(), e.end());
    }
    reloadErrors_ = errors;
    renderError_.clear();
    printedRenderError_.clear();
    for (const auto& e : errors)
        say(std::cerr, "shadowlab: shader error (keeping the last good program): " + oneLine(e));
    if (shownErrors().empty() && slot_ && !first) {  // (at the start: nothing to say)
        say(std::cout, hadErrors ? "shadowlab: shaders reloaded; every program builds again"
                                 : "shadowlab: shaders reloaded");
        flash("shaders reloaded: every stage drew in the trial worker", false);
    }
}

std::vector<std::string> WindowSession::shownErrors() const {
    std::vector<std::string> errors;
    for (const StageInfo& s : stageRegistry()) {
        auto it = refused_.find(refusedKey(s.id));
        if (it != refused_.end() &&
            std::find(errors.begin(), errors.end(), it->second) == errors.end())
            errors.push_back(it->second);
    }
    errors.insert(errors.end(), reloadErrors_.begin(), reloadErrors_.end());
    return errors;
}

void WindowSession::flash(const std::string& text, bool error) {
    flash_ = text;
    flashIsError_ = error;
    flashUntil_ = Clock::now() + kFlashTime;
}

std::string WindowSession::readPixelsToPng(const std::string& path) const {
    Image img(width_, height_);
    std::vector<std::uint8_t> bottomUp(img.rgba.size());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
    std::size_t row = std::size_t(width_) * 4;
    for (int j = 0; j < height_; ++j)
        std::copy_n(&bottomUp[std::size_t(height_ - 1 - j) * row], row,
                    &img.rgba[std::size_t(j) * row]);
    return writePng(path, img);
}

void WindowSession::saveShot() {
    Renderer& r = *slot_->renderer;
    if (width_ <= 0 || height_ <= 0) {
        flash("p: the window has no pixels to save (minimised?)", true);
        return;
    }
    namespace fs = std::filesystem;
    std::string error;
    std::string path;
    try {
        fs::create_directories(args_.shots);
        auto now = std::chrono::system_clock::now();
        auto ms =
            std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count();
        std::string name =
            shotFileName(r.stage().id, treeName(r.shaders().tree()), viewLabel(r.stage(), r.view),
                         std::chrono::system_clock::to_time_t(now), static_cast<int>(ms % 1000));
        path = (fs::absolute(args_.shots) / name).lexically_normal().string();
        error = draw(width_, height_, path, false);
    } catch (const std::exception& e) {
        error = e.what();
    }
    if (!error.empty()) {  // shown and reported; the session goes on and its exit code stays
        std::string line = "p: could not save into '" + args_.shots + "': " + error;
        say(std::cerr, "shadowlab: " + line);
        flash(line, true);
        return;
    }
    say(std::cout, "saved " + path);
    flash("saved " + path, false);
}

std::string WindowSession::treeText() const {
    Renderer& r = *slot_->renderer;
    std::string t = std::string("tree ") + treeName(r.shaders().tree());
    if (r.stage().legacyOnly && tree_ == GlslTree::Core) t += " (fixed-function needs it)";
    return t;
}

std::string WindowSession::title() const {
    Renderer& r = *slot_->renderer;
    return std::to_string(r.stageIndex()) + " " + r.stage().id;
}

// A parameter's uniform is its name in camelCase (margin-kind: marginKind); a student's program
// that does not read it gets the parameter marked, so a change that does nothing says why.
std::string WindowSession::ignoredMark(const std::string& param) const {
    std::string uniform;
    for (std::size_t i = 0; i < param.size(); ++i)
        if (param[i] == '-' && i + 1 < param.size())
            uniform += char(std::toupper(static_cast<unsigned char>(param[++i])));
        else
            uniform += param[i];
    Renderer& r = *slot_->renderer;
    return r.shaders().ignoredUniforms(r.stage().id).count(uniform)
               ? " (your shader does not read it)"
               : "";
}

HudBlock WindowSession::flashBlock() const {
    HudBlock b;
    b.bottom = true;
    b.lines = {
        {flash_, flashIsError_ ? glm::vec4(1, 0.85f, 0.8f, 1) : glm::vec4(0.6f, 1, 0.6f, 1)}};
    b.maxLines = 3;
    b.panel = flashIsError_ ? glm::vec4(0.25f, 0.02f, 0.02f, 0.9f) : glm::vec4(0, 0, 0, 0.75f);
    return b;
}

std::vector<HudBlock> WindowSession::hudBlocks() const {
    Renderer& r = *slot_->renderer;
    const StageInfo& s = r.stage();
    const float scale = textScale(width_, height_);
    const int rows = std::max(3, static_cast<int>((height_ / scale - 6) / Hud::kLineHeight));
    const glm::vec4 white(1), grey(0.85f, 0.85f, 0.85f, 1), yellow(1, 1, 0.6f, 1),
        green(0.6f, 1, 0.6f, 1), blue(0.75f, 0.85f, 1, 1), errorText(1, 0.85f, 0.8f, 1);
    std::vector<HudBlock> blocks;
    std::vector<std::string> errors = shownErrors();
    if (!renderError_.empty() &&
        std::find(errors.begin(), errors.end(), renderError_) == errors.end())
        errors.insert(errors.begin(), renderError_);
    const std::string view = viewLabel(s, r.view);
    const std::string legend = viewLegend(s, r.view);
    auto addLegendAndFlash = [&] {  // at the bottom, in both modes
        if (!legend.empty()) {
            HudBlock b;
            b.bottom = true;
            b.lines = {{legend, white}};
            b.maxLines = 2;
            blocks.push_back(b);
        }
        if (!flash_.empty()) blocks.push_back(flashBlock());
    };

    if (split_) {
        const auto halves = splitHalves();
        for (std::size_t k = 0; k < halves.size() && k < 2; ++k) {
            HudBlock b;
            b.bottom = true;
            b.column = int(k);
            b.half = true;
            b.lines = {{(k == 0 ? "left: " : "right: ") + halves[k].name, white}};
            b.maxLines = 3;
            blocks.push_back(b);
        }
    }
    if (hudMode_ == HudMode::Compact) {  // for a projector: what the picture is, and how to read it
        HudBlock top;
        std::string line = title() + " | " + treeName(r.shaders().tree());
        const auto& specs = r.params().specs();
        if (!specs.empty()) {
            const std::string& name = specs[selectedParam_ % specs.size()].name;
            line += " | " + name + " = " + r.params().text(name) + ignoredMark(name);
        }
        top.lines.push_back({line, yellow});
        if (waitingForTrial()) top.lines.push_back({kTryingLine, green});
        if (valuesPending()) top.lines.push_back({kTryingValuesLine, green});
        const std::string lesson = lessonLine();
        if (!lesson.empty()) top.lines.push_back({lesson, white});
        if (!errors.empty())
            top.lines.push_back({"shader error (i: all of it): " + oneLine(errors[0]), errorText});
        top.maxLines = 5;
        blocks.push_back(top);
        addLegendAndFlash();
        return blocks;
    }

    HudBlock top;
    top.lines.push_back({title() + ": " + s.title, yellow});
    std::ostringstream status;
    status << treeText() << " | scene " << scene_ << " | view " << view << " | ";
    if (drawnFrames_ == 0)  // the time is known once the frame is done: the first one has none
        status << "first frame";
    else
        status << static_cast<int>(drawMs_ * 10) / 10.0 << " ms to draw";
    top.lines.push_back({status.str(), white});
    if (waitingForTrial()) top.lines.push_back({kTryingLine, green});
    if (valuesPending()) top.lines.push_back({kTryingValuesLine, green});
    if (scene_ != startScene_)
        top.lines.push_back({"scene " + scene_ + ": the " + s.id +
                                 " stage brings its own (back to " + startScene_ +
                                 " when you leave it)",
                             blue});
    if (!request_.overlay.empty()) {
        if (!r.shaders().overlay().empty())
            top.lines.push_back({"your shaders: " + r.shaders().overlay() + " (over ours)", green});
        else
            top.lines.push_back({"your shaders (" + request_.overlay + ") are for the " +
                                     treeName(request_.tree) + " tree: ours here",
                                 grey});
    }
    const auto& specs = r.params().specs();
    for (std::size_t i = 0; i < specs.size(); ++i) {
        bool selected = i == selectedParam_ % specs.size();
        top.lines.push_back({std::string(selected ? "> " : "  ") + specs[i].name + " = " +
                                 r.params().text(specs[i].name) + ignoredMark(specs[i].name),
                             selected ? green : grey});
    }
    const std::string lesson = lessonLine();
    if (!lesson.empty()) top.lines.push_back({lesson, white});
    for (const auto& n : r.stats.notes) top.lines.push_back({n, blue});
    if (showHelp_)
        for (const auto& h : windowHelp()) top.lines.push_back({h, white});
    else
        top.lines.push_back({"h: every key", grey});
    top.maxLines =
        std::max(3, showHelp_ ? rows - 3 : rows * 11 / 20);  // help asked for: room for it
    blocks.push_back(top);

    addLegendAndFlash();
    if (!errors.empty()) {
        HudBlock b;
        b.bottom = true;
        b.lines.push_back({renderError_.empty()
                               ? "shader error (the last good program keeps drawing):"
                               : "shader error (no good program for this stage yet):",
                           {1, 0.7f, 0.6f, 1}});
        for (const auto& e : errors) {
            std::istringstream in(e);
            std::string line;
            while (std::getline(in, line))
                if (!line.empty()) b.lines.push_back({line, errorText});
        }
        b.maxLines = std::max(3, rows * 7 / 20);
        b.panel = {0.12f, 0.0f, 0.0f, 0.88f};
        blocks.push_back(b);
    }
    return blocks;
}

float WindowSession::textScale(int width, int height) const {
    return std::max(0.5f, hudScale(width, height) * args_.hudScale);
}

void WindowSession::drawStage(GLuint target, int width, int height) {
    Renderer& r = *slot_->renderer;
    const std::string key = refusedKey(r.stage().id);
    auto refused = refused_.find(key);
    if (waitingForTrial()) {  // nothing of these files built here yet
        glBindFramebuffer(GL_FRAMEBUFFER, target);
        glViewport(0, 0, width, height);
        glClearColor(0.1f, 0.1f, 0.12f, 1);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        return;
    }
    try {
        // Refused by the trial and never drawn here: building it from disk could hang or crash.
        if (refused != refused_.end() && !drewOnce_.count(key)) throw ShaderError(refused->second);
        if (paramsPending()) {  // values not yet drawn in the worker: the last good ones draw
            const ParamSet onScreen = r.params();
            for (const ParamSpec& p : r.params().specs()) r.params().set(p.name, p.defaultText());
            for (const auto& [name, value] : lastGoodSets_[key]) r.params().set(name, value);
            r.render(target, width, height);
            r.params() = onScreen;
        } else {
            if (drawsStudentPrograms()) lastGoodSets_[key] = nonDefault(r.params());
            r.render(target, width, height);
        }
        drewOnce_.insert(key);
        renderError_.clear();
    } catch (const ShaderError& e) {  // no good program yet for this stage: show why
        glBindFramebuffer(GL_FRAMEBUFFER, target);
        glViewport(0, 0, width, height);
        glClearColor(0.08f, 0.02f, 0.02f, 1);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        renderError_ = e.what();
        if (printedRenderError_ != renderError_)
            say(std::cerr, "shadowlab: shader error (no good program for this stage yet): " +
                               oneLine(e.what()));
        printedRenderError_ = renderError_;
    }
}

void WindowSession::PictureTarget::resize(int width, int height) {
    if (width == width_ && height == height_) return;
    width_ = width;
    height_ = height;
    colour_ = Renderbuffer::create();
    glBindRenderbuffer(GL_RENDERBUFFER, colour_.id());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    depthStencil_ = Renderbuffer::create();
    glBindRenderbuffer(GL_RENDERBUFFER, depthStencil_.id());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
    fbo_ = Framebuffer::create();
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_.id());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                              depthStencil_.id());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

std::string WindowSession::draw(int width, int height, const std::string& saveTo, bool withHud) {
    width_ = width;
    height_ = height;
    Renderer& r = *slot_->renderer;
    auto start = Clock::now();
    if (animateLight_) {  // radians per second, whatever the frame rate (down to 1 frame a second;
                          // a longer gap is a pause, not a frame, and does not jump the light)
        double dt = std::min(std::chrono::duration<double>(start - lastAnimation_).count(), 1.0);
        r.lightPosition = circlingLight(r.lightPosition, kLightRadiansPerSecond, dt);
    }
    lastAnimation_ = start;
    const float scale = textScale(width, height);
    std::pair<int, int> bands{0, 0};
    if (hudMode_ != HudMode::Hidden)
        bands = hudBands(layoutHud(hudBlocks(), width, height, scale), height, scale);
    // The picture goes between the panels, so that none covers it; panels asked for that would
    // leave it less than half the window (the full panel with the help) lie over it instead.
    if (bands.first + bands.second > height / 2) bands = {0, 0};
    std::string saved;
    if (!saveTo.empty() && !withHud) {  // the picture alone, at the window's size
        drawStage(0, width, height);
        saved = readPixelsToPng(saveTo);
    }
    const int pictureHeight = height - bands.first - bands.second;
    pictureBottom_ = bands.second;
    if (split_ && splitHalves().empty()) split_ = false;  // another stage, or its only lesson
    if (split_) {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, width, height);
        glClearColor(0.1f, 0.1f, 0.12f, 1);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        drawSplit(width, pictureHeight);
    } else if (bands.first + bands.second == 0) {
        drawStage(0, width, height);
    } else {
        picture_.resize(width, pictureHeight);
        drawStage(picture_.framebuffer(), width, pictureHeight);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, width, height);
        glClearColor(0.1f, 0.1f, 0.12f, 1);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, picture_.framebuffer());
        glBlitFramebuffer(0, 0, width, pictureHeight, 0, bands.second, width,
                          bands.second + pictureHeight, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    pictureTop_ = bands.first;
    pictureHeight_ = pictureHeight;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);  // the stage's passes leave theirs
    if (hudMode_ != HudMode::Hidden) {
        try {
            hud_.draw(r.shaders(), hudBlocks(), width, height, scale);
        } catch (const ShaderError& e) {  // a student's broken hud/text: the picture still shows
            if (renderError_.empty()) renderError_ = e.what();
        }
    }
    if (!saveTo.empty() && withHud) saved = readPixelsToPng(saveTo);
    glFinish();
    drawMs_ = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    ++drawnFrames_;
    return saved;
}

std::string WindowSession::stateJson() const {
    Renderer& r = *slot_->renderer;
    nlohmann::json j;
    j["stage"] = r.stage().id;
    j["index"] = r.stageIndex();
    j["tree"] = treeName(r.shaders().tree());
    j["sessionTree"] = treeName(tree_);
    j["scene"] = scene_;
    j["view"] = viewLabel(r.stage(), r.view);
    j["hud"] = hudMode_ == HudMode::Full      ? "full"
               : hudMode_ == HudMode::Compact ? "compact"
                                              : "hidden";
    const std::vector<std::string> errors = shownErrors();
    const bool renderErrorListed =
        std::find(errors.begin(), errors.end(), renderError_) != errors.end();
    j["errors"] = errors.size() + (renderError_.empty() || renderErrorListed ? 0 : 1);
    j["error"] = !renderError_.empty() ? oneLine(renderError_)
                 : errors.empty()      ? ""
                                       : oneLine(errors[0]);
    j["trying"] = trial_ && trial_->running();
    j["tryingValues"] = valuesPending();  // drawn with the last good values meanwhile
    // "none": no good program drew it; "trying": the student's folder is still in the worker
    j["picture"] = waitingForTrial() ? "trying" : renderError_.empty() ? "stage" : "none";
    j["drawn"] = drawnFrames_;
    j["message"] = flash_;
    j["animating"] = animateLight_;
    j["lightAngle"] = std::atan2(r.lightPosition.z, r.lightPosition.x);  // radians, around y
    const auto& specs = r.params().specs();
    j["param"] = specs.empty() ? "" : specs[selectedParam_ % specs.size()].name;
    j["value"] = specs.empty() ? "" : r.params().text(j["param"].get<std::string>());
    j["help"] = showHelp_;
    j["lesson"] = lessonLine();
    j["eye"] = {r.camera.eye.x, r.camera.eye.y, r.camera.eye.z};
    j["eyeDistance"] = glm::length(r.camera.eye - r.camera.at);
    j["split"] = nlohmann::json::array();
    if (split_)
        for (const Half& h : splitHalves()) j["split"].push_back(h.name);
    for (const ParamSpec& p : specs) j["params"][p.name] = r.params().text(p.name);
    for (const ParamSpec& p : specs)
        if (!ignoredMark(p.name).empty()) j["ignored"].push_back(p.name);
    j["width"] = width_;
    j["height"] = height_;
    j["pictureTop"] = pictureTop_;  // window rows above the picture (the top panels' band)
    j["pictureHeight"] = pictureHeight_;
    j["textScale"] = textScale(width_, height_);
    return j.dump();
}

}  // namespace sl
