// `shadowlab window`: the interactive window (freeglut).
#include "app/commands.h"
#include "platform/glut_window.h"

namespace sl {

Command addWindowCommand(CLI::App& app) {
    auto args = std::make_shared<WindowArgs>();
    auto* cmd = app.add_subcommand("window", "interactive window: every stage one key away");
    addCommonOptions(cmd, args->common);
    cmd->add_option("--shots", args->shots, "folder for the PNGs `p` saves (default ./shots)");
    cmd->add_option("--frames", args->frames, "render N frames, then exit (for tests)");
    cmd->add_option("--screenshot", args->screenshot, "save the last frame as PNG (with --frames)");
    cmd->add_flag("--screenshot-hud", args->screenshotHud, "the screenshot includes the HUD");
    cmd->add_option("--keys", args->keys, "press these keys, one per frame (tests; with --frames)");
    cmd->add_flag("--resize-test", args->resizeTest,
                  "resize to 0x0, 1x1, 0x0 and back in the first frames (tests; with --frames)");
    cmd->add_option("--state", args->stateFile,
                    "write the HUD's state (stage, tree, view, errors) as JSON to FILE when it "
                    "changes (tests)");
    return {cmd, [args] { return guarded([&] { return runWindow(*args); }); }};
}

}  // namespace sl
