// Every glyph of the HUD's font, drawn by the HUD at a projector's text scale into a headless
// context, against its bitmap: the cells stb_easy_font's own quads cover (rasterised here on the
// CPU, from a buffer with room to spare). A screenshot test: a stroke missing or extra in any
// glyph, alone or at the end of a word, is a cell that differs.
#include <gtest/gtest.h>
#include <stb_easy_font.h>

#include <cmath>
#include <set>

#include "platform/headless.h"
#include "render/hud.h"
#include "stages/request.h"

using namespace sl;

namespace {

// The font's cells of `text` with its top-left corner at (0, 0), in the font's own pixels.
std::set<std::pair<int, int>> bitmapOf(const std::string& text) {
    std::vector<char> buffer(1 << 20);
    const int quads = stb_easy_font_print(0, 0, const_cast<char*>(text.c_str()), nullptr,
                                          buffer.data(), static_cast<int>(buffer.size()));
    std::set<std::pair<int, int>> cells;
    const float* v = reinterpret_cast<const float*>(buffer.data());
    for (int q = 0; q < quads; ++q) {  // 4 vertices of x, y, z, colour; corners 0 and 2
        const float* a = v + q * 16;
        const float* c = a + 8;
        for (int y = int(std::lround(a[1])); y < int(std::lround(c[1])); ++y)
            for (int x = int(std::lround(a[0])); x < int(std::lround(c[0])); ++x)
                cells.insert({x, y});
    }
    return cells;
}

struct Drawn {
    std::string text;
    float x, y;  // HUD pixels
};

// Draws each text with the HUD at `scale` on a black width x height frame, white; compares the
// pixel at the centre of every font cell around each (a margin of 2 cells) with its bitmap.
// Returns the texts that differ, with the cells.
std::vector<std::string> mismatches(const std::vector<Drawn>& texts, int width, int height,
                                    float scale) {
    auto context = createHeadlessContext(Backend::Auto, GlslTree::Core, width, height);
    ShaderLibrary shaders(GlslTree::Core, shaderTreeRoot(GlslTree::Core), "");
    Hud hud;
    glBindFramebuffer(GL_FRAMEBUFFER, context->framebuffer());
    glViewport(0, 0, width, height);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    for (const Drawn& d : texts)
        hud.drawLabel(shaders, {d.text, glm::vec4(1)}, d.x * scale, d.y * scale, width, height,
                      scale);
    glFinish();
    const Image image = context->read();
    std::vector<std::string> bad;
    for (const Drawn& d : texts) {
        const auto cells = bitmapOf(d.text);
        const int wide = stb_easy_font_width(const_cast<char*>(d.text.c_str()));
        std::string where;
        for (int y = -2; y < 12; ++y)
            for (int x = -2; x < wide + 2; ++x) {
                const int i = int((d.x + x + 0.5f) * scale), j = int((d.y + y + 0.5f) * scale);
                if (i < 0 || j < 0 || i >= width || j >= height) continue;
                const bool lit = image.luma(i, j) > 127.5f;
                if (lit != bool(cells.count({x, y})))
                    where += " (" + std::to_string(x) + "," + std::to_string(y) +
                             (lit ? " drawn" : " missing") + ")";
            }
        if (!where.empty()) bad.push_back("'" + d.text + "':" + where);
    }
    return bad;
}

}  // namespace

// Each printable character alone, at the scale of a 1920x1080 window's HUD (5.4 screen pixels a
// font pixel: a cell centre is never on a pixel edge).
TEST(HudGlyphs, EveryGlyphAtTheHudScaleIsItsBitmap) {
    const float scale = hudScale(1920, 1080);
    std::vector<Drawn> texts;
    for (int c = 33; c < 127; ++c) {
        const int k = c - 33;
        texts.push_back(
            {std::string(1, char(c)), float(4 + (k % 16) * 11), float(4 + (k / 16) * 15)});
    }
    const int width = int(std::ceil((4 + 16 * 11) * scale)),
              height = int(std::ceil((4 + 6 * 15) * scale));
    const auto bad = mismatches(texts, width, height, scale);
    for (const auto& b : bad) ADD_FAILURE() << b;
    EXPECT_TRUE(bad.empty()) << bad.size() << " of " << texts.size() << " glyphs differ";
}

// The words whose last letter was drawn wrong, and a line of text as the HUD shows one.
TEST(HudGlyphs, LastLetterOfAWordIsWhole) {
    const float scale = hudScale(1920, 1080);
    const std::vector<Drawn> texts = {{"averaged", 4, 4},
                                      {"saved", 4, 19},
                                      {"eye", 4, 34},
                                      {"p2", 44, 34},
                                      {"eye'", 74, 34},
                                      {"at'", 114, 34},
                                      {"lesson 3/7 (n): the specks are gone", 4, 49}};
    const int width = int(std::ceil(200 * scale)), height = int(std::ceil(64 * scale));
    const auto bad = mismatches(texts, width, height, scale);
    for (const auto& b : bad) ADD_FAILURE() << b;
}
