// shadowlab: render-to-texture in OpenGL, shadow maps and a planar mirror, as the lecture teaches
// them. Subcommands live in src/app/cmd_*.cpp.
#include <iostream>

#include "app/commands.h"
#include "io/box.h"
#include "io/usage_error.h"

int main(int argc, char** argv) {
    sl::applyBoxThreads();  // before any GL context: llvmpipe sizes its threads once
    CLI::App app{"shadowlab: shadow maps and a planar mirror, stage by stage"};
    app.require_subcommand(1);
    std::vector<sl::Command> commands = {
        sl::addStagesCommand(app),  sl::addRenderCommand(app),  sl::addWindowCommand(app),
        sl::addBenchCommand(app),   sl::addSweepCommand(app),   sl::addCheckCommand(app),
        sl::addExampleCommand(app), sl::addReleaseCommand(app), sl::addGradeCommand(app)};
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "shadowlab: " << e.what() << " (run 'shadowlab --help' for the commands)\n";
        return sl::kBadInput;
    }
    for (auto& c : commands)
        if (c.sub->parsed()) return c.run();
    return sl::kBadInput;
}
