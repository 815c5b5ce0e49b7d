// `shadowlab window`: the interactive window (freeglut), and the bounded worker in which it tries
// changed shaders before adopting them (the watchdog of platform/program_trial.h).
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <mutex>
#include <thread>

#include "app/commands.h"
#include "gl/debug.h"
#include "gl/gl.h"
#include "grade/worker.h"
#include "platform/glut_window.h"
#include "platform/headless.h"
#include "render/hud.h"
#include "render/renderer.h"
#include "scene/scene_json.h"
#include "stages/expectations.h"

namespace sl {

namespace {

// Draws one stage once in the worker's own headless context (made by the first stage and kept
// for the next, as `check` does).
// At the window's size: a loop's cost grows with the pixels, and a program that draws a small
// picture in time may still take a minute to fill the window.
nlohmann::json drawOnThisThread(Backend backend, GlslTree tree, const std::string& overlay,
                                const TrialStage& s, int width, int height) {
    static std::unique_ptr<HeadlessContext> context;  // in the worker only
    if (!context) {
        // Quiet: the window prints its own notes when it builds the programs it adopts, and the
        // trial's verdict comes back through the worker's pipe.
        int null = ::open("/dev/null", O_WRONLY);
        if (null >= 0) ::dup2(null, 1), ::dup2(null, 2), ::close(null);
        context = createHeadlessContext(backend, tree, width, height);
        installGlDebugOutput(true);
    }
    RenderRequest r;
    r.stage = s.stage;
    r.tree = tree;
    r.overlay = overlay;
    r.scene = s.scene;
    r.sceneGiven = true;
    r.width = width;
    r.height = height;
    r.sets = s.sets;
    auto renderer = makeRenderer(r);
    for (ViewMode v : renderer->stage().views) {  // every view: each may have its own program
        renderer->view = v;
        renderer->render(context->framebuffer(), width, height);
    }
    // The window's text too: a student may override hud/text, drawn over every frame.
    static Hud hud;
    hud.draw(renderer->shaders(), {HudBlock{{{s.stage, glm::vec4(1)}}}}, width, height, 1);
    glFinish();
    return {{"stage", s.stage}};
}

// The worker is forked from the window, whose thread has the window's GLX context current in
// libglvnd's dispatch: on that thread EGL refuses to make its own context current
// (EGL_BAD_ACCESS, seen where there is no OSMesa and EGL is the headless path). A thread of the
// worker's own starts with no context current; every trial draw runs there, one after another.
class WorkerGlThread {
  public:
    WorkerGlThread() : thread_([this] { loop(); }) { thread_.detach(); }
    void run(const std::function<void()>& task) {
        std::unique_lock<std::mutex> lock(mutex_);
        task_ = task;
        done_ = false;
        wake_.notify_all();
        wake_.wait(lock, [&] { return done_; });
    }

  private:
    void loop() {
        for (;;) {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [&] { return bool(task_); });
            std::function<void()> task = std::move(task_);
            task_ = nullptr;
            lock.unlock();
            task();
            lock.lock();
            done_ = true;
            wake_.notify_all();
        }
    }
    std::mutex mutex_;
    std::condition_variable wake_;
    std::function<void()> task_;
    bool done_ = false;
    std::thread thread_;
};

nlohmann::json drawInWorker(Backend backend, GlslTree tree, const std::string& overlay,
                            const TrialStage& s, int width, int height) {
    static WorkerGlThread gl;  // made in the worker, on its first trial
    nlohmann::json result;
    std::exception_ptr failure;
    gl.run([&] {
        try {
            result = drawOnThisThread(backend, tree, overlay, s, width, height);
        } catch (...) {
            failure = std::current_exception();
        }
    });
    if (failure) std::rethrow_exception(failure);
    return result;
}

// The stages one after the other in a series of bounded workers: one that fails (a shader error,
// a crash, out of time or memory) gets its verdict and a fresh worker goes on with the next.
class WorkerTrial : public ProgramTrial {
  public:
    WorkerTrial(const Limits& limits, Backend backend) : limits_(limits), backend_(backend) {}
    void start(GlslTree tree, const std::string& overlay, const std::vector<TrialStage>& stages,
               int width, int height) override {
        tree_ = tree;
        width_ = width;
        height_ = height;
        overlay_ = overlay;
        stages_ = stages;
        done_ = 0;
        verdicts_.clear();
        next();
    }
    bool poll(std::vector<TrialVerdict>& verdicts) override {
        if (!series_ || !series_->poll()) return false;
        for (const WorkerOutcome& o : series_->outcomes()) {
            const TrialStage& s = stages_[done_++];
            TrialVerdict v{s.stage, o.kind == WorkerOutcome::Kind::Ok, ""};
            if (o.kind == WorkerOutcome::Kind::Error)
                v.what = o.errorWhat;
            else if (!v.ok)
                v.what = workerFailureLine(
                    "stage " + s.stage + " (" + treeName(tree_) + ") in the trial worker", o,
                    limits_);
            verdicts_.push_back(v);
        }
        series_.reset();
        if (done_ < stages_.size()) {
            next();
            return false;
        }
        verdicts = verdicts_;
        return true;
    }
    bool running() const override { return series_ != nullptr; }

  private:
    void next() {
        std::vector<TrialStage> rest(stages_.begin() + long(done_), stages_.end());
        series_.reset();  // kills an abandoned trial's worker first
        if (rest.empty()) return;
        auto job = [backend = backend_, tree = tree_, overlay = overlay_, rest, w = width_,
                    h = height_](std::size_t k) {
            return drawInWorker(backend, tree, overlay, rest[k], w, h);
        };
        series_ = std::make_unique<BackgroundSeries>(limits_, rest.size(), job);
    }
    Limits limits_;
    Backend backend_;
    GlslTree tree_ = GlslTree::Core;
    int width_ = 640, height_ = 480;
    std::string overlay_;
    std::vector<TrialStage> stages_;
    std::size_t done_ = 0;
    std::vector<TrialVerdict> verdicts_;
    std::unique_ptr<BackgroundSeries> series_;
};

// The lessons `n` steps through: each stage's entries of expectations.json (its defaults first),
// then the lecture's figures of slides_examples/ for that stage (one per variant).
std::vector<WindowLesson> windowLessons() {
    std::vector<WindowLesson> lessons;
    for (const Expectation& e : expectations()) {
        WindowLesson l{e.stage, e.scene, e.trees, e.set, e.label() + ": " + e.outcome, e.look};
        lessons.push_back(l);
    }
    namespace fs = std::filesystem;
    std::vector<fs::path> files;
    std::error_code error;
    for (const auto& f : fs::directory_iterator(dataDir() + "/slides_examples", error))
        if (f.path().extension() == ".json") files.push_back(f.path());
    std::sort(files.begin(), files.end());
    for (const auto& path : files) {
        std::ifstream in(path);
        nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
        if (!j.is_object() || !j.contains("stage") || !j["stage"].is_string()) continue;
        auto strings = [](const nlohmann::json& o) {
            std::vector<std::pair<std::string, std::string>> sets;
            if (o.is_object())
                for (const auto& [k, v] : o.items())
                    if (v.is_string()) sets.emplace_back(k, v.get<std::string>());
            return sets;
        };
        WindowLesson l;
        l.stage = j["stage"];
        l.scene = j.value("scene", "");
        if (j.contains("glsl") && j["glsl"].is_string()) l.trees = {j["glsl"]};
        if (j.contains("view") && j["view"].is_string()) parseView(j["view"], l.view);
        if (j.contains("comment") && j["comment"].is_array() && !j["comment"].empty() &&
            j["comment"].back().is_string())
            l.look = j["comment"].back();
        const std::string name = "figure " + path.stem().string();
        if (j.contains("variants") && j["variants"].is_array()) {
            for (const auto& v : j["variants"]) {
                WindowLesson variant = l;
                variant.name = name + " " + v.value("label", "");
                variant.sets = strings(v.value("parameters", nlohmann::json()));
                lessons.push_back(variant);
            }
        } else {
            l.name = name;
            l.sets = strings(j.value("parameters", nlohmann::json()));
            lessons.push_back(l);
        }
    }
    return lessons;
}

}  // namespace

Command addWindowCommand(CLI::App& app) {
    struct Args {
        CommonOptions common;
        WindowArgs window;
        // A frame that takes seconds is a frozen window in a class: 3 s of CPU per stage is
        // generous (our shaders draw a 1920x1080 frame, compiling included, in well under a
        // second); the wall clock is a backstop.
        Limits limits{3, 30, 2048};
    };
    auto a = std::make_shared<Args>();
    WindowArgs& w = a->window;
    auto* cmd = app.add_subcommand("window", "interactive window: every stage one key away");
    addCommonOptions(cmd, a->common);
    cmd->add_option("--shots", w.shots, "folder for the PNGs `p` saves (default ./shots)");
    cmd->add_flag("--fullscreen", w.fullscreen, "start full screen (`f` toggles)");
    cmd->add_option("--hud-scale", w.hudScale,
                    "text size, times the size that suits the window (default 1)")
        ->check(CLI::Range(0.25, 8.0));
    cmd->add_option("--time-limit", a->limits.cpuSeconds,
                    "CPU seconds a changed shader may take to draw a stage in the trial worker "
                    "before the window refuses it (default 3; 0 = no limit)")
        ->check(CLI::Range(0.0, 86400.0));
    cmd->add_option("--memory-limit", a->limits.memoryMb,
                    "resident memory of the trial worker in MB (default 2048; 0 = no limit)")
        ->check(CLI::Range(0L, 1L << 24));
    cmd->add_option("--frames", w.frames, "render N frames, then exit (for tests)");
    cmd->add_option("--screenshot", w.screenshot, "save the last frame as PNG (with --frames)");
    cmd->add_flag("--screenshot-hud", w.screenshotHud, "the screenshot includes the HUD");
    cmd->add_option("--keys", w.keys, "press these keys, one per frame (tests; with --frames)");
    cmd->add_flag("--resize-test", w.resizeTest,
                  "resize to 0x0, 1x1, 0x0 and back in the first frames (tests; with --frames)");
    cmd->add_option("--state", w.stateFile,
                    "write the HUD's state (stage, tree, view, errors) as JSON to FILE when it "
                    "changes (tests)");
    return {cmd, [a] {
                return guarded([&] {
                    WindowArgs args = a->window;
                    args.request = toRequest(a->common);
                    args.lessons = windowLessons();
                    args.trial =
                        std::make_shared<WorkerTrial>(a->limits, toBackend(a->common.backend));
                    return runWindow(args);
                });
            }};
}

}  // namespace sl
