// A real freeglut window under Xvfb renders the same picture as the headless path.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>

#include "render_fixture.h"

// Last: it includes Xlib, whose macros (None, Bool, Status...) would clash with gtest's headers.
#include "io/png.h"
#include "live_window.h"  // NOLINT(llvm-include-order)
#include "stages/registry.h"

using namespace sl;
using namespace sl::test;

namespace {

// `extra`: more window options (scripted input); `frames`: how many frames before the screenshot.
void compareWindowWithHeadless(const std::string& stage, GlslTree tree,
                               const std::string& extra = "", int frames = 3) {
    std::string dir = tempDir("window");
    std::string png = dir + "/window.png";
    std::string output;
    int code = runShadowlab("window --stage " + stage + " --glsl " + treeName(tree) +
                                " --size 320x240 --frames " + std::to_string(frames) + " " + extra +
                                " --screenshot " + png,
                            &output);
    // The runner puts the command on an X server of its own; see tests/CMakeLists.txt.
    ASSERT_EQ(code, 0) << output;
    Image window;
    ASSERT_EQ(readPng(png, window), "");
    RenderRequest r;
    r.stage = stage;
    r.tree = tree;
    r.width = 320;
    r.height = 240;
    Image headless = renderHeadless(r).image;
    ASSERT_EQ(window.width, headless.width);
    ASSERT_EQ(window.height, headless.height);
    // Tolerance: mean channel difference under 1 level and no more than 0.5% of the pixels off
    // by more than 8 (GLX and OSMesa run the same llvmpipe; rasterisation may differ on edges).
    long off = 0;
    double sum = 0;
    for (int j = 0; j < r.height; ++j)
        for (int i = 0; i < r.width; ++i) {
            int worst = 0;
            for (int k = 0; k < 3; ++k) {
                int d = std::abs(window.at(i, j)[k] - headless.at(i, j)[k]);
                worst = std::max(worst, d);
                sum += d;
            }
            off += worst > 8;
        }
    EXPECT_LT(sum / (3.0 * r.width * r.height), 1.0);
    EXPECT_LT(off, r.width * r.height / 200);
}

}  // namespace

TEST(Window, CoreWindowMatchesHeadless) {
    compareWindowWithHeadless("phong", GlslTree::Core);
}
TEST(Window, LegacyWindowMatchesHeadless) {
    compareWindowWithHeadless("phong", GlslTree::Legacy);
}
// The mirror stage: the render-to-texture pass inside a window's frame, drawn like headless.
TEST(Window, MirrorWindowMatchesHeadless) {
    compareWindowWithHeadless("mirror", GlslTree::Core);
}
TEST(Window, LegacyMirrorWindowMatchesHeadless) {
    compareWindowWithHeadless("mirror", GlslTree::Legacy);
}

namespace {

// Every key the window knows (but p, which saves, and Esc) pressed in every stage: digits
// select the stage, then views, parameters, light, help, reload, resets, HUD modes, trees.
std::string keysForEveryStage() {
    std::string keys;
    for (char stage = '0'; stage <= '9'; ++stage) {
        keys += stage;
        keys += "vvvvv\t+\t-++--\t\t+=_lhlhrxcii";
    }
    keys += "g]]]]]]]]g[[[[[[[[i";
    keys += "]]][[[]][[";
    return keys;
}

// Presses every key in every stage in a real window of the tree; the run must end normally.
void pressEveryKeyInEveryStage(GlslTree tree) {
    std::string keys = keysForEveryStage();
    std::string output;
    int code =
        runShadowlab(std::string("window --glsl ") + treeName(tree) + " --size 200x150 --frames " +
                         std::to_string(keys.size() + 2) + " --keys '" + keys + "'",
                     &output);
    EXPECT_EQ(code, 0) << output;
}

}  // namespace

TEST(Window, SurvivesEveryKeyInEveryStageLegacy) {
    pressEveryKeyInEveryStage(GlslTree::Legacy);
}

// Key 6 (fixed) is legacy-only: a core session runs it on the legacy tree.
TEST(Window, SurvivesEveryKeyInEveryStageCore) {
    pressEveryKeyInEveryStage(GlslTree::Core);
}

// Minimised (0x0), 1x1, 0x0 and back: the last frame is the same picture as before.
TEST(Window, SurvivesResizeTo0x0AndBackPhong) {
    compareWindowWithHeadless("phong", GlslTree::Core, "--resize-test", 14);
}
TEST(Window, SurvivesResizeTo0x0AndBackHardware) {
    compareWindowWithHeadless("hardware", GlslTree::Core, "--resize-test", 14);
}
TEST(Window, SurvivesResizeTo0x0AndBackMirror) {
    compareWindowWithHeadless("mirror", GlslTree::Core, "--resize-test", 14);
}

// ---- live sessions: a window on its own virtual X server, driven by real X key events -------

namespace {}  // namespace

// The "done when": one session started with no options; `]` through all eight stages
// and `p` at each, then the other tree with `g`, `[` back through all eight and `p` at each.
TEST(LiveWindow, EveryStageInOneSessionBothTreesWithShots) {
    std::string dir = tempDir("live-stages");
    LiveWindow w("", dir);
    ASSERT_TRUE(w.ready()) << w.err();
    std::string forward = "p", backward = "p";
    const int stages = int(stageIds().size());  // the lecture's eight and the peers' stage
    for (int k = 0; k + 1 < stages; ++k) forward += " bracketright p", backward += " bracketleft p";
    ASSERT_TRUE(w.keys(forward + " g " + backward));
    ASSERT_TRUE(waitUntil([&] { return countLines(w.out(), "saved ") >= 2 * stages; }, 90))
        << w.out() << w.err();
    EXPECT_EQ(w.quit(), 0) << w.err();
    // Every shot is in ./shots, named <stage>-<tree>-<view>-<time>.png, announced with its
    // absolute path on a line of its own.
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(dir + "/shots"))
        names.insert(e.path().filename().string());
    EXPECT_EQ(names.size(), 2u * stages);
    for (const std::string& stage : stageIds()) {
        bool legacyOnly = findStage(stage)->legacyOnly;
        for (const char* tree : {"core", "legacy"}) {
            std::string ran = legacyOnly ? "legacy" : tree;  // fixed runs legacy in both passes
            int found = 0;
            for (const auto& n : names) found += n.rfind(stage + "-" + ran + "-final-", 0) == 0;
            EXPECT_GE(found, legacyOnly ? 2 : 1) << stage << " " << tree;
        }
        EXPECT_NE(w.out().find("saved " + fs::canonical(dir).string() + "/shots/" + stage + "-"),
                  std::string::npos)
            << stage;
    }
    Image shot;
    ASSERT_EQ(readPng(dir + "/shots/" + *names.begin(), shot), "");
    EXPECT_EQ(shot.width, 640);
}

// The "done when" exactly as a person or a script does it: `shadowlab window` with no
// options in an empty folder, keys typed with plain `xdotool key` (no --window, the script does
// not focus the window, the pointer is elsewhere: under Xvfb there is no window manager, so the
// window takes the keyboard itself): `p`, then `]` and `p` seven times. Eight pictures in
// ./shots, in lecture order, each named after its stage.
TEST(LiveWindow, DoneWhenNoOptionsSevenBracketsEightShots) {
    std::string dir = tempDir("live-done-when");
    LiveWindow w("", dir, /*focus=*/false);
    ASSERT_TRUE(w.ready()) << "no window, or it never took the keyboard focus\n" << w.err();
    std::string keys = "p";
    for (int k = 0; k < 7; ++k) keys += " bracketright p";
    ASSERT_TRUE(w.keys(keys));
    ASSERT_TRUE(waitUntil([&] { return countLines(w.out(), "saved ") >= 8; }, 90))
        << w.out() << w.err();
    // `xdotool type` sends characters (it finds `]` on the keymap itself): one stage more.
    ASSERT_EQ(w.xdo("type --delay 40 ']p'"), 0);
    ASSERT_TRUE(waitUntil([&] { return countLines(w.out(), "saved ") >= 9; }, 60)) << w.out();
    // Esc sent to the window itself: xdotool sends the release after the press, so the window
    // must still exist then (it used to be gone, and xdotool failed with BadWindow).
    EXPECT_EQ(w.xdo("key --window " + w.id() + " Escape"), 0);
    EXPECT_EQ(w.exitCode(), 0) << w.err();

    std::vector<std::string> saved;  // in the order saved, from stdout
    std::istringstream out(w.out());
    for (std::string line; std::getline(out, line);)
        if (line.rfind("saved ", 0) == 0) saved.push_back(line.substr(6));
    ASSERT_EQ(saved.size(), 9u) << w.out();
    const auto ids = stageIds();
    const std::string shots = fs::canonical(dir).string() + "/shots/";
    for (std::size_t k = 0; k < saved.size(); ++k) {
        const std::string& stage = ids[k % ids.size()];
        EXPECT_EQ(saved[k].rfind(shots + stage + "-", 0), 0u) << k << ": " << saved[k];
        EXPECT_TRUE(fs::is_regular_file(saved[k])) << saved[k];
    }
    std::set<std::string> stagesSeen;
    for (std::size_t k = 0; k < 8; ++k)
        stagesSeen.insert(
            saved[k].substr(shots.size(), saved[k].find('-', shots.size()) - shots.size()));
    EXPECT_EQ(stagesSeen.size(), 8u);  // eight different stage ids
}

// Closed from outside: `xdotool windowclose` destroys the window (freeglut ignores that and
// used to run on with no window, forever), `windowkill` cuts the connection (Xlib's exit 1).
// Both end the session at once with one line on stderr and exit code 0, also while the light
// animates (frames being drawn into the window as it goes). A window manager's close
// (WM_DELETE_WINDOW) ends it as Esc does.
TEST(LiveWindow, ClosedFromOutsideEndsTheSession) {
    for (bool animating : {false, true}) {
        std::string dir = tempDir("live-wm-close");
        LiveWindow w("--state state.json --size 320x240", dir);
        ASSERT_TRUE(w.ready()) << w.err();
        ASSERT_TRUE(w.waitState([](const auto& s) { return s["stage"] == "phong"; }, 30));
        if (animating) ASSERT_TRUE(w.keys("l"));
        ASSERT_TRUE(w.askToClose());
        EXPECT_EQ(w.exitCode(), 0) << "WM_DELETE_WINDOW " << animating << "\n" << w.err();
        EXPECT_EQ(countLines(w.err(),
                             "shadowlab: the window was closed by the window manager; "
                             "quitting"),
                  1)
            << w.err();
    }
    for (const char* how : {"windowclose", "windowkill"}) {
        for (bool animating : {false, true}) {
            std::string dir = tempDir(std::string("live-") + how);
            LiveWindow w("--state state.json --size 320x240", dir);
            ASSERT_TRUE(w.ready()) << w.err();
            ASSERT_TRUE(w.waitState([](const auto& s) { return s["stage"] == "phong"; }, 30));
            if (animating) {
                ASSERT_TRUE(w.keys("l"));
                ASSERT_TRUE(w.waitState([](const auto& s) { return s["animating"] == true; }, 10));
            }
            EXPECT_EQ(w.xdo(std::string(how) + " " + w.id()), 0);
            EXPECT_EQ(w.exitCode(), 0) << how << " " << animating << "\n" << w.err();
            EXPECT_EQ(countLines(w.err(), "shadowlab: the "), 1) << w.err();
        }
    }
}

// A driver that never returns from the frame it was drawing when the window went (Mesa 26's
// llvmpipe on Debian testing, now and then: it resized to the gone window's garbage size and
// cleared gigabytes): the watch on a connection of its own (platform/x11_window.h) ends the
// session within 3 s of the destruction, with its own line and exit code 0. The window's thread
// is held stuck for 60 s here (SHADOWLAB_TEST_STUCK_AFTER_DESTROY_S, platform/glut_window.cpp):
// without the watch the session outlives exitCode()'s 30 s.
TEST(LiveWindow, DestroyedWhileItsThreadIsStuckEndsTheSession) {
    std::string dir = tempDir("live-stuck");
    ::setenv("SHADOWLAB_TEST_STUCK_AFTER_DESTROY_S", "60", 1);
    LiveWindow w("--state state.json --size 320x240", dir);
    ::unsetenv("SHADOWLAB_TEST_STUCK_AFTER_DESTROY_S");
    ASSERT_TRUE(w.ready()) << w.err();
    ASSERT_TRUE(w.waitState([](const auto& s) { return s["stage"] == "phong"; }, 30));
    ASSERT_TRUE(w.keys("l"));  // animating, as in the runs that stuck
    ASSERT_TRUE(w.waitState([](const auto& s) { return s["animating"] == true; }, 10));
    const auto start = Clock::now();
    EXPECT_EQ(w.xdo("windowclose " + w.id()), 0);
    EXPECT_EQ(w.exitCode(), 0) << w.err();
    const double took = std::chrono::duration<double>(Clock::now() - start).count();
    EXPECT_GE(took, 2.5) << "ended before the watch's 3 s: the stuck thread was not stuck";
    EXPECT_EQ(countLines(w.err(),
                         "shadowlab: the window was destroyed from outside while a "
                         "frame was being drawn"),
              1)
        << w.err();
    EXPECT_EQ(countLines(w.err(), "shadowlab: the "), 1) << w.err();
}

// A student's shader saved the ways editors and shells do, while the window runs: an atomic
// save (temporary file renamed over it), the file deleted (ours takes over) and written again,
// `sed -i`, a file left empty for a moment, an included common file overridden and broken,
// then removed. Every break shows an error, every repair clears it without a key, a file
// caught empty is never called empty, and the terminal gets whole lines.
TEST(LiveWindow, ShaderSavedEveryWayComesAndGoes) {
    std::string dir = tempDir("live-saves");
    fs::create_directories(dir + "/mine/margin");
    fs::create_directories(dir + "/mine/common");
    const std::string source = std::string(SHADOWLAB_SOURCE_DIR) + "/shaders_core/";
    const std::string good = readText(source + "margin/lit.frag");
    const std::string common = readText(source + "common/phong.glsl");
    std::string bad = good;
    const std::string fine = "return margin;", broken = "return margin +;";
    ASSERT_NE(bad.find(fine), std::string::npos) << "the test breaks margin/lit.frag there";
    bad.replace(bad.find(fine), fine.size(), broken);
    const std::string file = dir + "/mine/margin/lit.frag";
    std::ofstream(file) << good;
    LiveWindow w("--shaders mine --stage margin --state state.json --size 320x240", dir);
    ASSERT_TRUE(w.ready()) << w.err();
    ASSERT_TRUE(w.waitState(
        [](const auto& s) { return s["stage"] == "margin" && s["picture"] == "stage"; }, 30));
    auto atomicSave = [&](const std::string& text) {
        std::string tmp = dir + "/mine/margin/.lit.frag.swp";
        std::ofstream(tmp) << text;
        fs::rename(tmp, file);
    };
    auto errorsShown = [&](bool shown, const char* step) {
        EXPECT_TRUE(w.waitState(
            [&](const auto& s) { return (s["errors"].template get<int>() > 0) == shown; }, 20))
            << step << "\n"
            << w.state().dump() << "\n"
            << w.err();
    };
    auto reloads = [&] { return countLines(w.out(), "shadowlab: shaders reloaded"); };

    atomicSave(bad);
    errorsShown(true, "atomic save of a broken file");
    atomicSave(good);
    errorsShown(false, "atomic save of the repair");
    int before = reloads();
    fs::remove(file);  // ours is used again, and the line says so
    EXPECT_TRUE(waitUntil([&] { return reloads() > before; }, 20)) << w.out();
    EXPECT_EQ(countLines(w.out(),
                         "shadowlab: shaders reloaded (margin); your margin/lit.frag is "
                         "gone: ours draws in its place"),
              1)
        << w.out();
    errorsShown(false, "file deleted");
    std::ofstream(file) << bad;  // written again, broken: it must be seen again
    errorsShown(true, "deleted file written again");
    ASSERT_EQ(std::system(("sed -i 's/return margin +;/return margin;/' " + file).c_str()), 0);
    errorsShown(false, "sed -i repair");
    before = reloads();
    { std::ofstream truncated(file, std::ios::trunc); }  // a save that pauses once truncated
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    std::ofstream(file) << good;
    EXPECT_TRUE(waitUntil([&] { return reloads() > before; }, 20)) << w.out();
    errorsShown(false, "a file empty for 300 ms, then written");
    std::ofstream(dir + "/mine/common/phong.glsl") << common << "\nvec3 broken = ;\n";
    errorsShown(true, "an overridden include broken");
    fs::remove(dir + "/mine/common/phong.glsl");
    errorsShown(false, "the broken include removed");
    // A shared file's repair is said once every stage drew, which may be after the stage on
    // screen cleared its error: wait for the line before quitting.
    auto everyProgram = [&] {
        return countLines(w.out(), "shadowlab: shaders reloaded; every program builds again");
    };
    EXPECT_TRUE(waitUntil([&] { return everyProgram() >= 3; }, 60)) << w.out();
    EXPECT_EQ(w.quit(), 0);
    const std::string err = w.err();
    EXPECT_EQ(err.find("empty"), std::string::npos) << err;
    EXPECT_GE(countLines(err, "shadowlab: shader error"), 3) << err;
    std::istringstream lines(err);
    for (std::string line; std::getline(lines, line);)  // whole lines, each its own event
        EXPECT_EQ(line.rfind("shadowlab: ", 0), 0u) << line;
    EXPECT_EQ(err.back(), '\n');
    EXPECT_EQ(everyProgram(), 3) << w.out();
}

namespace {
// The light's angle around the vertical axis from the window's state, waiting for a new frame
// so that the moment it was read is the moment it was drawn (within the polling step).
std::pair<double, Clock::time_point> freshLightAngle(LiveWindow& w) {
    double previous = w.state().value("lightAngle", 0.0), angle = previous;
    waitUntil(
        [&] {
            auto s = w.state();
            if (s.is_discarded()) return false;
            angle = s.value("lightAngle", previous);
            return angle != previous;
        },
        10);
    return {angle, Clock::now()};
}

// `l` turns the light at a fixed speed in radians per second, measured over a few seconds.
double measuredLightSpeed(const std::string& args) {
    std::string dir = tempDir("live-light");
    LiveWindow w(args + " --state state.json --size 320x240", dir);
    EXPECT_TRUE(w.ready()) << w.err();
    EXPECT_TRUE(w.waitState([](const auto& s) { return s.contains("lightAngle"); }, 30));
    w.keys("l");
    EXPECT_TRUE(w.waitState([](const auto& s) { return s["animating"] == true; }, 10));
    auto [a0, t0] = freshLightAngle(w);
    std::this_thread::sleep_for(std::chrono::seconds(3));
    auto [a1, t1] = freshLightAngle(w);
    EXPECT_EQ(w.quit(), 0);
    double turned = std::remainder(a1 - a0, 2 * M_PI);
    return turned / std::chrono::duration<double>(t1 - t0).count();
}
}  // namespace

// The README's 0.6 rad/s, at a fast frame rate (small map) and a slow one (an 8192 map, a few
// frames a second here): it used to be 0.02 rad per frame. The margin covers reading the state
// up to a polling step late at either end.
TEST(LiveWindow, LightTurnsInRadiansPerSecond) {
    double fast = measuredLightSpeed("--stage hardware --set map-size=256");
    double slow = measuredLightSpeed("--stage hardware --set map-size=8192");
    EXPECT_NEAR(fast, 0.6, 0.1);
    EXPECT_NEAR(slow, 0.6, 0.1);
}

// A student breaks the shader while the window runs, then repairs it the way `cp` does
// (truncate, a pause, the rest): the error comes, then goes without any key, and the
// half-written file is never compiled.
TEST(LiveWindow, RepairedShaderClearsTheError) {
    std::string dir = tempDir("live-repair");
    fs::create_directories(dir + "/mine/phong");
    std::string good = readText(std::string(SHADOWLAB_SOURCE_DIR) + "/shaders_core/phong/lit.frag");
    std::string file = dir + "/mine/phong/lit.frag";
    std::ofstream(file) << good;
    LiveWindow w("--shaders mine --state state.json --size 320x240", dir);
    ASSERT_TRUE(w.ready()) << w.err();
    ASSERT_TRUE(w.waitState(
        [](const auto& s) { return s["stage"] == "phong" && s["picture"] == "stage"; }, 30));
    std::ofstream(file) << "#version 330 core\nvoid main() { this is not GLSL }\n";
    ASSERT_TRUE(w.waitState([](const auto& s) { return s["errors"].template get<int>() > 0; }, 15))
        << w.err();
    {
        std::ofstream half(file, std::ios::trunc);
        half << good.substr(0, good.size() / 3);
        half.flush();
        std::this_thread::sleep_for(std::chrono::milliseconds(80));
        half << good.substr(good.size() / 3);
    }
    // phong/ is shared (the light view of every shadow stage draws with it): every stage is
    // tried again, and the terminal's line comes once all of them drew.
    EXPECT_TRUE(w.waitState(
        [](const auto& s) { return s["errors"] == 0 && s["error"] == "" && s["trying"] == false; },
        90))
        << w.state().dump() << "\n"
        << w.err();
    EXPECT_EQ(w.quit(), 0);
    std::string err = w.err();
    EXPECT_EQ(err.find("empty"), std::string::npos) << err;
    EXPECT_EQ(countLines(err, "shadowlab: shader error"), 1) << err;  // one message, one line
    EXPECT_TRUE(!err.empty() && err.back() == '\n');
    EXPECT_NE(w.out().find("every program builds again\n"), std::string::npos) << w.out();
}

// `i` cycles the HUD: compact (the default, for a projector), full, hidden, compact; `h`
// shows the help.
TEST(LiveWindow, HudToggles) {
    std::string dir = tempDir("live-hud");
    LiveWindow w("--state state.json --size 320x240", dir);
    ASSERT_TRUE(w.ready()) << w.err();
    ASSERT_TRUE(w.waitState([](const auto& s) { return s["hud"] == "compact"; }, 30));
    for (const char* expected : {"full", "hidden", "compact"}) {
        ASSERT_TRUE(w.keys("i"));
        EXPECT_TRUE(w.waitState([&](const auto& s) { return s["hud"] == expected; }, 10))
            << expected;
    }
    ASSERT_TRUE(w.keys("h"));
    EXPECT_TRUE(w.waitState([](const auto& s) { return s["help"] == true; }, 10));
    // Shift-Tab goes back: two Tabs forward and one back is the second parameter.
    ASSERT_TRUE(w.keys("5 Tab Tab shift+Tab"));
    EXPECT_TRUE(w.waitState(
        [](const auto& s) { return s["stage"] == "hardware" && s["param"] == "light-fit"; }, 10))
        << w.state().dump();
    EXPECT_EQ(w.quit(), 0);
}

// The full HUD pages by whole pages with PgDn (no `h` first): each page says "page k of m",
// starts where the one before ended, and the last ends at the last line: every line is shown.
TEST(LiveWindow, FullHudPagesEveryLineOnce) {
    std::string dir = tempDir("live-pages");
    LiveWindow w("--stage margin --state state.json --size 640x360", dir);
    ASSERT_TRUE(w.ready()) << w.err();
    ASSERT_TRUE(w.waitState([](const auto& s) { return s["drawn"] > 0; }, 30));
    // The page line's numbers: page, pages, first line, last line, lines.
    auto pageLine = [](const nlohmann::json& s) {
        std::array<int, 5> n{0, 0, 0, 0, 0};
        for (const auto& l : s["hudText"])
            if (std::sscanf(l.get<std::string>().c_str(),
                            "PgUp/PgDn: page %d of %d (lines %d-%d of %d)", &n[0], &n[1], &n[2],
                            &n[3], &n[4]) == 5)
                return n;
        return n;
    };
    ASSERT_TRUE(w.keys("i"));
    ASSERT_TRUE(w.waitState([&](const auto& s) { return pageLine(s)[0] == 1; }, 10))
        << w.state()["hudText"].dump();
    const int pages = pageLine(w.state())[1], total = pageLine(w.state())[4];
    ASSERT_GE(pages, 2) << "a 640x360 window pages the full HUD";
    int shownUpTo = pageLine(w.state())[3];
    EXPECT_EQ(pageLine(w.state())[2], 1);
    for (int page = 2; page <= pages; ++page) {
        ASSERT_TRUE(w.keys("Next"));
        ASSERT_TRUE(w.waitState([&](const auto& s) { return pageLine(s)[0] == page; }, 10))
            << page << " " << w.state()["hudText"].dump();
        const auto n = pageLine(w.state());
        EXPECT_EQ(n[1], pages);
        EXPECT_EQ(n[2], shownUpTo + 1) << "page " << page << " starts where the last ended";
        shownUpTo = n[3];
    }
    EXPECT_EQ(shownUpTo, total) << "the last page ends at the last line";
    ASSERT_TRUE(w.keys("Next"));  // past the end: the last page stays
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    EXPECT_EQ(pageLine(w.state())[0], pages);
    ASSERT_TRUE(w.keys("Prior"));
    EXPECT_TRUE(w.waitState([&](const auto& s) { return pageLine(s)[0] == pages - 1; }, 10));
    EXPECT_EQ(w.quit(), 0);
}

// A window nobody touches draws nothing: over 3 s it uses next to no CPU (it used to redraw
// continuously at about 70 % of a core). A bound with a wide margin: this is not a speed test.
TEST(LiveWindow, IdleWindowCostsNextToNoCpu) {
    std::string dir = tempDir("live-idle");
    LiveWindow w("--state state.json", dir);
    ASSERT_TRUE(w.ready()) << w.err();
    ASSERT_TRUE(w.waitState([](const auto& s) { return s["stage"] == "phong"; }, 30));
    std::this_thread::sleep_for(std::chrono::seconds(1));  // the first frames and programs
    double before = w.cpuSeconds();
    std::this_thread::sleep_for(std::chrono::seconds(3));
    double used = w.cpuSeconds() - before;
    EXPECT_LT(used, 0.3) << "CPU seconds used in 3 s of idling";
    EXPECT_EQ(w.quit(), 0);
}

// `p` into a folder that cannot be written: said on stderr (one line) and on screen, and the
// session still ends with 0.
TEST(Window, FailedShotKeepsTheExitCode) {
    std::string dir = tempDir("shots-fail");
    std::string blocker = dir + "/not-a-folder";
    std::ofstream(blocker) << "x";
    std::string output;
    int code = runShadowlab(
        "window --size 200x150 --frames 4 --keys p --shots " + blocker + "/shots", &output);
    EXPECT_EQ(code, 0) << output;
    EXPECT_NE(output.find("shadowlab: p: could not save into '" + blocker + "/shots'"),
              std::string::npos)
        << output;
}

// The same with a real key press: the message on screen (the HUD's state), one line on
// stderr, and Esc still ends with 0.
TEST(LiveWindow, FailedShotShownAndExitCodeStays) {
    std::string dir = tempDir("live-shots-fail");
    std::ofstream(dir + "/not-a-folder") << "x";
    LiveWindow w("--shots not-a-folder/shots --state state.json --size 320x240", dir);
    ASSERT_TRUE(w.ready()) << w.err();
    ASSERT_TRUE(w.waitState([](const auto& s) { return s["stage"] == "phong"; }, 30));
    ASSERT_TRUE(w.keys("p"));
    EXPECT_TRUE(w.waitState(
        [](const auto& s) {
            return s["message"].template get<std::string>().rfind("p: could not save", 0) == 0;
        },
        15))
        << w.state().dump();
    EXPECT_EQ(w.quit(), 0);
    EXPECT_EQ(countLines(w.err(), "shadowlab: p: could not save into 'not-a-folder/shots'"), 1)
        << w.err();
    EXPECT_EQ(countLines(w.out(), "saved "), 0);
}

// `p` in a scripted run: the absolute path on stdout, the file there, its name the stage's.
TEST(Window, ShotGoesToTheShotsFolder) {
    std::string dir = tempDir("shots-ok");
    std::string output;
    int code = runShadowlab(
        "window --stage mirror --size 200x150 --frames 4 --keys vp --shots " + dir, &output);
    ASSERT_EQ(code, 0) << output;
    std::size_t at = output.find("saved " + dir + "/mirror-core-mirror-texture-");
    ASSERT_NE(at, std::string::npos) << output;
    std::string path = output.substr(at + 6, output.find('\n', at) - at - 6);
    Image shot;
    EXPECT_EQ(readPng(path, shot), "");
    EXPECT_EQ(shot.width, 200);
}

namespace {
// The HUD's state after a scripted run with these keys.
nlohmann::json stateAfterKeys(const std::string& keys) {
    std::string dir = tempDir("state");
    std::string output;
    int code = runShadowlab("window --size 200x150 --frames " + std::to_string(keys.size() + 2) +
                                " --keys '" + keys + "' --state " + dir + "/state.json",
                            &output);
    EXPECT_EQ(code, 0) << output;
    return nlohmann::json::parse(readText(dir + "/state.json"), nullptr, false);
}
}  // namespace

// In the default scene (no mirror) the mirror stage brings its scene, and leaving it brings
// the session's back; fixed runs on the legacy tree in a core session, and the HUD says which.
TEST(Window, MirrorBringsItsSceneAndFixedRunsLegacy) {
    auto mirror = stateAfterKeys("7");
    EXPECT_EQ(mirror["stage"], "mirror");
    EXPECT_EQ(mirror["scene"], "mirror");
    auto back = stateAfterKeys("70");
    EXPECT_EQ(back["stage"], "phong");
    EXPECT_EQ(back["scene"], "slides");
    auto fixed = stateAfterKeys("6");
    EXPECT_EQ(fixed["stage"], "fixed");
    EXPECT_EQ(fixed["tree"], "legacy");
    EXPECT_EQ(fixed["sessionTree"], "core");
    auto legacy = stateAfterKeys("g5");
    EXPECT_EQ(legacy["stage"], "hardware");
    EXPECT_EQ(legacy["tree"], "legacy");
}

// Caps Lock (or Shift) on a letter is the same command: `I` and `H` as `i` and `h`.
TEST(Window, CapitalLettersAreTheSameCommands) {
    auto s = stateAfterKeys("IH");
    EXPECT_EQ(s["hud"], "full");
    EXPECT_EQ(s["help"], true);
}

// Notes only where they help: a copy of ours with a comment added says nothing; one that stops
// using `margin` is told so once, and not about uniforms our own shader never used either
// (every lit pass gets shadowMatrix; it used to be named on every edited copy).
TEST(Window, UnusedUniformNotesOnlyForWhatTheStudentDropped) {
    std::string dir = tempDir("notes");
    const std::string source = std::string(SHADOWLAB_SOURCE_DIR) + "/shaders_core/";
    fs::create_directories(dir + "/margin");
    fs::create_directories(dir + "/hardware");
    std::string margin = readText(source + "margin/lit.frag");
    const std::string uses = "return margin;";
    ASSERT_NE(margin.find(uses), std::string::npos);
    margin.replace(margin.find(uses), uses.size(), "return 0.01;");
    std::ofstream(dir + "/margin/lit.frag") << margin;
    std::ofstream(dir + "/hardware/lit.frag")
        << readText(source + "hardware/lit.frag") << "// mine\n";
    std::string output;
    int code = runShadowlab(
        "window --shaders " + dir + " --stage margin --size 200x150 --frames 6 --keys 54r4",
        &output);
    EXPECT_EQ(code, 0) << output;
    EXPECT_EQ(countLines(output,
                         "shadowlab: note: margin/lit (your shader) has no active "
                         "uniform 'margin'"),
              1)
        << output;
    EXPECT_EQ(countLines(output, "shadowlab: note:"), 1) << output;
}

namespace {
// The state and the screenshot (with the HUD) of a scripted run; its exit code and output.
struct Scripted {
    int code = -1;
    std::string output;
    nlohmann::json state;
    Image shot;
};
Scripted scripted(const std::string& args, const std::string& keys, int frames = 0) {
    Scripted out;
    const std::string dir = tempDir("scripted");
    out.code = runShadowlab("window " + args + " --frames " +
                                std::to_string(frames > 0 ? frames : int(keys.size()) + 3) +
                                (keys.empty() ? "" : " --keys '" + keys + "'") + " --state " + dir +
                                "/state.json --screenshot " + dir + "/shot.png --screenshot-hud",
                            &out.output);
    out.state = nlohmann::json::parse(readText(dir + "/state.json"), nullptr, false);
    EXPECT_EQ(readPng(dir + "/shot.png", out.shot), "") << out.output;
    return out;
}
std::string joinedText(const nlohmann::json& lines) {
    std::string all;
    if (lines.is_array())
        for (const auto& l : lines) all += l.get<std::string>() + "\n";
    return all;
}
// Whether the wrapped lines hold `text` (compared without the spaces and line ends wrapping
// moves: a long path is cut anywhere).
bool holds(const nlohmann::json& lines, std::string text) {
    std::string all = joinedText(lines);
    auto squeeze = [](std::string& s) {
        s.erase(std::remove_if(s.begin(), s.end(), [](char c) { return c == ' ' || c == '\n'; }),
                s.end());
    };
    squeeze(all);
    squeeze(text);
    return all.find(text) != std::string::npos;
}
// Pixels of the picture's area (pictureRect of the state) brighter than `level` in every channel.
long brightInPicture(const Scripted& s, int level) {
    const auto rect = s.state["pictureRect"];
    long n = 0;
    for (int j = rect[1]; j < rect[1].get<int>() + rect[3].get<int>() && j < s.shot.height; ++j)
        for (int i = rect[0]; i < rect[0].get<int>() + rect[2].get<int>() && i < s.shot.width; ++i)
            n += s.shot.at(i, j)[0] > level && s.shot.at(i, j)[1] > level &&
                 s.shot.at(i, j)[2] > level;
    return n;
}
}  // namespace

// `h` shows the keys in every HUD mode and at every size: in the picture's place, as large as
// the window's text when they fit, smaller or a page at a time when not (the first keys always
// show, then either the last or where PgDn goes on).
TEST(Window, HelpShowsTheKeysInEveryModeAndSize) {
    for (const char* size : {"200x150", "640x480", "1280x720"})
        for (const char* keys : {"h", "ih", "iih"}) {
            const Scripted s = scripted(std::string("--size ") + size, keys);
            const std::string what = std::string(size) + " keys " + keys;
            ASSERT_EQ(s.code, 0) << what << s.output;
            EXPECT_EQ(s.state["picture"], "help") << what;
            const std::string page = joinedText(s.state["pageText"]);
            EXPECT_NE(page.find("0-8: stage by number"), std::string::npos) << what << page;
            EXPECT_TRUE(page.find("Esc: quit") != std::string::npos ||
                        page.find("PgUp/PgDn: page 1 of ") != std::string::npos)
                << what << page;
            EXPECT_GT(brightInPicture(s, 200), 100) << what << ": no text drawn in the picture";
        }
}

// A student's folder that does not build when the window opens: where the picture would be, the
// reason (file, line, message); the terminal and the HUD say nothing false: no "last good
// program" kept (there is none), no "saved last" (nothing was saved).
TEST(Window, BrokenFolderAtStartShowsWhyWhereThePictureWouldBe) {
    const std::string dir = tempDir("broken-start");
    fs::create_directories(dir + "/margin");
    std::string text =
        readText(std::string(SHADOWLAB_SOURCE_DIR) + "/shaders_core/margin/lit.frag");
    const std::size_t at = text.find("return margin;");
    ASSERT_NE(at, std::string::npos);
    const long line = std::count(text.begin(), text.begin() + long(at), '\n') + 1;
    text.replace(at, 14, "return margin +;");
    std::ofstream(dir + "/margin/lit.frag") << text;
    const Scripted s = scripted("--shaders " + dir + " --stage margin --size 640x480", "");
    EXPECT_EQ(s.code, 2) << s.output;
    EXPECT_EQ(s.state["picture"], "none");
    const std::string page = joinedText(s.state["pageText"]);
    EXPECT_TRUE(holds(s.state["pageText"], "margin/lit.frag:" + std::to_string(line) + ":"))
        << page;
    EXPECT_TRUE(holds(s.state["pageText"], "syntax error")) << page;
    EXPECT_EQ(s.output.find("keeping the last good program"), std::string::npos) << s.output;
    EXPECT_EQ(s.output.find("saved last"), std::string::npos) << s.output;
    EXPECT_EQ(countLines(s.output, "shadowlab: shader error (no good program for margin"), 1)
        << s.output;
    EXPECT_GT(brightInPicture(s, 200), 300) << "the reason is drawn where the picture would be";
}

// The lesson's label follows the settings: after a key changes a value, or `v` another view,
// the HUD no longer names a lesson the picture is not; `x` (the defaults) is lesson 1 again.
TEST(Window, LessonLabelFollowsTheSettings) {
    const auto lesson = [](const std::string& keys) {
        return scripted("--stage bias --size 320x240", keys).state["lesson"].get<std::string>();
    };
    EXPECT_EQ(lesson("n").rfind("lesson 2/", 0), 0u);
    EXPECT_NE(lesson("n=").find("none of the"), std::string::npos);
    EXPECT_EQ(lesson("n=x").rfind("lesson 1/", 0), 0u);
    EXPECT_NE(lesson("nv").find("none of the"), std::string::npos);
}

// The mirror's second lesson describes the slides' exercise drawn from above: it is drawn, the
// mirror (blue) and the reflected camera's frustum (orange) on paper, beside the scene.
TEST(Window, MirrorLessonShowsTheViewFromAbove) {
    const Scripted s = scripted("--stage mirror --size 1024x576", "n");
    ASSERT_EQ(s.code, 0) << s.output;
    EXPECT_NE(s.state["lesson"].get<std::string>().find("from above"), std::string::npos)
        << s.state["lesson"];
    EXPECT_EQ(s.state["halvesShow"], nlohmann::json({"top-view", "stage"}));
    const auto left = s.state["halves"][0];
    long paper = 0, blue = 0, orange = 0;
    for (int j = left[1]; j < left[1].get<int>() + left[3].get<int>(); ++j)
        for (int i = left[0]; i < left[0].get<int>() + left[2].get<int>(); ++i) {
            const std::uint8_t* p = s.shot.at(i, j);
            paper += p[0] > 230 && p[1] > 230 && p[2] > 220;
            blue += p[2] > 180 && p[0] < 80;
            orange += p[0] > 180 && p[1] > 60 && p[1] < 130 && p[2] < 60;
        }
    const long area = left[2].get<long>() * left[3].get<long>();
    EXPECT_GT(paper, area / 2) << "the diagram's paper";
    EXPECT_GT(blue, 50) << "the mirror";
    EXPECT_GT(orange, 50) << "eye' and its frustum";
}

// The light's view keeps its aspect: the light's frustum is square, drawn square and centred
// (a 2:1 window drew the sphere twice as wide as high).
TEST(Window, LightViewKeepsItsAspect) {
    const std::string dir = tempDir("light-view");
    std::string output;
    const int code = runShadowlab(
        "window --stage margin --size 900x450 --frames 4 --keys vv "
        "--state " +
            dir + "/state.json --screenshot " + dir + "/light.png",
        &output);
    ASSERT_EQ(code, 0) << output;
    EXPECT_EQ(nlohmann::json::parse(readText(dir + "/state.json"))["view"], "light");
    Image shot;
    ASSERT_EQ(readPng(dir + "/light.png", shot), "");
    long outside = 0, inside = 0;
    for (int j = 0; j < shot.height; ++j)
        for (int i = 0; i < shot.width; ++i) {
            const bool scene = shot.luma(i, j) > 70;
            if (i < 225 - 2 || i >= 675 + 2)
                outside += scene;
            else
                inside += scene;
        }
    EXPECT_EQ(outside, 0) << "the light's view drawn outside its centred square";
    EXPECT_GT(inside, 450 * 450 / 10);
}
