// The window on a projector, live under Xvfb with real X events: full screen at 1920x1080 with
// text tall enough to read from the back of a hall (measured on a screenshot of the window), and
// panels that never cover the picture: the rows between them are the whole picture, the same as
// the headless render at that size (the mirror's reflection at three sizes, the shadow-map view).
#include <gtest/gtest.h>

#include "render_fixture.h"

// Last: it includes Xlib, whose macros (None, Bool, Status...) would clash with gtest's headers.
#include "live_window.h"  // NOLINT(llvm-include-order)

using namespace sl;
using namespace sl::test;

namespace {

// The height in pixels of the first line of yellow HUD text above row `below`.
int firstTextLineHeight(const Image& img, int below) {
    int first = -1, last = -1;
    for (int j = 0; j < below && j < img.height; ++j) {
        bool yellow = false;
        for (int i = 0; i < img.width && !yellow; ++i) {
            const std::uint8_t* p = img.at(i, j);
            yellow = p[0] > 200 && p[1] > 200 && p[2] < 190;
        }
        if (yellow && first < 0) first = j;
        if (yellow) last = j;
        if (!yellow && first >= 0) break;
    }
    return first < 0 ? 0 : last - first + 1;
}

// The window from (left, top), request.width x request.height, against the headless picture: the
// same tolerance as the window-against-headless tests (mean under 1 level, under 0.5 % of the
// pixels off by more than 8).
void expectWholePicture(const Image& window, int left, int top, const RenderRequest& request,
                        const std::string& what) {
    Image headless = renderHeadless(request).image;
    ASSERT_LE(left + headless.width, window.width) << what;
    ASSERT_LE(top + headless.height, window.height) << what;
    long off = 0;
    double sum = 0;
    for (int j = 0; j < headless.height; ++j)
        for (int i = 0; i < headless.width; ++i) {
            int worst = 0;
            for (int k = 0; k < 3; ++k) {
                int d = std::abs(window.at(left + i, top + j)[k] - headless.at(i, j)[k]);
                worst = std::max(worst, d);
                sum += d;
            }
            off += worst > 8;
        }
    const long pixels = long(headless.width) * headless.height;
    EXPECT_LT(sum / (3.0 * pixels), 1.0) << what;
    EXPECT_LT(off, pixels / 200) << what << ": " << off << " pixels differ";
}

// Waits for a frame drawn at the given size (a new one unless the window has that size now);
// false if none comes.
bool frameAt(LiveWindow& w, int width, int height) {
    auto now = w.state();
    const bool already = now.value("width", 0) == width && now.value("height", 0) == height;
    const long drawn = already ? 0 : now.value("drawn", 0L);
    return w.waitState(
        [&](const auto& s) {
            return s["width"] == width && s["height"] == height && s["drawn"] > drawn;
        },
        30);
}

}  // namespace

// --fullscreen on a 1920x1080 screen: the window takes it all, the HUD's text is at least 3 % of
// the height (it was 2.3 %), `f` leaves full screen and comes back; --hud-scale scales the text.
TEST(LiveWindowProjector, FullScreenTextIsLegibleAt1920x1080) {
    std::string dir = tempDir("live-fullscreen");
    LiveWindow w("--fullscreen --state state.json", dir, true, "1920x1080");
    ASSERT_TRUE(w.ready()) << w.err();
    ASSERT_TRUE(
        w.waitState([](const auto& s) { return s["width"] == 1920 && s["height"] == 1080; }, 30))
        << w.state().dump();
    // No window manager places it: the window itself moves to 0,0 (freeglut left it at +1+1,
    // its last row and column off the screen), and back from `f` it stays on the screen.
    auto geometry = [&] { return w.capture("xdotool getwindowgeometry " + w.id()); };
    auto at = [&](const std::string& where) {
        return waitUntil([&] { return geometry().find("Position: " + where) != std::string::npos; },
                         10);
    };
    EXPECT_TRUE(at("0,0")) << geometry();
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    Image shot = w.grab();
    ASSERT_EQ(shot.width, 1920);
    ASSERT_EQ(shot.height, 1080);
    const int text = firstTextLineHeight(shot, w.state()["pictureTop"]);
    std::cout << "text height at 1920x1080: " << text << " px (" << 100.0 * text / 1080
              << " % of the height)\n";
    EXPECT_GE(text, 0.03 * 1080) << "text height in pixels";
    ASSERT_TRUE(w.keys("f"));
    EXPECT_TRUE(w.waitState([](const auto& s) { return s["width"] == 640; }, 15))
        << w.state().dump();
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    EXPECT_EQ(geometry().find("Position: -"), std::string::npos) << geometry();
    ASSERT_TRUE(w.keys("f"));
    EXPECT_TRUE(w.waitState([](const auto& s) { return s["width"] == 1920; }, 15))
        << w.state().dump();
    EXPECT_TRUE(at("0,0")) << geometry();
    EXPECT_EQ(w.quit(), 0);

    std::string dir2 = tempDir("live-hud-scale");
    LiveWindow half("--fullscreen --hud-scale 0.5 --state state.json", dir2, true, "1920x1080");
    ASSERT_TRUE(half.ready()) << half.err();
    ASSERT_TRUE(half.waitState([](const auto& s) { return s["width"] == 1920; }, 30));
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    const int halfText = firstTextLineHeight(half.grab(), half.state()["pictureTop"]);
    EXPECT_NEAR(halfText, text / 2.0, 2) << "--hud-scale 0.5";
    EXPECT_EQ(half.quit(), 0);
}

// The default HUD over the mirror stage at 1024x768, 1280x720 and 1920x1080 (the window resized
// with xdotool), then the hardware stage's shadow-map view: between the panels the window shows
// the whole picture, reflection included, exactly as rendered headless at that size.
TEST(LiveWindowProjector, PanelsNeverCoverThePicture) {
    std::string dir = tempDir("live-uncovered");
    LiveWindow w("--stage mirror --state state.json --size 1024x768", dir, true, "1920x1080");
    ASSERT_TRUE(w.ready()) << w.err();
    ASSERT_TRUE(w.waitState([](const auto& s) { return s["stage"] == "mirror"; }, 30));
    // With no window manager the window sits at -1,-1 (its border): all of it on the screen.
    ASSERT_EQ(w.xdo("windowmove " + w.id() + " 0 0"), 0);
    for (auto [width, height] : {std::pair{1024, 768}, {1280, 720}, {1920, 1080}}) {
        ASSERT_EQ(w.xdo("windowsize " + w.id() + " " + std::to_string(width) + " " +
                        std::to_string(height)),
                  0);
        ASSERT_TRUE(frameAt(w, width, height)) << width << "x" << height;
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        auto s = w.state();
        const int top = s["pictureTop"], pictureHeight = s["pictureHeight"];
        EXPECT_GT(top, 0) << "the compact HUD takes a band at the top";
        RenderRequest r;
        r.stage = "mirror";
        r.width = width;
        r.height = pictureHeight;
        expectWholePicture(w.grab(), 0, top, r, "mirror at " + std::to_string(width));
    }
    ASSERT_EQ(w.xdo("windowsize " + w.id() + " 1024 768"), 0);
    ASSERT_TRUE(frameAt(w, 1024, 768));
    ASSERT_TRUE(w.keys("5 v"));
    ASSERT_TRUE(w.waitState(
        [](const auto& s) { return s["stage"] == "hardware" && s["view"] == "shadow-map"; }, 30))
        << w.state().dump();
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    auto s = w.state();
    const int top = s["pictureTop"], pictureHeight = s["pictureHeight"];
    EXPECT_LT(top + pictureHeight, 768) << "the view's legend takes a band at the bottom";
    RenderRequest r;
    r.stage = "hardware";
    r.view = ViewMode::ShadowMap;
    r.width = 1024;
    r.height = pictureHeight;
    expectWholePicture(w.grab(), 0, top, r, "hardware shadow-map view");
    EXPECT_EQ(w.quit(), 0);
}

// `n` steps through the stage's lessons with real key presses: the bias stage's -0.5 and flipped
// light, the hardware stage's lab scene with its polygon offsets, the lecture's figures after
// the entries; the HUD names each and says what to look for.
TEST(LiveWindowProjector, LessonKeyAppliesEachLesson) {
    std::string dir = tempDir("live-lessons");
    LiveWindow w("--stage bias --state state.json --size 640x480", dir);
    ASSERT_TRUE(w.ready()) << w.err();
    ASSERT_TRUE(w.waitState([](const auto& s) { return s["stage"] == "bias"; }, 30));
    auto lesson = [&](const std::string& fragment) {
        return w.waitState(
            [&](const auto& s) {
                return s["lesson"].template get<std::string>().find(fragment) != std::string::npos;
            },
            15);
    };
    EXPECT_TRUE(lesson("lesson 1/")) << w.state().dump();
    EXPECT_NE(w.state()["lesson"].get<std::string>().find("Look for: "), std::string::npos);
    ASSERT_TRUE(w.keys("n"));
    ASSERT_TRUE(lesson("light-z=flipped")) << w.state().dump();
    EXPECT_EQ(w.state()["params"]["light-z"], "flipped");
    ASSERT_TRUE(w.keys("n"));
    ASSERT_TRUE(lesson("bias-z=+0.5")) << w.state().dump();
    auto s = w.state();
    EXPECT_EQ(s["params"]["light-z"], "standard") << "each lesson starts from the defaults";
    EXPECT_EQ(s["params"]["bias-z"], "+0.5");
    ASSERT_TRUE(w.keys("n"));
    ASSERT_TRUE(lesson("figure bias-inverted")) << w.state().dump();
    // The hardware stage: the lab scene comes with its lessons, and goes with the stage.
    ASSERT_TRUE(w.keys("5 n n"));
    ASSERT_TRUE(lesson("offset-factor=0 offset-units=6: acne")) << w.state().dump();
    s = w.state();
    EXPECT_EQ(s["scene"], "lab");
    EXPECT_EQ(s["params"]["offset-factor"], "0");
    ASSERT_TRUE(w.keys("4"));
    ASSERT_TRUE(w.waitState([](const auto& s) { return s["stage"] == "margin"; }, 15));
    EXPECT_EQ(w.state()["scene"], "slides");
    EXPECT_EQ(w.quit(), 0);
}

// The picture holds still: in every stage, from lesson to lesson (`n`, real key presses at
// 1280x720), after a value that is no lesson (`=`) and with a message on screen (`c`), the
// picture's rectangle is the same; only the window's size and the HUD's mode change it.
TEST(LiveWindowProjector, PictureHoldsStillAcrossAStagesLessons) {
    std::string dir = tempDir("live-still");
    LiveWindow w("--stage phong --state state.json --size 1280x720", dir, true, "1920x1080");
    ASSERT_TRUE(w.ready()) << w.err();
    ASSERT_TRUE(w.waitState([](const auto& s) { return s["drawn"] > 0; }, 30));
    // Presses `key`, then waits for a frame drawn since that shows what `ok` asks for.
    auto press = [&](const std::string& key, const std::function<bool(const nlohmann::json&)>& ok) {
        const long drawn = w.state().value("drawn", 0L);
        return w.keys(key) &&
               w.waitState([&](const auto& s) { return s["drawn"] > drawn && ok(s); }, 20);
    };
    const auto first = w.state()["stage"];
    int stages = 0, compared = 0;
    do {
        auto s = w.state();
        const std::string stage = s["stage"], label = s["lesson"];
        const nlohmann::json rect = s["pictureRect"];
        // "lesson 1/N (n): ...": N from the stage's own data
        const std::size_t slash = label.find('/');
        const int lessons = label.rfind("lesson ", 0) == 0 ? std::stoi(label.substr(slash + 1)) : 0;
        for (int k = 2; k <= lessons; ++k) {
            const std::string want = "lesson " + std::to_string(k) + "/";
            ASSERT_TRUE(press("n",
                              [&](const auto& t) {
                                  return t["lesson"].template get<std::string>().rfind(want, 0) ==
                                         0;
                              }))
                << stage << " " << want << w.state().dump();
            EXPECT_EQ(w.state()["pictureRect"], rect) << stage << " " << w.state()["lesson"];
            ++compared;
        }
        if (w.state()["param"] != "") {  // a value no lesson has
            ASSERT_TRUE(press("equal", [](const auto&) { return true; }));
            EXPECT_EQ(w.state()["pictureRect"], rect) << stage << " " << w.state()["lesson"];
        }
        // a message on screen
        ASSERT_TRUE(press("c", [](const auto& t) { return t["message"] != ""; }))
            << w.state().dump();
        EXPECT_EQ(w.state()["pictureRect"], rect) << stage << " with a message";
        ASSERT_TRUE(press("bracketright", [&](const auto& t) { return t["stage"] != stage; }));
        ++stages;
    } while (w.state()["stage"] != first && stages < 20);
    std::cout << compared << " lessons compared in " << stages << " stages\n";
    EXPECT_GE(compared, 20);
    EXPECT_EQ(w.quit(), 0);
}

// `s` splits the window: the lesson's failure on the left (bias: -0.5 inverts the shadows), its
// fix on the right (the flipped light), same camera and light, each labelled, each half the
// same picture as the headless render of its settings at that size; the mirror's split is its
// texture and stencil methods.
TEST(LiveWindowProjector, SplitShowsFailureBesideFix) {
    std::string dir = tempDir("live-split");
    LiveWindow w("--stage bias --state state.json --size 1024x576", dir);
    ASSERT_TRUE(w.ready()) << w.err();
    ASSERT_EQ(w.xdo("windowmove " + w.id() + " 0 0"), 0);
    ASSERT_TRUE(w.waitState([](const auto& s) { return s["stage"] == "bias"; }, 30));
    ASSERT_TRUE(w.keys("s"));
    ASSERT_TRUE(w.waitState([](const auto& s) { return s["split"].size() == 2; }, 15))
        << w.state().dump();
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    auto s = w.state();
    EXPECT_EQ(s["split"][0], "bias: inverted");
    EXPECT_EQ(s["split"][1], "bias light-z=flipped: correct");
    const int top = s["pictureTop"], height = s["pictureHeight"];
    Image shot = w.grab();
    RenderRequest r;
    r.stage = "bias";
    r.width = 512;
    r.height = height;
    // A half narrower than 4:3 (the scenes' cameras are framed for it) widens its field of view
    // so that the scene's width fits: the slides' 45 degrees, so widened.
    const float aspect = 512.0f / float(height);
    if (aspect < 4.0f / 3.0f)
        r.fovy =
            glm::degrees(2 * std::atan(std::tan(glm::radians(45.0f) / 2) * (4.0f / 3.0f) / aspect));
    expectWholePicture(shot, 0, top, r, "left half: bias defaults");
    r.sets = {{"light-z", "flipped"}};
    expectWholePicture(shot, 512, top, r, "right half: the flipped light");
    ASSERT_TRUE(w.keys("7"));
    ASSERT_TRUE(w.waitState(
        [](const auto& s) { return s["stage"] == "mirror" && s["split"].size() == 2; }, 15))
        << w.state().dump();
    EXPECT_EQ(w.state()["split"][1], "mirror-method=stencil");
    ASSERT_TRUE(w.keys("s"));
    EXPECT_TRUE(w.waitState([](const auto& s) { return s["split"].empty(); }, 15));
    EXPECT_EQ(w.quit(), 0);
}

// The small keys, pressed for real: arrows orbit, the mouse wheel zooms (over the window), `v`
// in the one-view fixed stage says so, `r` says on screen that it is trying and then that the
// shaders reloaded, and Esc closes the window fast.
TEST(LiveWindowProjector, ArrowsWheelAndConfirmations) {
    std::string dir = tempDir("live-keys");
    LiveWindow w("--state state.json --size 640x480", dir);
    ASSERT_TRUE(w.ready()) << w.err();
    ASSERT_TRUE(w.waitState([](const auto& s) { return s["drawn"] > 0; }, 30));
    const auto eye = w.state()["eye"];
    const double distance = w.state()["eyeDistance"];
    ASSERT_TRUE(w.keys("Left Up"));
    EXPECT_TRUE(w.waitState([&](const auto& s) { return s["eye"] != eye; }, 10));
    EXPECT_NEAR(w.state()["eyeDistance"].get<double>(), distance, 1e-3) << "orbit keeps distance";
    EXPECT_TRUE(w.waitState([&](const auto& s) { return s["keys"]["received"] >= 2; }, 10));
    EXPECT_GT(w.state()["eye"][1].get<double>(), eye[1].get<double>() + 0.01)
        << "Up raises the camera";
    // A drag across the window's width turns the camera about half a turn around its target.
    ASSERT_TRUE(w.keys("c"));
    ASSERT_TRUE(w.waitState([&](const auto& s) { return s["eye"] == eye; }, 10));
    ASSERT_EQ(w.xdo("mousemove --window " + w.id() + " 10 240 mousedown 1 mousemove --window " +
                    w.id() + " 330 240 mousemove --window " + w.id() + " 630 240 mouseup 1"),
              0);
    ASSERT_TRUE(w.waitState([&](const auto& s) { return s["eye"] != eye; }, 10));
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    auto yaw = [](const nlohmann::json& s) {
        return std::atan2(s["eye"][0].get<double>() - s["at"][0].get<double>(),
                          s["eye"][2].get<double>() - s["at"][2].get<double>());
    };
    double turned =
        std::abs(yaw(w.state()) - yaw(nlohmann::json{{"eye", eye}, {"at", w.state()["at"]}}));
    if (turned > M_PI) turned = 2 * M_PI - turned;
    std::cout << "a drag of 620 of 640 pixels turned " << turned * 180 / M_PI << " degrees\n";
    EXPECT_NEAR(turned * 180 / M_PI, 620.0 / 640 * 180, 15) << w.state().dump();
    // Orbiting down stops above the floor's top (y = 0), not its bottom (-0.1).
    std::string down;
    for (int k = 0; k < 40; ++k) down += " Down";
    ASSERT_TRUE(w.keys(down));
    EXPECT_TRUE(w.waitState([&](const auto& s) { return s["keys"]["received"] >= 43; }, 30));
    EXPECT_GE(w.state()["eye"][1].get<double>(), 0.05 - 1e-3) << w.state().dump();
    ASSERT_TRUE(w.keys("c"));
    ASSERT_TRUE(w.waitState([&](const auto& s) { return s["eye"] == eye; }, 10));
    ASSERT_EQ(w.xdo("mousemove --window " + w.id() + " 300 200"), 0);
    ASSERT_EQ(w.xdo("click 4"), 0);  // the wheel up: closer
    EXPECT_TRUE(w.waitState(
        [&](const auto& s) {
            return std::abs(s["eyeDistance"].template get<double>() - 0.9 * distance) < 1e-3;
        },
        10))
        << w.state().dump();
    ASSERT_TRUE(w.keys("6 v"));
    EXPECT_TRUE(w.waitState(
        [](const auto& s) {
            return s["message"].template get<std::string>().find("has one view") !=
                   std::string::npos;
        },
        10))
        << w.state().dump();
    ASSERT_TRUE(w.keys("0 r"));
    EXPECT_TRUE(w.waitState(
        [](const auto& s) {
            return s["message"].template get<std::string>().rfind("shaders reloaded", 0) == 0;
        },
        30))
        << w.state().dump();
    auto escape = Clock::now();
    EXPECT_EQ(w.quit(), 0);
    const double closing = std::chrono::duration<double>(Clock::now() - escape).count();
    std::cout << "Esc to exit: " << closing << " s\n";
    EXPECT_LT(closing, 1.0);
}

// Honest HUD: a student's margin shader that returns 0.01 instead of reading `margin` gets the
// parameter marked on screen (it changes nothing); ours reads every parameter, nothing marked.
TEST(LiveWindowProjector, ParameterTheShaderDoesNotReadIsMarked) {
    std::string dir = tempDir("live-ignored");
    fs::create_directories(dir + "/mine/margin");
    std::string text =
        readText(std::string(SHADOWLAB_SOURCE_DIR) + "/shaders_core/margin/lit.frag");
    const std::string uses = "return margin;";
    ASSERT_NE(text.find(uses), std::string::npos);
    text.replace(text.find(uses), uses.size(), "return 0.01;");
    std::ofstream(dir + "/mine/margin/lit.frag") << text;
    LiveWindow w("--shaders mine --stage margin --state state.json --size 640x480", dir);
    ASSERT_TRUE(w.ready()) << w.err();
    ASSERT_TRUE(w.waitState([](const auto& s) { return s["picture"] == "stage"; }, 30));
    ASSERT_TRUE(w.keys("Tab"));  // a redraw after the first frame's notes
    EXPECT_TRUE(w.waitState(
        [](const auto& s) {
            return s.contains("ignored") && s["ignored"].size() == 1 && s["ignored"][0] == "margin";
        },
        15))
        << w.state().dump();
    ASSERT_TRUE(w.keys("g"));  // the legacy tree: ours, every parameter read
    EXPECT_TRUE(w.waitState(
        [](const auto& s) { return s["tree"] == "legacy" && !s.contains("ignored"); }, 15))
        << w.state().dump();
    EXPECT_EQ(w.quit(), 0);
}

// The mirror's top view on a projector: full screen at 1920x1080, `n` brings the slides'
// exercise from above; on the screen's pixels each label's ink is as tall as the HUD's text
// (they were 0.6 of it), on its own patch of paper inside the figure's half, none over another.
TEST(LiveWindowProjector, TopViewLabelsAtTheHudsTextSize) {
    std::string dir = tempDir("live-top-view");
    LiveWindow w("--fullscreen --stage mirror --state state.json", dir, true, "1920x1080");
    ASSERT_TRUE(w.ready()) << w.err();
    ASSERT_TRUE(w.waitState([](const auto& s) { return s["width"] == 1920; }, 30));
    ASSERT_TRUE(w.keys("n"));
    ASSERT_TRUE(w.waitState(
        [](const auto& s) {
            return s["halvesShow"] == nlohmann::json({"top-view", "stage"}) &&
                   s["topViewLabels"].size() == 6;
        },
        30))
        << w.state().dump();
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    const Image shot = w.grab();
    const auto state = w.state();
    ASSERT_EQ(shot.width, 1920);
    const int hud = firstTextLineHeight(shot, state["pictureTop"]);
    ASSERT_GE(hud, 0.03 * 1080) << "the HUD's text height";
    const auto half = state["halves"][0];
    std::vector<std::array<int, 4>> boxes;
    int tallest = 0;
    for (const auto& label : state["topViewLabels"]) {
        const std::string text = label["text"];
        EXPECT_EQ(label["shown"], text) << "whole, not a key";
        const auto b = label["box"];
        const std::array<int, 4> box = {int(std::ceil(b[0].get<float>())),
                                        int(std::ceil(b[1].get<float>())), int(b[2].get<float>()),
                                        int(b[3].get<float>())};
        EXPECT_TRUE(box[0] >= half[0] && box[1] >= half[1] &&
                    box[0] + box[2] <= half[0].get<int>() + half[2].get<int>() &&
                    box[1] + box[3] <= half[1].get<int>() + half[3].get<int>())
            << text << " inside the top view's half";
        for (const auto& other : boxes)
            EXPECT_FALSE(box[0] < other[0] + other[2] && other[0] < box[0] + box[2] &&
                         box[1] < other[1] + other[3] && other[1] < box[1] + box[3])
                << text << " overlaps another label";
        boxes.push_back(box);
        // The rows with ink (anything darker than the paper) inside the label's box.
        int first = -1, last = -1;
        for (int j = box[1]; j < box[1] + box[3] && j < shot.height; ++j)
            for (int i = box[0]; i < box[0] + box[2] && i < shot.width; ++i) {
                const std::uint8_t* p = shot.at(i, j);
                if (std::min({p[0], p[1], p[2]}) < 150) {
                    if (first < 0) first = j;
                    last = j;
                    break;
                }
            }
        const int ink = first < 0 ? 0 : last - first + 1;
        std::cout << text << ": " << ink << " px of ink (the HUD's text: " << hud << " px)\n";
        // Glyphs without a descender or an ascender ("eye", "at") take 7 of the line's 9 rows.
        EXPECT_GE(ink, hud * 7 / 9 - 1) << text;
        EXPECT_LE(ink, hud + 1) << text;
        tallest = std::max(tallest, ink);
    }
    EXPECT_NEAR(tallest, hud, 1) << "p1, p2 and eye' span the whole line, as the HUD's text does";
    EXPECT_EQ(w.quit(), 0);
}
