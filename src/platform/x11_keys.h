// X11 details freeglut leaves out.
#pragma once

namespace sl {

// Shift-Tab arrives from X as the keysym ISO_Left_Tab, which freeglut drops (it has no text
// and no special-key code). Rebinding it to "\t" for this client makes it reach the keyboard
// callback as Tab with Shift held. Call with the window's context current; false when the
// context is not GLX (then Shift-Tab stays unavailable; Tab still cycles).
bool passShiftTabAsTab();

}  // namespace sl
