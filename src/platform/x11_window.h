// X11 window matters freeglut leaves out: who has the keyboard, and whether our window still
// exists. Both find freeglut's display and window through the current GLX context.
#pragma once

namespace sl {

// Under a bare X server (Xvfb with no window manager) the keyboard follows the pointer, so keys
// typed with `xdotool key` (XTEST) go nowhere unless the pointer happens to be over the window.
// When nobody holds the focus (PointerRoot or None) and the window is viewable, it takes it;
// under a window manager (which gives the focus itself) this does nothing. True when it did.
bool takeKeyboardFocusIfNobodyHasIt();

// Call once, with the window's context current: from then on X errors about our window do not
// end the process (see windowStillExists), and a killed connection (`xdotool windowkill`, the
// X server gone) ends the session with one line on stderr and exit code 0, as closing the
// window does, instead of Xlib's message and exit 1.
void watchWindow();

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
