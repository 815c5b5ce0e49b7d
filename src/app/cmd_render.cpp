// `shadowlab render --stage ID --out FILE.png`: one headless frame.
#include <algorithm>
#include <chrono>
#include <iostream>

#include "app/bench_run.h"
#include "app/commands.h"

namespace sl {

namespace {

struct RenderArgs {
    CommonOptions common;
    std::string out;
    bool explain = false;
    int repeat = 10;
    bool moveLight = false;
};

int renderOnce(const RenderArgs& a) {
    RenderRequest request = toRequest(a.common);
    validateRequest(request);
    if (a.out.empty()) throw UsageError("--out: a PNG file name is required");
    auto context = createHeadlessContext(toBackend(a.common.backend), request.tree, request.width,
                                         request.height);
    installGlDebugOutput();
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
    if (glErrorCount() > 0)
        throw std::runtime_error("the render raised " + std::to_string(glErrorCount()) +
                                 " GL error(s); last: " + lastGlError());
    std::string err = writePng(a.out, context->read());
    if (!err.empty()) throw UsageError("--out: " + err);
    std::cout << "rendered " << request.stage << " (" << treeName(request.tree) << ", "
              << context->backendName() << ") -> " << a.out << "  first frame " << first
              << " ms, median " << median << " ms/frame over " << steady.size() << " frames\n";
    for (const auto& note : renderer->stats.notes) std::cout << "  " << note << "\n";
    if (a.explain) std::cout << renderer->explain();
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
    cmd->add_option("--repeat", args->repeat, "frames timed after the first (median reported)")
        ->check(CLI::Range(0, 1000));
    return {cmd, [args] { return guarded([&] { return renderOnce(*args); }); }};
}

}  // namespace sl
