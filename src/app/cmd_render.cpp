// `shadowlab render --stage ID --out FILE.png`: one headless frame.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>

#include "app/commands.h"
#include "app/mirror_figure.h"
#include "bench/bench_output.h"
#include "bench/bench_run.h"
#include "eval/job_errors.h"
#include "io/png.h"
#include "io/usage_error.h"
#include "metrics/mirror_figure.h"
#include "render/mirror_pass.h"
#include "sandbox/worker.h"
#include "scene/scene_json.h"

namespace sl {

namespace {

struct RenderArgs {
    CommonOptions common;
    LimitOptions limits;
    std::string out;
    bool explain = false;
    int repeat = 10;
    bool moveLight = false;
    std::string figure;  // --figure: the mirror seen from above
};

// --figure: the reflected camera of the scene's mirror for the requested eye and at, seen from
// above (no GL needed).
void drawMirrorFigure(const RenderRequest& request, const std::string& path) {
    std::string sceneName = effectiveScene(request);
    Scene scene = loadScene(sceneName);
    if (!scene.mirror) throw UsageError("--figure: scene '" + sceneName + "' has no mirror");
    Camera camera = scene.camera;
    if (request.eye) camera.eye = *request.eye;
    if (request.at) camera.at = *request.at;
    std::string reason;
    std::optional<Mirror> mirror = drawableMirror(*scene.mirror, &reason);
    MirrorCamera reflected;
    if (mirror)
        reflected = mirrorCamera(*mirror, camera.eye, sceneReachInFront(scene, *mirror));
    else
        reflected.reason = reason;
    MirrorTopView view =
        mirrorTopView(mirror ? *mirror : *scene.mirror, camera.eye, camera.at, reflected);
    std::filesystem::path folder = std::filesystem::absolute(path).parent_path();
    if (!std::filesystem::is_directory(folder))
        throw UsageError("--figure: the folder '" + folder.string() + "' does not exist");
    std::string err = writeMirrorFigure(path, view);
    if (!err.empty()) throw std::runtime_error("--figure: " + err);
    std::cout << "mirror seen from above -> " << path << "\n" << describeTopView(view);
}

// The frames, the PNG and the timing line: the GL part of `render`, run inside the worker.
void renderInWorker(const RenderArgs& a, const RenderRequest& request) {
    auto context = createHeadlessContext(toBackend(a.common.backend), request.tree, request.width,
                                         request.height);
    installGlDebugOutput(true);
    auto renderer = makeRenderer(request);
    renderer->timePasses = true;
    // The first frame compiles shaders and renders the map; later frames show the steady cost.
    std::vector<double> times;
    const glm::vec3 home = renderer->lightPosition;
    for (int k = 0; k <= a.repeat; ++k) {
        if (a.moveLight)  // the last frame, the one saved, is lit from the requested light
            renderer->lightPosition =
                k == a.repeat ? home : steppedLight(home, renderer->scene().light.target, k);
        auto start = std::chrono::steady_clock::now();
        renderer->render(context->framebuffer(), request.width, request.height);
        glFinish();
        times.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
    }
    double first = times.front();
    std::vector<double> steady(times.begin() + 1, times.end());
    std::sort(steady.begin(), steady.end());
    double median = steady.empty() ? first : steady[steady.size() / 2];
    throwGlFailure(glErrorCount() > 0, "the render");
    std::string err = writePng(a.out, context->read());
    if (!err.empty()) throw UsageError("--out: " + err);
    std::cout << "rendered " << request.stage << " (" << treeName(request.tree) << ", "
              << context->backendName() << ") -> " << a.out << "  first frame " << first
              << " ms, median " << median << " ms/frame over " << steady.size() << " frames\n";
    for (const auto& note : renderer->stats.notes) std::cout << "  " << note << "\n";
    if (a.explain) std::cout << renderer->explain();
}

int renderOnce(const RenderArgs& a) {
    RenderRequest request = toRequest(a.common);
    validateRequest(request);
    toBackend(a.common.backend);  // a bad name before any work
    if (!a.figure.empty()) checkOutputPath("--figure", a.figure);
    if (!a.out.empty()) checkOutputPath("--out", a.out);
    if (!a.figure.empty()) {
        drawMirrorFigure(request, a.figure);
        if (a.out.empty()) return kOk;  // the figure alone
    }
    if (a.out.empty()) throw UsageError("--out: a PNG file name is required");
    // The GL work runs in a bounded worker: a shader that hangs the compiler or crashes the
    // driver is the submission's error (exit 2), not ours.
    // A student's shaders get the budget's floors (no calibration for one picture), ours the
    // backstop alone.
    const BudgetRule rule = a.limits.rule();
    const Limits limits = request.overlay.empty() ? oursLimits(rule) : provisionalLimits(rule);
    WorkerOutcome outcome = runBounded(
        limits,
        [&] {
            renderInWorker(a, request);
            return nlohmann::json::object();
        },
        renderJobErrors());
    if (outcome.kind != WorkerOutcome::Kind::Ok)
        throw UsageError(workerFailureLine(
            "stage " + request.stage + " (" + treeName(request.tree) + ")", outcome, limits));
    return kOk;
}

}  // namespace

Command addRenderCommand(CLI::App& app) {
    auto args = std::make_shared<RenderArgs>();
    auto* cmd = app.add_subcommand("render", "render one stage headless into a PNG");
    addCommonOptions(cmd, args->common);
    cmd->add_option("--out", args->out, "output PNG file");
    cmd->add_flag("--explain", args->explain, "print the matrices and choices used");
    cmd->add_flag(
        "--move-light", args->moveLight,
        "step the light by half a degree every frame (the map is re-rendered each frame)");
    cmd->add_option("--figure", args->figure,
                    "also draw the mirror construction seen from above into this PNG (gnuplot)");
    cmd->add_option("--repeat", args->repeat, "frames timed after the first (median reported)")
        ->check(CLI::Range(0, 1000));
    addLimitOptions(cmd, args->limits);
    return {cmd, [args] { return guarded([&] { return renderOnce(*args); }); }};
}

}  // namespace sl
