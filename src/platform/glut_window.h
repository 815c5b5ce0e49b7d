// The OS window (freeglut): one double-buffered window with a compatibility-profile context
// (Mesa's runs GLSL 3.30 core shaders as well as 1.20 and the fixed-function pipeline), its
// events handed to whoever runs it. What the window shows and does is src/window/'s.
#pragma once

namespace sl {

// Keys freeglut reports apart from characters.
enum class SpecialKey { Left, Right, Up, Down, PageUp, PageDown, Home, End, Other };

// What the application does with the window's events (all on the one thread).
class WindowEvents {
  public:
    virtual ~WindowEvents() = default;
    virtual void display() = 0;
    virtual void reshape(int width, int height) = 0;
    virtual void key(unsigned char key, bool shift) = 0;
    virtual void keyUp(unsigned char key) = 0;
    virtual void special(SpecialKey key, bool shift) = 0;
    virtual void mouse(int button, bool down, int x, int y) = 0;  // 3, 4: the wheel
    virtual void motion(int x, int y) = 0;
    virtual void timer() = 0;  // every pollMs of runWindowLoop
    // The window was closed from outside: `how` says by what ("the window manager's close",
    // "destroyed"). The loop ends after this.
    virtual void closed(const char* how) = 0;
    // The window was destroyed under freeglut: returning from its loop would tear down the
    // display (XCloseDisplay), which crashes Mesa 26's GLX on the vanished drawable (exit 139 or
    // a heap abort). What the application does after its loop happens here, and the process ends.
    [[noreturn]] virtual void finishWithoutWindow() = 0;
};

// Opens the window (width x height, full screen if asked) with its context current and GL's
// entry points loaded; throws std::runtime_error when the context is older than 3.3.
void openWindow(int width, int height, bool fullscreen);
// Runs the event loop until leaveWindowLoop() or a close; `continuous`: a frame after every
// frame (scripted runs), else frames come from postRedisplay().
void runWindowLoop(WindowEvents& events, int pollMs, bool continuous);
void leaveWindowLoop();
void postRedisplay();
void swapWindowBuffers();
void toggleFullScreen();
// Calls `what(value)` once, `ms` from now, on the loop's thread.
void callLater(int ms, void (*what)(int), int value);
// Asks freeglut to resize the window (tests).
void resizeWindow(int width, int height);
// The screen's size in pixels (what a full-screen window will be).
void screenSize(int& width, int& height);

}  // namespace sl
