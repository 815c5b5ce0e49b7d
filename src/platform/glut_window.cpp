#include "platform/glut_window.h"

#include <GL/freeglut.h>

#include <cstdio>
#include <fstream>
#include <iostream>

#include "gl/gl.h"  // before freeglut, which would pull in GL/gl.h
#include "gl/loader.h"
#include "platform/window_session.h"
#include "platform/x11_keys.h"
#include "platform/x11_window.h"

namespace sl {

namespace {

// The command line's exit codes (app/options.h names them; the platform does not include app/).
constexpr int kOk = 0, kBadInput = 2, kGlFailure = 3;

constexpr int kPollMs = 125;  // shader files and on-screen messages, 8 times a second
// Esc quits when it is released (or this long after the press, if no release comes): quitting
// on the press destroyed the window before `xdotool key --window ID Escape` sent the release,
// and xdotool failed with BadWindow.
constexpr int kQuitAfterEscMs = 400;

// freeglut's callbacks are plain functions, so the window's state lives here.
struct WindowState {
    WindowArgs args;
    std::unique_ptr<WindowSession> session;
    int width = 0, height = 0;
    int startWidth = 0, startHeight = 0;  // --size
    int frame = 0;
    int exitCode = kOk;
    int dragX = -1, dragY = -1;
    bool resizeDone = false;  // --resize-test finished
    int resizeFrames = 0;     // frames the resize script took
    std::string writtenState;
    bool quitting = false;  // Esc pressed, waiting for its release
};
WindowState* g = nullptr;

void reshape(int w, int h) {
    g->width = w;
    g->height = h;
    glutPostRedisplay();
}

void quitNow(int) {
    glutLeaveMainLoop();
}

// Every key, from X or from --keys: Esc quits, the rest is the session's.
void pressKey(unsigned char key, bool shift) {
    if (key == 27) {
        if (!g->quitting) glutTimerFunc(kQuitAfterEscMs, quitNow, 0);
        g->quitting = true;
        return;
    }
    if (g->quitting) return;
    if (key == 'f' || key == 'F') {  // full screen and back: the window's, not the session's
        glutFullScreenToggle();
        return;
    }
    if (g->session->key(key, shift)) glutPostRedisplay();
}

void keyboard(unsigned char key, int, int) {
    pressKey(key, (glutGetModifiers() & GLUT_ACTIVE_SHIFT) != 0);
}

void keyboardUp(unsigned char key, int, int) {
    if (key == 27 && g->quitting) glutLeaveMainLoop();
}

// The window was destroyed under us (freeglut would go on without it): end as Esc does.
bool windowGone() {
    static bool said = false;
    if (windowStillExists()) return false;
    if (!said) std::cerr << "shadowlab: the window was closed; quitting" << std::endl;
    said = true;
    glutLeaveMainLoop();
    return true;
}

// --resize-test, one step at a time: each waits (a bounded number of frames) until the size it
// asked for has arrived, so the test does not depend on how fast the X server answers.
// A minimised window reports 0x0 through the reshape callback; X itself cannot make a 0x0
// window, so those steps call the callback as freeglut would. The real X resizes go to 16x16:
// under Xvfb (no window manager) a real 1x1 window stops freeglut's redisplays altogether, so
// 1x1 is reached through the callback too.
struct ResizeStep {
    int width, height;
    bool callbackOnly;
};

void runResizeScript() {
    static std::size_t step = 0;
    static int waited = 0;
    const int w = g->startWidth, h = g->startHeight;
    const ResizeStep steps[] = {{0, 0, true}, {w, h, true}, {16, 16, false},
                                {0, 0, true}, {1, 1, true}, {w, h, false}};
    const std::size_t count = sizeof(steps) / sizeof(steps[0]);
    if (step > count) return;
    if (step > 0) {  // wait for the previous step's size
        const ResizeStep& s = steps[step - 1];
        if ((g->width != s.width || g->height != s.height) && ++waited < 500) return;
        if (waited >= 500) {
            std::cerr << "shadowlab: --resize-test: the window never reached " << s.width << "x"
                      << s.height << std::endl;
            g->exitCode = kGlFailure;
        }
    }
    waited = 0;
    if (step < count) {
        const ResizeStep& s = steps[step];
        if (s.callbackOnly)
            reshape(s.width, s.height);
        else
            glutReshapeWindow(s.width, s.height);
    }
    ++step;
    g->resizeDone = step > count;
}

// The scripted input of --keys and --resize-test, applied after frame `frame` was drawn. A
// scripted `+` or `_` is Shift with = or -, as on the keyboard.
void runScript(int frame) {
    const std::string& keys = g->args.keys;
    if (frame >= 1 && std::size_t(frame) <= keys.size()) {
        char k = keys[std::size_t(frame) - 1];
        pressKey(static_cast<unsigned char>(k), k == '+' || k == '_');
    }
    if (g->args.resizeTest) runResizeScript();
}

// Counts a frame and says whether the loop ends after it (with --frames).
bool finishFrame() {
    ++g->frame;
    if (g->args.resizeTest && !g->resizeDone) ++g->resizeFrames;
    runScript(g->frame);
    // The resize script's frames come on top of --frames: the last ones are drawn at full size.
    return g->args.frames > 0 && g->frame >= g->args.frames + g->resizeFrames &&
           (!g->args.resizeTest || g->resizeDone);
}

void writeState() {
    if (g->args.stateFile.empty()) return;
    std::string state = g->session->stateJson();
    if (state == g->writtenState) return;
    g->writtenState = state;
    std::string tmp = g->args.stateFile + ".tmp";
    { std::ofstream(tmp) << state << "\n"; }
    std::rename(tmp.c_str(), g->args.stateFile.c_str());  // readers never see half a file
}

void display() {
    if (windowGone()) return;
    if (g->frame == 0) takeKeyboardFocusIfNobodyHasIt();
    bool testRun = g->args.frames > 0;
    if (g->width > 0 && g->height > 0) {  // minimised or 0x0: nothing to draw, time goes on
        bool last = testRun && g->frame + 1 >= g->args.frames + g->resizeFrames &&
                    (!g->args.resizeTest || g->resizeDone);
        std::string shot = last ? g->args.screenshot : "";
        std::string err = g->session->draw(g->width, g->height, shot, g->args.screenshotHud);
        if (!err.empty()) {
            std::cerr << "shadowlab: --screenshot: " << err << std::endl;
            g->exitCode = kBadInput;
        }
        glutSwapBuffers();
        if (testRun && g->session->shaderFailed()) g->exitCode = kBadInput;
        if (testRun && glErrorCount() > 0) g->exitCode = kGlFailure;
        writeState();
    }
    if (finishFrame()) {
        glutLeaveMainLoop();
        return;
    }
    // Idle costs nothing: the next frame comes from input, a reload, or a running animation
    // (test runs draw continuously through the idle callback).
    if (g->session->animating()) glutPostRedisplay();
}

void tick(int) {
    if (windowGone()) return;
    // Also later: a window that had the focus when this one opened may have closed since.
    takeKeyboardFocusIfNobodyHasIt();
    if (g->session->tick(std::chrono::steady_clock::now())) glutPostRedisplay();
    glutTimerFunc(kPollMs, tick, 0);
}

// Arrow keys orbit as a drag of 20 pixels does.
void special(int key, int, int) {
    if (g->quitting) return;
    const int step = 20;
    bool redraw = key == GLUT_KEY_LEFT    ? g->session->drag(-step, 0)
                  : key == GLUT_KEY_RIGHT ? g->session->drag(step, 0)
                  : key == GLUT_KEY_UP    ? g->session->drag(0, -step)
                  : key == GLUT_KEY_DOWN  ? g->session->drag(0, step)
                                          : false;
    if (redraw) glutPostRedisplay();
}

void mouse(int button, int state, int x, int y) {
    // The wheel: X buttons 4 and 5 (freeglut's 3 and 4), one notch a press.
    if ((button == 3 || button == 4) && state == GLUT_DOWN) {
        if (g->session->zoom(button == 3 ? 1 : -1)) glutPostRedisplay();
        return;
    }
    if (button != GLUT_LEFT_BUTTON) return;
    g->dragX = state == GLUT_DOWN ? x : -1;
    g->dragY = y;
}

void motion(int x, int y) {  // orbit the camera around its target
    if (g->dragX < 0) return;
    if (g->session->drag(x - g->dragX, y - g->dragY)) glutPostRedisplay();
    g->dragX = x;
    g->dragY = y;
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

int runWindow(const WindowArgs& args) {
    WindowState state;
    state.args = args;
    const RenderRequest& request = args.request;
    if (!args.screenshot.empty() && args.frames <= 0)
        throw UsageError("--screenshot needs --frames N (the frame to save)");
    if ((!args.keys.empty() || args.resizeTest) && args.frames <= 0)
        throw UsageError("--keys and --resize-test need --frames N (scripted input is for tests)");
    if (args.keys.find('\x1b') != std::string::npos)
        throw UsageError("--keys: Esc would quit before the last frame; leave it out");
    if (args.shots.empty()) throw UsageError("--shots: give a folder (it is created if missing)");
    // An unknown stage is a usage error before any display is opened (the session checks the
    // rest once it has a context: fixed runs legacy, mirror brings its scene).
    if (!findStage(request.stage)) validateRequest(request);
    g = &state;

    int argc = 1;
    char name[] = "shadowlab";
    char* argv[] = {name, nullptr};
    glutInit(&argc, argv);
    glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_GLUTMAINLOOP_RETURNS);
    glutInitDisplayMode(GLUT_RGBA | GLUT_DOUBLE | GLUT_DEPTH | GLUT_STENCIL);
    glutInitWindowSize(request.width, request.height);
    // No profile asked for: Mesa then gives its newest compatibility context, which runs the
    // fixed-function stage and GLSL 1.20 as well as the 3.30 core shaders.
    glutCreateWindow("shadowlab");
    if (!loadGl(reinterpret_cast<GlProcLoader>(&glutGetProcAddress)))
        throw std::runtime_error("could not load GL entry points through glutGetProcAddress");
    requireGl33();
    if (args.fullscreen) glutFullScreen();
    passShiftTabAsTab();
    watchWindow();
    // Before the session is built (compiling takes a while): keys typed meanwhile queue up for
    // the window instead of going wherever the pointer is.
    takeKeyboardFocusIfNobodyHasIt();
    installGlDebugOutput();
    state.width = state.startWidth = request.width;
    state.height = state.startHeight = request.height;
    state.session = std::make_unique<WindowSession>(args);

    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutKeyboardUpFunc(keyboardUp);
    glutMouseFunc(mouse);
    glutSpecialFunc(special);
    glutMotionFunc(motion);
    glutTimerFunc(kPollMs, tick, 0);
    if (args.frames > 0) glutIdleFunc(glutPostRedisplay);  // --frames: frame after frame
    glutMainLoop();
    int code = state.exitCode;
    state.session.reset();
    g = nullptr;
    return code;
}

}  // namespace sl
