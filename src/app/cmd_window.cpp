// `shadowlab window`: the interactive window (freeglut).
#include "app/commands.h"
#include "platform/glut_window.h"

namespace sl {

Command addWindowCommand(CLI::App& app) {
    auto args = std::make_shared<WindowArgs>();
    auto* cmd = app.add_subcommand("window", "interactive window: every stage one key away");
    addCommonOptions(cmd, args->common);
    cmd->add_option("--frames", args->frames, "render N frames, then exit (for tests)");
    cmd->add_option("--screenshot", args->screenshot, "save the last frame as PNG (with --frames)");
    return {cmd, [args] { return guarded([&] { return runWindow(*args); }); }};
}

}  // namespace sl
