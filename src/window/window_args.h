// What `shadowlab window` is asked to do: the command line's request, the lessons `n` steps
// through, and the scripted input of tests.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "platform/headless.h"
#include "sandbox/budget.h"
#include "stages/request.h"

namespace sl {

// A lesson the window steps through with `n`: an entry of expectations.json or a lecture figure
// of slides_examples/, with its settings and what to look for on screen.
struct WindowLesson {
    std::string stage;
    std::string scene;               // "": the stage's own
    std::vector<std::string> trees;  // empty: every tree the stage runs in
    std::vector<std::pair<std::string, std::string>> sets;
    std::string name;  // "margin margin-kind=slope: almost no acne"
    std::string look;  // what to look for, one short line
    ViewMode view = ViewMode::Final;
    // The lecture's mirror exercise drawn from above beside the picture (slides_examples'
    // "figure": the mirror's ends p1, p2, the eye and at in the x-z plane).
    bool topView = false;
    glm::vec2 p1{0.0f}, p2{0.0f}, eye{0.0f}, at{0.0f};
};

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

// The lessons of expectations.json and slides_examples/, in that order per stage.
std::vector<WindowLesson> windowLessons();

// Opens the window and runs it, then ends the process with its exit code (returns only by
// throwing, before the window opens or while it does).
int runWindow(const WindowArgs& args);

}  // namespace sl
