#include "platform/x11_window.h"

#include <X11/Xlib.h>
#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>

namespace sl {

namespace {

// glXGetCurrentDisplay / glXGetCurrentDrawable are looked up at run time because <GL/glx.h>
// would clash with glad's GL header (as in x11_keys.cpp).
Display* currentDisplay() {
    using GetDisplay = Display* (*)();
    auto get = reinterpret_cast<GetDisplay>(dlsym(RTLD_DEFAULT, "glXGetCurrentDisplay"));
    return get ? get() : nullptr;
}

Window currentWindow() {
    using GetDrawable = XID (*)();
    auto get = reinterpret_cast<GetDrawable>(dlsym(RTLD_DEFAULT, "glXGetCurrentDrawable"));
    return get ? get() : 0;  // freeglut draws straight into its X window
}

int lastError = 0;
int rememberError(Display*, XErrorEvent* e) {
    lastError = e->error_code;
    return 0;
}

// After the window was destroyed by someone else every request about it fails (BadWindow,
// GLXBadDrawable at a swap, freeglut's own XDestroyWindow at teardown): the session is ending,
// so none of these may end it with Xlib's "X Error of failed request" and exit code 1.
int ignoreErrors(Display*, XErrorEvent*) {
    return 0;
}

// The connection itself is gone (`xdotool windowkill`, the X server stopped): Xlib would print
// its own message and exit 1; this says what happened on one line. The handler must not return.
int connectionLost(Display*) {
    std::fputs("shadowlab: the X connection was closed (the window was killed); quitting\n",
               stderr);
    std::fflush(stdout);
    std::_Exit(0);
}

}  // namespace

bool takeKeyboardFocusIfNobodyHasIt() {
    Display* display = currentDisplay();
    Window window = currentWindow();
    if (!display || !window) return false;
    Window focus = 0;
    int revert = 0;
    XGetInputFocus(display, &focus, &revert);
    if (focus != PointerRoot && focus != None) return false;  // a window manager's choice
    XWindowAttributes attributes;
    if (!XGetWindowAttributes(display, window, &attributes) || attributes.map_state != IsViewable)
        return false;  // not yet on screen (focusing it would be a BadMatch)
    XErrorHandler before = XSetErrorHandler(rememberError);
    lastError = 0;
    XSetInputFocus(display, window, RevertToPointerRoot, CurrentTime);
    XSync(display, False);
    XSetErrorHandler(before);
    return lastError == 0;
}

bool windowStillExists() {
    static bool lost = false;
    if (lost) return false;
    Display* display = currentDisplay();
    Window window = currentWindow();
    if (!display || !window) return true;
    XErrorHandler before = XSetErrorHandler(rememberError);
    lastError = 0;
    XWindowAttributes attributes;
    XGetWindowAttributes(display, window, &attributes);
    XSync(display, False);
    XSetErrorHandler(before);
    if (lastError != BadWindow) return true;
    lost = true;
    XSetErrorHandler(ignoreErrors);
    return false;
}

void reportLostConnection() {
    XSetIOErrorHandler(connectionLost);
}

}  // namespace sl
