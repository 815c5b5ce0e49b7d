#include "platform/glut_window.h"

// clang-format off
#include "gl/gl.h"  // glad's, before freeglut, which would pull in GL/gl.h
#include <GL/freeglut.h>
// clang-format on

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <thread>

#include "gl/loader.h"
#include "platform/x11_keys.h"
#include "platform/x11_window.h"

namespace sl {

namespace {

// freeglut's callbacks are plain functions: the events' receiver lives here while the loop runs.
WindowEvents* events = nullptr;
int pollMs = 100;
bool closedSaid = false;
bool leaving = false;  // the application ended the loop: freeglut's close is its own then
// The tests' stand-in for a driver that does not return from a frame (Mesa 26 after the window
// was destroyed mid-frame: x11_window.h watchWindow): SHADOWLAB_TEST_STUCK_AFTER_DESTROY_S=N
// holds this thread N seconds where it finds the window gone. Unset: 0.
double stuckAfterDestroySeconds = 0;

void closeOnce(const char* how) {
    if (closedSaid || leaving || !events || !windowEnding()) return;
    closedSaid = true;
    events->closed(how);
    glutLeaveMainLoop();
}

// The window was destroyed under us (freeglut would go on without it, and its teardown would
// crash the driver): said once, then the application ends the process.
bool windowGone() {
    if (windowStillExists()) return false;
    if (stuckAfterDestroySeconds > 0)
        std::this_thread::sleep_for(std::chrono::duration<double>(stuckAfterDestroySeconds));
    if (!leaving && events) {
        closeOnce("destroyed from outside");
        events->finishWithoutWindow();
    }
    return true;
}

void onDisplay() {
    if (!windowGone()) events->display();
}
void onReshape(int w, int h) {
    keepOnScreenWithoutWindowManager();
    events->reshape(w, h);
}
void onKeyboard(unsigned char key, int, int) {
    events->key(key, (glutGetModifiers() & GLUT_ACTIVE_SHIFT) != 0);
}
void onKeyboardUp(unsigned char key, int, int) {
    events->keyUp(key);
}
void onSpecial(int key, int, int) {
    const SpecialKey k = key == GLUT_KEY_LEFT        ? SpecialKey::Left
                         : key == GLUT_KEY_RIGHT     ? SpecialKey::Right
                         : key == GLUT_KEY_UP        ? SpecialKey::Up
                         : key == GLUT_KEY_DOWN      ? SpecialKey::Down
                         : key == GLUT_KEY_PAGE_UP   ? SpecialKey::PageUp
                         : key == GLUT_KEY_PAGE_DOWN ? SpecialKey::PageDown
                         : key == GLUT_KEY_HOME      ? SpecialKey::Home
                         : key == GLUT_KEY_END       ? SpecialKey::End
                                                     : SpecialKey::Other;
    events->special(k, (glutGetModifiers() & GLUT_ACTIVE_SHIFT) != 0);
}
void onMouse(int button, int state, int x, int y) {
    events->mouse(button, state == GLUT_DOWN, x, y);
}
void onMotion(int x, int y) {
    events->motion(x, y);
}
void onTimer(int) {
    if (windowGone()) return;
    // Also later: a window that had the focus when this one opened may have closed since.
    takeKeyboardFocusIfNobodyHasIt();
    events->timer();
    glutTimerFunc(unsigned(pollMs), onTimer, 0);
}
// A window manager's close button (WM_DELETE_WINDOW): freeglut destroys the window and, as
// asked below, returns from its loop; this says so first.
void onClose() {
    closeOnce("closed by the window manager");
}

// The window's context is a compatibility one (it runs both trees); the core tree needs 3.3.
void requireGl33() {
    int major = 0, minor = 0;
    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    if (!version || std::sscanf(version, "%d.%d", &major, &minor) != 2 || major * 10 + minor < 33)
        throw std::runtime_error(std::string("the window's GL context is ") +
                                 (version ? version : "?") +
                                 "; shadowlab needs OpenGL 3.3 in the compatibility profile");
}

}  // namespace

void openWindow(int width, int height, bool fullscreen) {
    int argc = 1;
    char name[] = "shadowlab";
    char* argv[] = {name, nullptr};
    if (const char* stuck = std::getenv("SHADOWLAB_TEST_STUCK_AFTER_DESTROY_S"))
        stuckAfterDestroySeconds = std::atof(stuck);
    useXFromTwoThreads();
    glutInit(&argc, argv);
    glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_GLUTMAINLOOP_RETURNS);
    glutInitDisplayMode(GLUT_RGBA | GLUT_DOUBLE | GLUT_DEPTH | GLUT_STENCIL);
    glutInitWindowSize(width, height);
    // No profile asked for: Mesa then gives its newest compatibility context, which runs the
    // fixed-function stage and GLSL 1.20 as well as the 3.30 core shaders.
    glutCreateWindow("shadowlab");
    if (!loadGl(reinterpret_cast<GlProcLoader>(&glutGetProcAddress)))
        throw std::runtime_error("could not load GL entry points through glutGetProcAddress");
    requireGl33();
    if (fullscreen) glutFullScreen();
    passShiftTabAsTab();
    watchWindow();
    // Before the application is built (compiling takes a while): keys typed meanwhile queue up
    // for the window instead of going wherever the pointer is.
    takeKeyboardFocusIfNobodyHasIt();
}

void runWindowLoop(WindowEvents& receiver, int ms, bool continuous) {
    events = &receiver;
    pollMs = ms;
    glutDisplayFunc(onDisplay);
    glutReshapeFunc(onReshape);
    glutKeyboardFunc(onKeyboard);
    glutKeyboardUpFunc(onKeyboardUp);
    glutMouseFunc(onMouse);
    glutSpecialFunc(onSpecial);
    glutMotionFunc(onMotion);
    glutCloseFunc(onClose);
    glutTimerFunc(unsigned(pollMs), onTimer, 0);
    if (continuous) glutIdleFunc(glutPostRedisplay);
    glutMainLoop();
    events = nullptr;
}

void leaveWindowLoop() {
    leaving = true;
    windowEnding();
    glutLeaveMainLoop();
}
void postRedisplay() {
    glutPostRedisplay();
}
void swapWindowBuffers() {
    glutSwapBuffers();
}
void toggleFullScreen() {
    glutFullScreenToggle();
}
void callLater(int ms, void (*what)(int), int value) {
    glutTimerFunc(unsigned(ms), what, value);
}
void resizeWindow(int width, int height) {
    glutReshapeWindow(width, height);
}
void screenSize(int& width, int& height) {
    width = glutGet(GLUT_SCREEN_WIDTH);
    height = glutGet(GLUT_SCREEN_HEIGHT);
}

}  // namespace sl
