// The interactive window (freeglut). It owns the context and turns input into actions on the
// renderer; all drawing is the renderer's.
#pragma once

#include "app/options.h"

namespace sl {

struct WindowArgs {
    CommonOptions common;
    int frames = 0;          // > 0: render this many frames, then exit (tests)
    std::string screenshot;  // with frames: save the last frame here
    // Scripted input for tests: keys[k] is pressed after frame k + 1 (Esc is not allowed), and
    // resizeTest drives the window through 0x0, 1x1 and back to its size first (those frames
    // come on top of --frames).
    std::string keys;
    bool resizeTest = false;
};

int runWindow(const WindowArgs& args);

}  // namespace sl
