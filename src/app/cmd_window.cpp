// `shadowlab window`: the options; the window itself is src/window/.
#include <cstdio>

#include "app/commands.h"
#include "io/box.h"
#include "window/trial_runner.h"
#include "window/window_args.h"

namespace sl {

Command addWindowCommand(CLI::App& app) {
    struct Args {
        CommonOptions common;
        WindowArgs window;
        std::string timeLimit = "auto", memoryLimit = "auto";
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
    char floor[16];
    std::snprintf(floor, sizeof floor, "%g", kWindowCpuFloorSeconds);
    cmd->add_option("--time-limit", a->timeLimit,
                    "CPU seconds a changed stage may take to draw in the trial worker before the "
                    "window refuses it: auto (default: " +
                        std::to_string(int(kCpuFactor)) +
                        " x what our shaders take for the same frame, at least " + floor +
                        " s), a number, or 0 = no limit");
    cmd->add_option("--memory-limit", a->memoryLimit,
                    "resident memory of the trial worker in MB: auto (default: " +
                        std::to_string(boxDefaultMemoryMb(2048)) +
                        ", what this box gives a worker), a number, or 0 = no limit");
    cmd->add_option("--frames", w.frames, "render N frames, then exit (for tests)");
    cmd->add_option("--screenshot", w.screenshot, "save the last frame as PNG (with --frames)");
    cmd->add_flag("--screenshot-hud", w.screenshotHud, "the screenshot includes the HUD");
    cmd->add_option("--keys", w.keys, "press these keys, one per frame (tests; with --frames)");
    cmd->add_flag("--resize-test", w.resizeTest,
                  "resize to 0x0, 1x1, 0x0 and back in the first frames (tests; with --frames)");
    cmd->add_option("--state", w.stateFile,
                    "write the HUD's state (stage, tree, view, errors, trials) as JSON to FILE "
                    "when it changes (tests)");
    return {cmd, [a] {
                return guarded([&] {
                    WindowArgs args = a->window;
                    args.request = toRequest(a->common);
                    args.budget = budgetRuleFrom(a->timeLimit, a->memoryLimit);
                    args.budget.memoryCeilingMb = boxDefaultMemoryMb(2048);
                    args.backend = toBackend(a->common.backend);
                    args.lessons = windowLessons();
                    return runWindow(args);
                });
            }};
}

}  // namespace sl
