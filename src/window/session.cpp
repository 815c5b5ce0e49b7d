#include "window/session.h"

#include <algorithm>
#include <iostream>
#include <thread>

#include "scene/scene_json.h"
#include "stages/registry.h"
#include "window/window_text.h"

namespace sl {

namespace {

// One complete line per event on the terminal, there at once (stdout is a pipe in tests).
void say(std::ostream& out, const std::string& line) {
    out << line << '\n';
    out.flush();
}

}  // namespace

WindowSession::WindowSession(const WindowArgs& args)
    : args_(args),
      request_(args.request),
      tree_(request_.tree),
      hudShaders_(GlslTree::Core, shaderTreeRoot(GlslTree::Core), "") {
    const StageInfo* info = findStage(request_.stage);
    if (info && info->legacyOnly) request_.tree = GlslTree::Legacy;  // `--stage fixed` alone
    validateRequest(request_);
    request_.tree = tree_;
    startScene_ = effectiveScene(request_);
    // The trees as shipped are trusted; the stages a student's folder takes part in are tried
    // in the bounded worker before anything of them is compiled here (the window shows at once,
    // says it is trying and answers keys meanwhile; a scripted run waits for the verdicts).
    watchdog_ = std::make_unique<Watchdog>(
        Watchdog::Folders{shaderTreeRoot(GlslTree::Core), shaderTreeRoot(GlslTree::Legacy),
                          request_.overlay, request_.tree},
        args.budget, args.backend);
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
    stageScene_ = stageScene(*info);
}

WindowSession::~WindowSession() {
    finishShots();
}

bool WindowSession::offers(const StageInfo& s, ViewMode v) {
    for (ViewMode w : s.views)
        if (w == v) return true;
    return false;
}

std::string WindowSession::sceneFor(const StageInfo& s) {
    if (lessonScene_.first == s.id && !lessonScene_.second.empty()) return lessonScene_.second;
    return stageScene(s);
}

std::string WindowSession::stageScene(const StageInfo& s) {
    RenderRequest r = request_;
    r.stage = s.id;
    std::string name = effectiveScene(r);
    if (!s.needsMirror) return name;
    auto it = sceneHasMirror_.find(name);
    if (it == sceneHasMirror_.end())
        it = sceneHasMirror_.emplace(name, bool(loadScene(name).mirror)).first;
    // A scene without a mirror: the mirror stage brings its own scene (the HUD says so).
    if (it->second) return name;
    // not a stage id: the scene "mirror"
    return s.defaultScene.empty() ? "mirror" : s.defaultScene;
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
    Renderer& prev = renderer();
    Slot* next = nullptr;
    std::string scene;
    try {
        scene = sceneFor(s);
        next = &slotFor(tree, scene, s.id);
    } catch (const std::exception& e) {
        complain(std::string("cannot show stage '") + s.id + "': " + e.what());
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
    stageScene_ = stageScene(s);
    if (sessionTree != tree_) reloadErrors_.clear();  // the other tree's: not about this picture
    tree_ = sessionTree;
    renderError_.clear();
    rebuildShown();  // programs adopted while another renderer was on screen
    return true;
}

Watchdog::OnScreen WindowSession::onScreen() const {
    Watchdog::OnScreen s;
    s.tree = shownTree();
    s.stage = renderer().stage().id;
    s.scene = scene_;
    s.sets.push_back(nonDefault(renderer().params()));
    if (split_)
        for (const SplitHalf& h : splitHalves()) {
            ParamSet half = renderer().params();
            applySets(half, h.sets);
            s.sets.push_back(nonDefault(half));
        }
    return s;
}

TrialJob WindowSession::jobFor(GlslTree tree, const std::string& stage) {
    TrialJob job;
    job.tree = tree;
    job.stage = stage;
    const StageInfo* info = findStage(stage);
    try {
        job.scene = sceneFor(*info);
    } catch (const std::exception&) {
        job.scene = startScene_;  // the stage cannot be shown either; its trial says why
    }
    ParamSet params(info->params);
    if (renderer().stage().id == stage && shownTree() == tree)
        params = renderer().params();
    else if (stage == request_.stage)
        for (const auto& [name, value] : request_.sets) params.set(name, value);
    job.sets = nonDefault(params);
    return job;
}

bool WindowSession::tick(Clock::time_point now) {
    const bool wasRunning = watchdog_->running();
    const int tried = watchdog_->triedCount();
    watchdog_->tick(
        now, onScreen(), tree_, [this](GlslTree t, const std::string& s) { return jobFor(t, s); },
        width_ > 0 ? width_ : request_.width, height_ > 0 ? height_ : request_.height);
    bool redraw = handleTrialEvents();
    redraw = redraw || wasRunning != watchdog_->running() || tried != watchdog_->triedCount();
    for (std::size_t k = 0; k < shotsWriting_.size();) {  // shots written meanwhile
        if (shotsWriting_[k].wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
            ++k;
            continue;
        }
        const std::string error = shotsWriting_[k].get();
        const std::string path = shotsPaths_[k];
        shotsWriting_.erase(shotsWriting_.begin() + long(k));
        shotsPaths_.erase(shotsPaths_.begin() + long(k));
        shotSaid(path, error);
        redraw = true;
    }
    if (!flash_.empty() && now >= flashUntil_) {
        flash_.clear();
        redraw = true;
    }
    return redraw;
}

void WindowSession::settleTrials() {
    for (;;) {
        tick(Clock::now());
        if (!watchdog_->busy(onScreen(), tree_)) return;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
}

// New programs are built here for the renderer on screen at once, for the others when they are
// shown: a frame's worth of compiling, not one per scene and tree the session has visited.
void WindowSession::adopt(GlslTree tree, const std::set<std::string>& folders, bool force) {
    for (auto& [key, slot] : slots_) {
        if (slot.renderer->shaders().tree() != tree) continue;
        Deferred& later = deferred_[key];
        later.folders.insert(folders.begin(), folders.end());
        later.force = later.force || force;
    }
    renderError_.clear();
    printedRenderError_.clear();
    rebuildShown();
}

void WindowSession::rebuildShown() {
    for (auto& [key, slot] : slots_) {
        if (&slot != slot_) continue;
        auto later = deferred_.find(key);
        if (later == deferred_.end()) return;
        // Only from files that drew in the worker: a folder saved again since waits for its
        // trial (the files on disk are what a rebuild reads).
        const GlslTree tree = slot.renderer->shaders().tree();
        auto good = [&](const std::string& folder) {
            if (findStage(folder)) return watchdog_->diskIsGood(tree, folder);
            for (const StageInfo& s : stageRegistry())  // shared: every stage drew with it
                if (!(s.legacyOnly && tree == GlslTree::Core) && !watchdog_->diskIsGood(tree, s.id))
                    return false;
            return true;
        };
        std::set<std::string> now, wait;
        for (const auto& f : later->second.folders) (good(f) ? now : wait).insert(f);
        const auto errors = slot.renderer->reloadShaders(later->second.force, &now);
        if (wait.empty())
            deferred_.erase(later);
        else
            later->second.folders = wait;
        for (const auto& e : errors)
            if (std::find(reloadErrors_.begin(), reloadErrors_.end(), e) == reloadErrors_.end()) {
                reloadErrors_.push_back(e);
                say(std::cerr,
                    "shadowlab: shader error (keeping the last good program): " + oneLine(e));
            }
        if (errors.empty()) reloadErrors_.clear();
        return;
    }
}

bool WindowSession::handleTrialEvents() {
    auto events = watchdog_->events();
    for (const Watchdog::Event& e : events) {
        const bool shown = e.tree == shownTree() && e.stage == renderer().stage().id;
        switch (e.kind) {
            case Watchdog::Event::Kind::Adopt:
                if (!e.first) {
                    if (adoptedBatch_.empty()) errorsWhenBatchBegan_ = errorsBefore_;
                    adoptedBatch_.insert(e.stage);
                    if (e.tree == shownTree() && !overlayBeforeBatch_.count(e.stage))
                        overlayBeforeBatch_[e.stage] = renderer().shaders().overlayFiles(e.stage);
                }
                adopt(e.tree, {e.stage}, forceNextAdopt_ && shown);
                if (shown) forceNextAdopt_ = false;
                break;
            case Watchdog::Event::Kind::AdoptShared:
                adopt(e.tree, {"common", lightingStage().id}, false);
                break;
            case Watchdog::Event::Kind::Refused: {
                const std::string how =
                    watchdog_->adopted(e.tree, e.stage)
                        ? "keeping the last good program"
                        : "no good program for " + e.stage + " (" + treeName(e.tree) + ") yet";
                if (saidErrors_.insert(e.what).second)
                    say(std::cerr, "shadowlab: shader error (" + how + "): " + oneLine(e.what));
                if (shown) forceNextAdopt_ = false;
                break;
            }
            case Watchdog::Event::Kind::Lost:
                complain(e.what);
                break;
            case Watchdog::Event::Kind::ValueRefused: {
                std::string values;
                for (const auto& [name, value] : e.sets)
                    values += (values.empty() ? "" : ", ") + name + " = " + value;
                const std::string line = "these values did not draw in the trial worker (" +
                                         (values.empty() ? std::string("the defaults") : values) +
                                         "): " + oneLine(e.what) +
                                         "; the last values that drew show";
                complain(line);
                // On screen, back to what drew (if the stage still shows these values), and the
                // refusal said on the HUD as long as those stay.
                Renderer& r = renderer();
                if (shown) refusal_ = {e.stage, refusalText(e), e.tree, nonDefault(r.params())};
                if (shown && nonDefault(r.params()) == e.sets) {
                    applySets(r.params(), watchdog_->drawable(e.tree, e.stage, e.sets));
                    refusal_.backTo = nonDefault(r.params());
                }
                break;
            }
        }
    }
    const bool errorsNow = !shownErrors().empty();
    if (!adoptedBatch_.empty() && !watchdog_->busy(onScreen(), tree_)) {
        if (!errorsNow) {
            std::string stages;
            for (const auto& s : adoptedBatch_) stages += (stages.empty() ? "" : ", ") + s;
            const std::string gone = filesGone();
            say(std::cout, errorsWhenBatchBegan_
                               ? "shadowlab: shaders reloaded; every program builds again" + gone
                               : "shadowlab: shaders reloaded (" + stages + ")" + gone);
            flash(gone.empty() ? "shaders reloaded: " + stages + " drew in the trial worker first"
                               : "shaders reloaded" + gone,
                  false);
        }
        adoptedBatch_.clear();
        overlayBeforeBatch_.clear();
    }
    if (adoptedBatch_.empty()) errorsBefore_ = errorsNow;
    if (!errorsNow) saidErrors_.clear();  // a message that comes back is said again
    return !events.empty();
}

// "; your F is gone: ours draws in its place" for each student file the batch's stages drew from
// before and no longer do (deleted or renamed), "" when none.
std::string WindowSession::filesGone() const {
    std::vector<std::string> gone;
    for (const auto& [stage, before] : overlayBeforeBatch_) {
        const std::vector<std::string> now = renderer().shaders().overlayFiles(stage);
        for (const std::string& f : before)
            if (std::find(now.begin(), now.end(), f) == now.end()) gone.push_back(f);
    }
    if (gone.empty()) return {};
    std::string list;
    for (const std::string& f : gone) list += (list.empty() ? "" : ", ") + f;
    return "; your " + list + (gone.size() == 1 ? " is" : " are") + " gone: ours draws in " +
           (gone.size() == 1 ? "its" : "their") + " place";
}

// One line for the HUD: which files, which lesson or values, what ended the trial (a loop: the
// CPU budget it ran past).
std::string WindowSession::refusalText(const Watchdog::Event& e) const {
    std::string files;
    for (const auto& f : renderer().shaders().overlayFiles(e.stage))
        files += (files.empty() ? "" : " + ") + request_.overlay + "/" + f;
    if (files.empty()) files = "the shaders of " + e.stage;
    std::string why = e.what;
    const std::string worker = "in the trial worker: ";
    if (const std::size_t at = why.find(worker); at != std::string::npos)
        why = why.substr(at + worker.size());
    double budget = 0;
    for (const Watchdog::Tried& t : watchdog_->tried())
        if (t.what == "values" && t.sets == e.sets && t.stage == e.stage) budget = t.budgetSeconds;
    if (why.find("time limit") != std::string::npos && budget > 0)
        why = "no picture within its CPU budget of " + secondsText(budget);
    return "refused: " + files + ", " + valuesName(e.sets) + ": " + firstErrorLine(why) +
           "; the last values that drew show";
}

std::vector<std::string> WindowSession::shownErrors() const {
    std::vector<std::string> errors;
    auto add = [&](const std::string& e) {
        if (!e.empty() && std::find(errors.begin(), errors.end(), e) == errors.end())
            errors.push_back(e);
    };
    add(renderError_);
    add(watchdog_->refused(shownTree(), renderer().stage().id));
    for (const StageInfo& s : stageRegistry()) {
        const GlslTree tree = s.legacyOnly ? GlslTree::Legacy : tree_;
        add(watchdog_->refused(tree, s.id));
    }
    for (const auto& e : reloadErrors_) add(e);
    return errors;
}

void WindowSession::complain(const std::string& text) {
    say(std::cerr, "shadowlab: " + oneLine(text));
    flash(text, true);
}

void WindowSession::flash(const std::string& text, bool error) {
    flash_ = text;
    flashIsError_ = error;
    flashUntil_ = Clock::now() + kFlashTime;
}

}  // namespace sl
