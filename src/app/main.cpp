// shadowlab: render-to-texture in OpenGL, shadow maps and a planar mirror, as the lecture teaches
// them. Subcommands live in src/app/cmd_*.cpp.
#include <malloc.h>

#include <iostream>

#include "app/commands.h"
#include "io/box.h"
#include "io/usage_error.h"

namespace {
// A check allocates and frees images and reference buffers of 1-20 MB for every row. glibc hands
// blocks over 128 KB back to the kernel on free, so the next row faults every page in again: on
// a virtual machine that was over a quarter of a check's time (docs/ci.md, "How the time was
// cut"). Blocks up to 32 MB (glibc's largest threshold) come from the heap instead, and the
// heap's top is kept.
void reuseFreedMemory() {
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 512 << 20);
    mallopt(M_TOP_PAD, 64 << 20);
}
}  // namespace

int main(int argc, char** argv) {
    reuseFreedMemory();
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
