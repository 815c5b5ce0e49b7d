// A live window session for the window tests: `shadowlab window` on a virtual X server of its
// own, driven by real X events (xdotool), its state read back from --state.
#pragma once

#include <fcntl.h>
#include <sched.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "io/image.h"

// Last: its macros (None, Bool, Status...) would clash with gtest's headers.
#include <X11/Xlib.h>   // NOLINT(llvm-include-order)
#include <X11/Xutil.h>  // NOLINT(llvm-include-order)

namespace sl::test {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

inline std::string readText(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

inline bool waitUntil(const std::function<bool()>& done, double seconds) {
    auto end = Clock::now() + std::chrono::duration<double>(seconds);
    while (Clock::now() < end) {
        if (done()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return done();
}

// Starts `command` through sh in its own process group, in `dir`, output to files there.
inline pid_t spawn(const std::string& command, const std::string& dir,
                   const std::string& display = "") {
    pid_t pid = ::fork();
    if (pid == 0) {
        ::setpgid(0, 0);
        if (::chdir(dir.c_str()) != 0) ::_exit(127);
        if (!display.empty()) ::setenv("DISPLAY", display.c_str(), 1);
        int out = ::open("stdout.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
        int err = ::open("stderr.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
        ::dup2(out, 1);
        ::dup2(err, 2);
        ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    return pid;
}

// One window session as a user has it: `shadowlab window ARGS` on a display of its own
// (parallel tests never share one; -ac: no cookie to pass to the window), keys
// sent with xdotool as real X events. `focus`: give the window the keyboard with xdotool;
// without, the window must take it itself (a bare X server has no window manager to do it).
class LiveWindow {
  public:
    // `screen`: the virtual screen's size (a projector's 1920x1080 for the full-screen tests).
    LiveWindow(const std::string& args, const std::string& dir, bool focus = true,
               const std::string& screen = "1280x1024")
        : dir_(dir) {
        // Under a loaded parallel run the window now and then cannot open the display its
        // server just announced: a fresh server and window then, at most three times.
        for (int attempt = 0; attempt < 3; ++attempt) {
            start(args, dir, focus, screen);
            if (ready() || err().find("failed to open display") == std::string::npos) break;
            stop();
            reaped_ = false;
        }
    }
    ~LiveWindow() { stop(); }

  private:
    void start(const std::string& args, const std::string& dir, bool focus,
               const std::string& screen) {
        fs::create_directories(dir + "/x");
        // Xvfb picks a free display itself and writes its number once it accepts connections
        // (-displayfd): two servers started at once never race for one number, as xvfb-run -a's
        // look at the lock files can ("failed to open display" under a parallel ctest).
        xserver_ = spawn("exec Xvfb -displayfd 1 -ac -nolisten tcp -screen 0 " + screen + "x24",
                         dir + "/x");
        if (!waitUntil(
                [&] { return readText(dir + "/x/stdout.txt").find('\n') != std::string::npos; },
                30))
            return;
        display_ = ":" + readText(dir + "/x/stdout.txt");
        display_.erase(display_.find_last_not_of("\n ") + 1);
        window_ = spawn("exec " + std::string(SHADOWLAB_BIN) + " window " + args, dir, display_);
        // The window exists once xdotool finds it; it gets the keyboard focus (no window manager).
        std::string id;
        waitUntil(
            [&] {
                id = capture("xdotool search --name '^shadowlab$' 2>/dev/null | head -1");
                return !id.empty() || !alive();
            },
            60);
        id_ = id;
        if (id_.empty()) return;
        // Keys typed to the X server (XTEST) go to the focused window, whatever the pointer is
        // over: the pointer is put outside the window so that only the focus can route them.
        xdo("mousemove 1270 1010");
        if (focus)
            xdo("windowfocus --sync " + id_);
        else if (!waitUntil([&] { return capture("xdotool getwindowfocus 2>/dev/null") == id_; },
                            60))
            id_.clear();
    }
    void stop() {
        if (alive()) {
            ::kill(window_, SIGKILL);
            ::waitpid(window_, nullptr, 0);
        }
        if (xserver_ > 0) {
            ::kill(-xserver_, SIGTERM);
            ::waitpid(xserver_, nullptr, 0);
            xserver_ = -1;
        }
        // (alive() reaped the window: reaped_ stays true until a restart resets it)
    }

  public:
    bool ready() const { return !id_.empty(); }
    pid_t pid() const { return window_; }
    const std::string& id() const { return id_; }
    bool alive() {
        if (window_ <= 0 || reaped_) return false;
        if (::waitpid(window_, &exitStatus_, WNOHANG) != window_) return true;
        reaped_ = true;
        return false;
    }
    // Real key presses (xdotool key names: bracketright, shift+Tab, Escape...).
    bool keys(const std::string& names) { return xdo("key --delay 40 " + names) == 0; }
    int xdo(const std::string& what) {
        return std::system(("DISPLAY=" + display_ + " xdotool " + what).c_str());
    }
    std::string capture(const std::string& command) {
        std::string text;
        if (FILE* p = ::popen(("DISPLAY=" + display_ + " " + command).c_str(), "r")) {
            char buffer[256];
            while (std::fgets(buffer, sizeof buffer, p)) text += buffer;
            ::pclose(p);
        }
        while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
        return text;
    }
    nlohmann::json state() {
        std::string text = readText(dir_ + "/state.json");
        return nlohmann::json::parse(text, nullptr, false);
    }
    bool waitState(const std::function<bool(const nlohmann::json&)>& ok, double seconds) {
        return waitUntil(
            [&] {
                auto s = state();
                return !s.is_discarded() && ok(s);
            },
            seconds);
    }
    // CPU seconds the window's process has used (user + system).
    double cpuSeconds() const {
        std::string stat = readText("/proc/" + std::to_string(window_) + "/stat");
        std::istringstream in(stat.substr(stat.rfind(')') + 2));
        std::string field;
        long long utime = 0, stime = 0;
        for (int k = 3; k <= 15 && in >> field; ++k) {
            if (k == 14) utime = std::stoll(field);
            if (k == 15) stime = std::stoll(field);
        }
        return double(utime + stime) / ::sysconf(_SC_CLK_TCK);
    }
    // Esc, then the exit code (-1 when it did not end within the time).
    int quit() {
        keys("Escape");
        return exitCode();
    }
    // The exit code once the window has ended by itself (-1 when it did not within the time,
    // 128 + N when signal N ended it).
    int exitCode() {
        waitUntil([&] { return !alive(); }, 30);
        if (reaped_ && WIFSIGNALED(exitStatus_)) return 128 + WTERMSIG(exitStatus_);  // as sh
        return reaped_ && WIFEXITED(exitStatus_) ? WEXITSTATUS(exitStatus_) : -1;
    }
    // What a window manager's close button does: WM_DELETE_WINDOW sent to the window.
    bool askToClose() {
        Display* d = XOpenDisplay(display_.c_str());
        if (!d) return false;
        XEvent e{};
        e.xclient.type = ClientMessage;
        e.xclient.window = std::stoul(id_);
        e.xclient.message_type = XInternAtom(d, "WM_PROTOCOLS", False);
        e.xclient.format = 32;
        e.xclient.data.l[0] = static_cast<long>(XInternAtom(d, "WM_DELETE_WINDOW", False));
        e.xclient.data.l[1] = CurrentTime;
        bool sent = XSendEvent(d, e.xclient.window, False, NoEventMask, &e) != 0;
        XCloseDisplay(d);  // flushes
        return sent;
    }
    // What the X server shows in the window now (HUD included): a screenshot.
    Image grab() {
        Image img;
        Display* d = XOpenDisplay(display_.c_str());
        if (!d) return img;
        const ::Window win = std::stoul(id_);
        XWindowAttributes a{};
        XGetWindowAttributes(d, win, &a);
        // From the screen, where the window is (a window's own image fails when part of it is
        // off the screen: BadMatch).
        const ::Window root = DefaultRootWindow(d);
        int x0 = 0, y0 = 0;
        ::Window child;
        XTranslateCoordinates(d, win, root, 0, 0, &x0, &y0, &child);
        const int rootW = DisplayWidth(d, DefaultScreen(d)),
                  rootH = DisplayHeight(d, DefaultScreen(d));
        a.width = std::min(a.width, rootW - x0);
        a.height = std::min(a.height, rootH - y0);
        if (x0 < 0 || y0 < 0 || a.width <= 0 || a.height <= 0) {
            XCloseDisplay(d);
            return img;
        }
        if (XImage* x = XGetImage(d, root, x0, y0, a.width, a.height, AllPlanes, ZPixmap)) {
            img = Image(a.width, a.height);
            for (int j = 0; j < a.height; ++j)
                for (int i = 0; i < a.width; ++i) {
                    unsigned long p = XGetPixel(x, i, j);
                    std::uint8_t* q = img.at(i, j);
                    q[0] = (p >> 16) & 255, q[1] = (p >> 8) & 255, q[2] = p & 255, q[3] = 255;
                }
            XDestroyImage(x);
        }
        XCloseDisplay(d);
        return img;
    }
    std::string out() const { return readText(dir_ + "/stdout.txt"); }
    std::string err() const { return readText(dir_ + "/stderr.txt"); }

  private:
    std::string dir_, display_, id_;
    pid_t xserver_ = -1, window_ = -1;
    int exitStatus_ = 0;
    bool reaped_ = false;
};

// A busy loop on every core this process may use (`taskset -c N sh -c 'while :; do :; done'`),
// for as long as it lives: the window must answer and its trials finish on a loaded machine.
// Each loop is killed by its pid at the end.
class BusyCores {
  public:
    BusyCores() {
        cpu_set_t set;
        CPU_ZERO(&set);
        if (::sched_getaffinity(0, sizeof set, &set) != 0) return;
        for (int core = 0; core < CPU_SETSIZE; ++core) {
            if (!CPU_ISSET(core, &set)) continue;
            pid_t pid = ::fork();
            if (pid == 0) {
                const std::string c = std::to_string(core);
                ::execlp("taskset", "taskset", "-c", c.c_str(), "sh", "-c", "while :; do :; done",
                         static_cast<char*>(nullptr));
                ::_exit(127);
            }
            if (pid > 0) pids_.push_back(pid);
        }
    }
    ~BusyCores() {
        for (pid_t pid : pids_) {
            ::kill(pid, SIGKILL);
            ::waitpid(pid, nullptr, 0);
        }
    }
    std::size_t count() const { return pids_.size(); }

  private:
    std::vector<pid_t> pids_;
};

// Seconds on the steady clock, the one the window's --state reports use (CLOCK_MONOTONIC,
// shared by every process of the machine).
inline double steadyNow() {
    return std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
}

inline int countLines(const std::string& text, const std::string& start) {
    int n = 0;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) n += line.rfind(start, 0) == 0;
    return n;
}

}  // namespace sl::test
