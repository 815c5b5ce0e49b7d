#include "platform/x11_keys.h"

#include <X11/Xlib.h>
#include <X11/keysym.h>
#include <dlfcn.h>

namespace sl {

bool passShiftTabAsTab() {
    // freeglut's Display is the current GLX context's; glXGetCurrentDisplay is looked up at run
    // time because <GL/glx.h> would clash with glad's GL header.
    using GetDisplay = Display* (*)();
    auto getDisplay = reinterpret_cast<GetDisplay>(dlsym(RTLD_DEFAULT, "glXGetCurrentDisplay"));
    Display* display = getDisplay ? getDisplay() : nullptr;
    if (!display) return false;
    // No modifier list: ISO_Left_Tab only comes with Shift anyway, and a list makes this
    // libX11 look up modifiers under the display lock it already holds (a deadlock).
    const unsigned char tab[] = "\t";
    XRebindKeysym(display, XK_ISO_Left_Tab, nullptr, 0, tab, 1);
    return true;
}

}  // namespace sl
