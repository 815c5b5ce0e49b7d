// What `shadowlab window` is asked to do: the command line's request, the lessons `n` steps
// through, and the scripted input of tests.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "lecture/lessons.h"
#include "platform/headless.h"
#include "sandbox/budget.h"
#include "stages/request.h"

namespace sl {

struct WindowArgs {
    RenderRequest request;
    BudgetRule budget;  // the trial worker's (window/trial_runner.h)
    Backend backend = Backend::Auto;
    bool fullscreen = false;
    float hudScale = 1;  // times the text size that suits the window
    std::vector<WindowLesson> lessons;
    int frames = 0;              // > 0: render this many frames, then exit (tests)
    std::string screenshot;      // with frames: save the last frame here
    bool screenshotHud = false;  // the screenshot includes the HUD (for the README)
    // Scripted input for tests: keys[k] is pressed after frame k + 1 (Esc is not allowed), and
    // resizeTest drives the window through 0x0, 1x1 and back to its size first (those frames
    // come on top of --frames).
    std::string keys;
    bool resizeTest = false;
    std::string shots = "shots";  // where `p` saves
    std::string stateFile;        // "": none; else the HUD's state as JSON, rewritten on change
};

// Opens the window and runs it, then ends the process with its exit code (returns only by
// throwing, before the window opens or while it does).
int runWindow(const WindowArgs& args);

}  // namespace sl
