// X11 window matters freeglut leaves out: who has the keyboard, and whether our window still
// exists. Both find freeglut's display and window through the current GLX context.
#pragma once

namespace sl {

// Under a bare X server (Xvfb with no window manager) the keyboard follows the pointer, so keys
// typed with `xdotool key` (XTEST) go nowhere unless the pointer happens to be over the window.
// When nobody holds the focus (PointerRoot or None) and the window is viewable, it takes it;
// under a window manager (which gives the focus itself) this does nothing. True when it did.
bool takeKeyboardFocusIfNobodyHasIt();

// Call before any other X call (freeglut's included): the destruction watch below uses Xlib from
// a second thread (libX11 1.8 does this itself; Ubuntu 22.04's 1.7 does not).
void useXFromTwoThreads();

// Call once, with the window's context current: from then on X errors about our window do not
// end the process (see windowStillExists), and a killed connection (`xdotool windowkill`, the
// X server gone) ends the session with one line on stderr and exit code 0, as closing the
// window does, instead of Xlib's message and exit 1. A thread of its own, on a connection of its
// own, also watches for the window's destruction: a driver may never return from the frame it
// was drawing when the window went (Mesa 26's llvmpipe resized to the gone window's garbage
// size and cleared gigabytes, frame after frame), and then nothing on the window's thread can
// notice. Destroyed and not ended within kStuckAfterDestroySeconds, the session ends from that
// thread, with one line and exit code 0.
void watchWindow();
inline constexpr double kStuckAfterDestroySeconds = 3;
// The application ends the session itself (a close it was told of, Esc, its own finish): a
// destruction seen after this is its own, and the watch leaves the ending to it. False when the
// watch or the lost connection is ending it already (the process is about to exit: say nothing).
bool windowEnding();

// Without a window manager nobody places the window, and freeglut's full screen lands at +1+1
// (one row and column off the screen) and, toggled back, at -1-1. Under a bare X server this
// moves a window that covers the screen to 0,0 and one partly off the top or left back onto it;
// under a window manager (one that announces itself, EWMH) it does nothing. True when it moved.
bool keepOnScreenWithoutWindowManager();

// False once the window has been destroyed by someone else (`xdotool windowclose`): freeglut
// ignores DestroyNotify and would go on running with no window. One round trip to the server.
// True when the context is not GLX (nothing to watch).
bool windowStillExists();

}  // namespace sl
