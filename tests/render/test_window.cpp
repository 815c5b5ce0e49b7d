// A real freeglut window under Xvfb renders the same picture as the headless path.
#include <gtest/gtest.h>

#include "render_fixture.h"

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
    // The runner puts the command behind xvfb-run; see tests/CMakeLists.txt.
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

// Every key the window knows (but p, which saves into the working folder, and Esc) pressed in
// every stage: digits select the stage, then views, parameters, light, help and reload.
std::string keysForEveryStage() {
    std::string keys;
    for (char stage = '0'; stage <= '9'; ++stage) {
        keys += stage;
        keys += "vvvvv\t+\t-++--\t\t+lhlhr";
    }
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

// Key 6 (fixed) is legacy-only: the core window shows why and stays on the stage it had.
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
