#include "platform/x11_window.h"

#include <X11/Xlib.h>
#include <dlfcn.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

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

// Errors about our own window are not fatal: when someone destroys it, requests already on
// their way fail (the swap's XShmPutImage with BadDrawable, GLXBadDrawable, BadWindow) before
// the next check can notice, and Xlib's default handler would print them and exit 1. The next
// windowStillExists() decides. Once the window is known gone, nothing is fatal any more
// (freeglut's teardown destroys it again). Every other error goes to the previous handler.
Window watched = 0;
bool lost = false;
XErrorHandler previousHandler = nullptr;
int onXError(Display* d, XErrorEvent* e) {
    if (lost || (watched && e->resourceid == watched)) return 0;
    return previousHandler ? previousHandler(d, e) : 0;
}

// While a check runs: the error its request about our window got (others as usual).
int lastError = 0;
int rememberError(Display* d, XErrorEvent* e) {
    if (e->resourceid != watched) return onXError(d, e);
    lastError = e->error_code;
    return 0;
}

// Who ends the session: the application (windowEnding), the lost connection or the watch,
// whoever claims it first; the others stand aside, so one line says why.
std::atomic<bool> endClaimed{false};

// The connection itself is gone (`xdotool windowkill`, the X server stopped): Xlib would print
// its own message and exit 1; this says what happened on one line (unless the application had
// ended the session already and said why). The handler must not return.
int connectionLost(Display*) {
    if (!endClaimed.exchange(true))
        std::fputs("shadowlab: the X connection was closed (the window was killed); quitting\n",
                   stderr);
    std::fflush(stdout);
    std::_Exit(0);
}

// On a connection of its own: waits for the window's DestroyNotify, then gives the window's
// thread kStuckAfterDestroySeconds to notice (windowStillExists) and end the session.
void watchForDestroy(const std::string& displayName, Window window) {
    Display* own = XOpenDisplay(displayName.c_str());
    if (!own) return;  // no second connection: the window's thread watches alone
    XSelectInput(own, window, StructureNotifyMask);
    XSync(own, False);
    for (;;) {
        XEvent e;
        XNextEvent(own, &e);  // a lost server ends the process through connectionLost
        if (e.type == DestroyNotify && e.xdestroywindow.window == window) break;
    }
    std::this_thread::sleep_for(std::chrono::duration<double>(kStuckAfterDestroySeconds));
    if (endClaimed.exchange(true)) return;  // the application is ending the session
    std::fputs(
        "shadowlab: the window was destroyed from outside while a frame was being drawn, and "
        "the driver did not return from it; quitting\n",
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

bool keepOnScreenWithoutWindowManager() {
    Display* display = currentDisplay();
    Window window = currentWindow();
    if (!display || !window || lost) return false;
    const Window root = DefaultRootWindow(display);
    Atom type = None;
    int format = 0;
    unsigned long items = 0, after = 0;
    unsigned char* data = nullptr;
    const Atom check = XInternAtom(display, "_NET_SUPPORTING_WM_CHECK", True);
    if (check != None && XGetWindowProperty(display, root, check, 0, 1, False, AnyPropertyType,
                                            &type, &format, &items, &after, &data) == Success) {
        if (data) XFree(data);
        if (items > 0) return false;  // a window manager places windows
    }
    XWindowAttributes a;
    if (!XGetWindowAttributes(display, window, &a) || a.map_state != IsViewable) return false;
    int x = 0, y = 0;
    Window child = 0;
    XTranslateCoordinates(display, window, root, 0, 0, &x, &y, &child);
    const Screen* screen = DefaultScreenOfDisplay(display);
    const bool covers = a.width >= WidthOfScreen(screen) && a.height >= HeightOfScreen(screen);
    const int toX = covers ? 0 : std::max(x, 0), toY = covers ? 0 : std::max(y, 0);
    if (toX == x && toY == y) return false;
    XMoveWindow(display, window, toX, toY);
    XFlush(display);
    return true;
}

bool windowStillExists() {
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
    lost = lastError == BadWindow;
    return !lost;
}

void watchWindow() {
    Window window = currentWindow();
    if (!window || watched) return;
    watched = window;
    previousHandler = XSetErrorHandler(onXError);
    XSetIOErrorHandler(connectionLost);
    // A write on a killed connection (Mesa's swap, xcb) must fail and reach connectionLost, not
    // end the process with SIGPIPE.
    std::signal(SIGPIPE, SIG_IGN);
    if (Display* display = currentDisplay())
        std::thread(watchForDestroy, std::string(DisplayString(display)), window).detach();
}

void useXFromTwoThreads() {
    XInitThreads();
}

bool windowEnding() {
    static bool byApplication = false;  // the window's thread only
    if (!byApplication) byApplication = !endClaimed.exchange(true);
    return byApplication;
}

}  // namespace sl
