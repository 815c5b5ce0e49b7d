// The interactive window (freeglut). It owns the context and turns input into actions on the
// renderers; all drawing is theirs. One compatibility-profile context runs both shader trees,
// so every stage is one key away in one session.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "platform/program_trial.h"
#include "render/request.h"

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
};

struct WindowArgs {
    RenderRequest request;
    std::shared_ptr<ProgramTrial> trial;  // where changed shaders are tried ("": adopted at once)
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

int runWindow(const WindowArgs& args);

}  // namespace sl
