// The window's watchdog. A shader that loops makes the draw call spin inside the driver, one that
// crashes the compiler kills the process: neither may reach the window's own context. So changed
// shaders are first drawn by a bounded worker (a child process with time and memory limits), and
// the window adopts a stage's new programs only when they drew there. The window command supplies
// the worker (the platform does not know the command layer's process code).
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "gl/shader_library.h"

namespace sl {

// One stage to draw in the trial: its scene and its parameters as the window has them.
struct TrialStage {
    std::string stage;
    std::string scene;
    std::vector<std::pair<std::string, std::string>> sets;
};

struct TrialVerdict {
    std::string stage;  // the stage
    bool ok = true;
    std::string what;  // when not ok: what happened, one line or a driver log
};

class ProgramTrial {
  public:
    virtual ~ProgramTrial() = default;
    // Starts drawing each stage with the shaders now on disk, at the window's size (a running
    // trial is abandoned).
    virtual void start(GlslTree tree, const std::string& overlay,
                       const std::vector<TrialStage>& stages, int width, int height) = 0;
    // Never waits. True once the trial is over: `verdicts` then has one per stage tried.
    virtual bool poll(std::vector<TrialVerdict>& verdicts) = 0;
    virtual bool running() const = 0;
};

}  // namespace sl
