// The interactive window (freeglut). It owns the context and turns input into actions on the
// renderer; all drawing is the renderer's.
#pragma once

#include "app/options.h"

namespace sl {

struct WindowArgs {
    CommonOptions common;
    int frames = 0;          // > 0: render this many frames, then exit (tests)
    std::string screenshot;  // with frames: save the last frame here
};

int runWindow(const WindowArgs& args);

}  // namespace sl
