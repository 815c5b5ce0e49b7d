// `shadowlab window`'s loop: the OS window's events handed to the session, the scripted input
// of tests (--frames, --keys, --resize-test), --state, and the exit code.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>

#include "gl/debug.h"
#include "gl/gl.h"
#include "io/usage_error.h"
#include "platform/glut_window.h"
#include "stages/registry.h"
#include "window/session.h"

namespace sl {

namespace {

// The command line's exit codes (app/options.h names them; window/ does not include app/).
constexpr int kOk = 0, kBadInput = 2, kGlFailure = 3;

constexpr int kPollMs = 100;  // shader files, trials and on-screen messages, 10 times a second
// Esc quits when it is released (or this long after the press, if no release comes): quitting
// on the press destroyed the window before `xdotool key --window ID Escape` sent the release,
// and xdotool failed with BadWindow.
constexpr int kQuitAfterEscMs = 300;

// Everything of ours is done (shots written, the state file renamed into place); what is left
// is tearing down renderers, the driver and freeglut, and reaping a trial worker that may be
// freeing gigabytes: the process ends now instead.
[[noreturn]] void endProcess(int code) {
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    std::_Exit(code);
}

double secondsOf(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(t.time_since_epoch()).count();
}

class WindowLoop : public WindowEvents {
  public:
    explicit WindowLoop(const WindowArgs& args) : args_(args) {}
    int run();
    int finish();

    void display() override;
    void reshape(int w, int h) override {
        width_ = w;
        height_ = h;
        if (w > 0 && h > 0) session_->resized(w, h);
        postRedisplay();
    }
    void key(unsigned char key, bool shift) override;
    void keyUp(unsigned char key) override {
        if (key == 27 && quitting_) leaveWindowLoop();
    }
    void special(SpecialKey key, bool shift) override {
        if (quitting_) return;
        received();
        if (session_->special(key, shift)) postRedisplay();
    }
    void mouse(int button, bool down, int x, int y) override;
    void motion(int x, int y) override {  // orbit the camera around its target
        if (dragX_ < 0) return;
        if (session_->drag(x - dragX_, y - dragY_)) postRedisplay();
        dragX_ = x;
        dragY_ = y;
    }
    void timer() override {
        if (session_->tick(std::chrono::steady_clock::now())) postRedisplay();
    }
    void closed(const char* how) override {
        std::cerr << "shadowlab: the window was " << how << "; quitting" << std::endl;
    }
    [[noreturn]] void finishWithoutWindow() override { endProcess(finish()); }

  private:
    static void quitNow(int);
    void received() {  // a key or a click: the next frame answers it
        ++keysReceived_;
        keyAt_ = secondsOf(std::chrono::steady_clock::now());
        answered_ = false;
    }
    void runResizeScript();
    void runScript(int frame);
    bool finishFrame();
    void writeState();

    WindowArgs args_;
    std::unique_ptr<WindowSession> session_;
    int width_ = 0, height_ = 0;
    int frame_ = 0;
    int exitCode_ = kOk;
    int dragX_ = -1, dragY_ = -1;
    bool resizeDone_ = false;  // --resize-test finished
    int resizeFrames_ = 0;     // frames the resize script took
    std::size_t resizeStep_ = 0;
    int resizeWaited_ = 0;
    std::string writtenState_;
    bool quitting_ = false;  // Esc pressed, waiting for its release
    // Every key is answered by the next frame: when it came and when that frame was done
    // (steady clock seconds, the clock tests read too).
    long keysReceived_ = 0;
    double keyAt_ = 0, answeredAt_ = 0, answerDrawMs_ = 0;
    bool answered_ = true;
};

void WindowLoop::quitNow(int) {
    leaveWindowLoop();
}

// Every key, from X or from --keys: Esc quits, `f` is the OS window's, the rest the session's.
void WindowLoop::key(unsigned char key, bool shift) {
    if (key == 27) {
        if (!quitting_) callLater(kQuitAfterEscMs, quitNow, 0);
        quitting_ = true;
        return;
    }
    if (quitting_) return;
    received();
    if (key == 'f' || key == 'F') {  // full screen and back
        toggleFullScreen();
        return;
    }
    if (session_->key(key, shift)) postRedisplay();
}

void WindowLoop::mouse(int button, bool down, int x, int y) {
    // The wheel: X buttons 4 and 5 (freeglut's 3 and 4), one notch a press.
    if ((button == 3 || button == 4) && down) {
        received();
        if (session_->zoom(button == 3 ? 1 : -1)) postRedisplay();
        return;
    }
    if (button != 0) return;  // the left button drags
    dragX_ = down ? x : -1;
    dragY_ = y;
}

// --resize-test, one step at a time: each waits (a bounded number of frames) until the size it
// asked for has arrived, so the test does not depend on how fast the X server answers.
// A minimised window reports 0x0 through the reshape callback; X itself cannot make a 0x0
// window, so those steps call the callback as freeglut would. The real X resizes go to 16x16:
// under Xvfb (no window manager) a real 1x1 window stops freeglut's redisplays altogether, so
// 1x1 is reached through the callback too.
void WindowLoop::runResizeScript() {
    struct ResizeStep {
        int width, height;
        bool callbackOnly;
    };
    const int w = args_.request.width, h = args_.request.height;
    const ResizeStep steps[] = {{0, 0, true}, {w, h, true}, {16, 16, false},
                                {0, 0, true}, {1, 1, true}, {w, h, false}};
    const std::size_t count = sizeof(steps) / sizeof(steps[0]);
    if (resizeStep_ > count) return;
    if (resizeStep_ > 0) {  // wait for the previous step's size
        const ResizeStep& s = steps[resizeStep_ - 1];
        if ((width_ != s.width || height_ != s.height) && ++resizeWaited_ < 500) return;
        if (resizeWaited_ >= 500) {
            std::cerr << "shadowlab: --resize-test: the window never reached " << s.width << "x"
                      << s.height << std::endl;
            exitCode_ = kGlFailure;
        }
    }
    resizeWaited_ = 0;
    if (resizeStep_ < count) {
        const ResizeStep& s = steps[resizeStep_];
        if (s.callbackOnly)
            reshape(s.width, s.height);
        else
            resizeWindow(s.width, s.height);
    }
    ++resizeStep_;
    resizeDone_ = resizeStep_ > count;
}

// The scripted input of --keys and --resize-test, applied after frame `frame` was drawn. A
// scripted `+` or `_` is Shift with = or -, as on the keyboard.
void WindowLoop::runScript(int frame) {
    const std::string& keys = args_.keys;
    if (frame >= 1 && std::size_t(frame) <= keys.size()) {
        char k = keys[std::size_t(frame) - 1];
        key(static_cast<unsigned char>(k), k == '+' || k == '_');
    }
    if (args_.resizeTest) runResizeScript();
}

// Counts a frame and says whether the loop ends after it (with --frames).
bool WindowLoop::finishFrame() {
    ++frame_;
    if (args_.resizeTest && !resizeDone_) ++resizeFrames_;
    runScript(frame_);
    // The resize script's frames come on top of --frames: the last ones are drawn at full size.
    return args_.frames > 0 && frame_ >= args_.frames + resizeFrames_ &&
           (!args_.resizeTest || resizeDone_);
}

void WindowLoop::writeState() {
    if (args_.stateFile.empty()) return;
    nlohmann::json state = session_->state();
    // The frame that answered the last key: when it was done, and how long it took to draw.
    state["keys"] = {{"received", keysReceived_},
                     {"at", keyAt_},
                     {"answeredAt", answeredAt_},
                     {"drawMs", answerDrawMs_}};
    std::string text = state.dump();
    if (text == writtenState_) return;
    writtenState_ = text;
    std::string tmp = args_.stateFile + ".tmp";
    { std::ofstream(tmp) << text << "\n"; }
    std::rename(tmp.c_str(), args_.stateFile.c_str());  // readers never see half a file
}

void WindowLoop::display() {
    const bool testRun = args_.frames > 0;
    if (width_ > 0 && height_ > 0) {  // minimised or 0x0: nothing to draw, time goes on
        // A scripted run draws what the trials decided: it waits for them (each ends).
        if (testRun) session_->settleTrials();
        bool last = testRun && frame_ + 1 >= args_.frames + resizeFrames_ &&
                    (!args_.resizeTest || resizeDone_);
        std::string shot = last ? args_.screenshot : "";
        std::string err = session_->draw(width_, height_, shot, args_.screenshotHud);
        if (!err.empty()) {
            std::cerr << "shadowlab: --screenshot: " << err << std::endl;
            exitCode_ = kBadInput;
        }
        swapWindowBuffers();
        if (!answered_) {
            answered_ = true;
            answeredAt_ = secondsOf(std::chrono::steady_clock::now());
            answerDrawMs_ = session_->drawMs();
        }
        if (testRun && session_->shaderFailed()) exitCode_ = kBadInput;
        if (testRun && glErrorCount() > 0) exitCode_ = kGlFailure;
        writeState();
    }
    if (finishFrame()) {
        leaveWindowLoop();
        return;
    }
    // Idle costs nothing: the next frame comes from input, a trial, or a running animation
    // (test runs draw continuously).
    if (session_->animating()) postRedisplay();
}

int WindowLoop::run() {
    openWindow(args_.request.width, args_.request.height, args_.fullscreen);
    installGlDebugOutput();
    width_ = args_.request.width;
    height_ = args_.request.height;
    session_ = std::make_unique<WindowSession>(args_);
    if (args_.fullscreen) {  // the first trials are drawn at the size the picture will have
        int w = 0, h = 0;
        screenSize(w, h);
        if (w > 0 && h > 0) session_->resized(w, h);
    }
    runWindowLoop(*this, kPollMs, args_.frames > 0);
    return finish();
}

// What is left once the loop ends. The session is not taken down: the process ends
// (endProcess), and with it a trial worker (it dies with the window's thread that forked it,
// PR_SET_PDEATHSIG) and the context.
int WindowLoop::finish() {
    session_->finishShots();
    return exitCode_;
}

}  // namespace

int runWindow(const WindowArgs& args) {
    if (!args.screenshot.empty() && args.frames <= 0)
        throw UsageError("--screenshot needs --frames N (the frame to save)");
    if ((!args.keys.empty() || args.resizeTest) && args.frames <= 0)
        throw UsageError("--keys and --resize-test need --frames N (scripted input is for tests)");
    if (args.keys.find('\x1b') != std::string::npos)
        throw UsageError("--keys: Esc would quit before the last frame; leave it out");
    if (args.shots.empty()) throw UsageError("--shots: give a folder (it is created if missing)");
    // An unknown stage is a usage error before any display is opened (the session checks the
    // rest once it has a context: fixed runs legacy, mirror brings its scene).
    if (!findStage(args.request.stage)) validateRequest(args.request);
    endProcess(WindowLoop(args).run());
}

}  // namespace sl
