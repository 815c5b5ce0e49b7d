// The window's words without a window: HUD wrapping, view names and legends, shot names.
#include <gtest/gtest.h>

#include <algorithm>

#include "render/hud.h"
#include "stages/registry.h"
#include "window/window_text.h"

using namespace sl;

namespace {
std::string joined(const std::vector<HudLine>& lines) {
    std::string all;
    for (const auto& l : lines) all += l.text;
    return all;
}
std::string withoutSpaces(std::string s) {
    s.erase(std::remove(s.begin(), s.end(), ' '), s.end());
    return s;
}
}  // namespace

TEST(HudText, WrapsAtSpacesAndKeepsEveryCharacter) {
    std::vector<HudLine> in = {{"the quick brown fox jumps over the lazy dog", {1, 0, 0, 1}}};
    auto out = wrapHudLines(in, 60);
    ASSERT_GT(out.size(), 2u);
    for (const auto& l : out) EXPECT_EQ(l.color, glm::vec4(1, 0, 0, 1));
    EXPECT_EQ(withoutSpaces(joined(out)), withoutSpaces(in[0].text));
    EXPECT_EQ(out[0].text, "the quick");
}

// A 16x16 window once made the wrap loop forever: every piece must take a character.
TEST(HudText, WrapEndsInATinyWindow) {
    std::vector<HudLine> in = {{"  indented words and averyveryverylongword", {}}};
    for (float width : {0.0f, 1.0f, 5.0f, 8.0f}) {
        auto out = wrapHudLines(in, width);
        EXPECT_LE(out.size(), in[0].text.size());
        EXPECT_EQ(withoutSpaces(joined(out)), withoutSpaces(in[0].text));
    }
}

TEST(HudText, ABlockSaysHowManyLinesDoNotFit) {
    HudBlock b;
    for (int k = 0; k < 10; ++k) b.lines.push_back({"line " + std::to_string(k), {}});
    b.maxLines = 4;
    auto out = layoutHudBlock(b, 1000);
    ASSERT_EQ(out.size(), 4u);
    EXPECT_EQ(out[2].text, "line 2");
    EXPECT_EQ(out[3].text, "(7 more lines)");
}

// A scrollable block pages by whole pages: every line is on exactly one page, each page says
// which it is of how many, and a first line inside a page shows that whole page.
TEST(HudText, ScrollableBlockPagesByWholePages) {
    HudBlock b;
    for (int k = 0; k < 17; ++k) b.lines.push_back({"line " + std::to_string(k), {}});
    b.scrollable = true;
    const int perPage = 5, pages = 4;  // 6 lines: 5 of the block and the page line
    std::vector<int> seen(b.lines.size(), 0);
    for (int page = 0; page < pages; ++page) {
        b.firstLine = page * perPage;
        auto out = layoutHudBlock(b, 1000, perPage + 1);
        ASSERT_GE(out.size(), 2u);
        EXPECT_EQ(
            out.back().text.rfind(
                "PgUp/PgDn: page " + std::to_string(page + 1) + " of " + std::to_string(pages), 0),
            0u)
            << out.back().text;
        for (std::size_t k = 0; k + 1 < out.size(); ++k) ++seen[std::stoul(out[k].text.substr(5))];
        b.firstLine = page * perPage + 3;  // inside the page: the same page
        EXPECT_EQ(layoutHudBlock(b, 1000, perPage + 1).front().text, out.front().text);
    }
    for (std::size_t k = 0; k < seen.size(); ++k) EXPECT_EQ(seen[k], 1) << "line " << k;
}

TEST(HudText, ScaleFollowsTheSmallerSide) {
    EXPECT_FLOAT_EQ(hudScale(320, 240), 1.2f);
    EXPECT_FLOAT_EQ(hudScale(1920, 1080), 5.4f);
    EXPECT_FLOAT_EQ(hudScale(400, 1080), hudScale(1080, 400));  // a tall narrow window too
}

TEST(WindowText, MirrorTextureViewIsNotCalledShadowMap) {
    const StageInfo* mirror = findStage("mirror");
    const StageInfo* hardware = findStage("hardware");
    ASSERT_TRUE(mirror && hardware);
    EXPECT_EQ(viewLabel(*mirror, ViewMode::ShadowMap), "mirror-texture");
    EXPECT_EQ(viewLabel(*hardware, ViewMode::ShadowMap), "shadow-map");
    for (ViewMode v : hardware->views)
        EXPECT_EQ(viewLegend(*hardware, v).empty(), v == ViewMode::Final) << viewName(v);
    EXPECT_NE(viewLegend(*hardware, ViewMode::Visibility).find("white = lit"), std::string::npos);
}

TEST(WindowText, ShotNameCarriesStageTreeViewAndTime) {
    std::string name = shotFileName("margin", "core", "visibility", 0, 42);
    EXPECT_EQ(name.rfind("margin-core-visibility-", 0), 0u) << name;
    EXPECT_EQ(name.substr(name.size() - 8), "-042.png") << name;
    EXPECT_EQ(name.size(), std::string("margin-core-visibility-YYYYmmdd-HHMMSS-mmm.png").size());
}

TEST(WindowText, HelpListsEveryKey) {
    std::string all;
    for (const auto& h : windowHelp()) all += h + "\n";
    for (const char* key :
         {"0-8", "[ ]", "g:", "Shift-Tab", "= -", "Shift", "x:", "c:", "v:",    "l:",    "drag",
          "r:",  "p:",  "i:", "h:",        "Esc", "n:",    "s:", "f:", "wheel", "arrows"})
        EXPECT_NE(all.find(key), std::string::npos) << key;
}

TEST(WindowText, OneLinePerEvent) {
    EXPECT_EQ(oneLine("a.frag: did not compile:\na.frag:3:1: error\n\n"),
              "a.frag: did not compile: | a.frag:3:1: error");
}

// The line a student reads first: the first that names a file and a line, its place first.
TEST(WindowText, FirstErrorLineNamesFileAndLine) {
    EXPECT_EQ(firstErrorLine("mine/margin/lit.frag: fragment shader did not compile:\n"
                             "mine/margin/lit.frag:21:38: error: syntax error, unexpected ';'\n"),
              "mine/margin/lit.frag:21:38: error: syntax error, unexpected ';'");
    EXPECT_EQ(firstErrorLine("ERROR: mine/x.frag:3: 'in' : not allowed"),
              "mine/x.frag:3: ERROR: 'in' : not allowed");
    EXPECT_EQ(firstErrorLine("mine/margin/lit.frag (changed): stage margin (core) in the trial "
                             "worker: no result within its time limit of 2 s of CPU time"),
              "mine/margin/lit.frag (changed): stage margin (core) in the trial worker: no result "
              "within its time limit of 2 s of CPU time");
    EXPECT_EQ(firstErrorLine(""), "");
}
