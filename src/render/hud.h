// On-screen text for the window (stage, parameters, notes, legends, errors), drawn with
// stb_easy_font's quads on translucent panels so it stays readable over any picture, and the
// lines of a diagram (the mirror seen from above).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "gl/shader_library.h"

namespace sl {

struct HudLine {
    std::string text;
    glm::vec4 color{1.0f};
};

// Lines drawn together on one panel, from the top-left corner or up from the bottom-left.
struct HudBlock {
    std::vector<HudLine> lines;
    bool bottom = false;
    // Wrapped lines beyond this (or beyond the room the panels have) are cut: the last line
    // shown says how many more there are (`more`, with "N" for the count, else "(N more
    // lines)"); a scrollable block shows the whole page that holds line `firstLine` and says
    // which page of how many shows instead.
    int maxLines = 0;   // 0: as many as there is room for
    int keepLines = 1;  // lines it gets before the blocks after it get more than theirs
    std::string more;
    bool scrollable = false;
    int firstLine = 0;
    glm::vec4 panel{0.0f, 0.0f, 0.0f, 0.78f};  // white text stays readable on a white view
    // The split view's halves: 0 from the left edge, 1 from the middle; `half`: wrapped to half
    // the window (column 1 always is).
    int column = 0;
    bool half = false;
};

// Text size for a width x height window: from its smaller side, so a projector's 1080 lines
// get large text and a 320x240 window small text; at least 1.
float hudScale(int width, int height);

// The width of `text` in stb_easy_font's unscaled pixels.
float hudTextWidth(const std::string& text);

// Splits lines wider than `maxPixels` (stb_easy_font's unscaled pixels) at spaces (or anywhere
// in a word longer than a line). Colours carry over to the pieces.
std::vector<HudLine> wrapHudLines(const std::vector<HudLine>& lines, float maxPixels);

// Wraps a block's lines for `maxPixels` and cuts them to `maxLines` (the block's own when 0),
// the last line saying how many more there are or, scrollable, which ones show.
std::vector<HudLine> layoutHudBlock(const HudBlock& block, float maxPixels, int maxLines = 0);

// The most of the window's height the top and the bottom panels may take together, each side.
struct HudRoom {
    float top = 1, bottom = 1;
};

// Where a block's panel goes, in the HUD's unscaled pixels (y down from the top).
struct HudPanel {
    std::vector<HudLine> lines;
    float x = 0, y = 0, width = 0, height = 0;
    bool bottom = false;
    glm::vec4 color{0.0f};
    int wrappedLines = 0;  // before the cut
    int pageLines = 0;     // a scrollable block's lines a page (0: it shows whole)
};
constexpr float kHudMargin = 3;  // between panels and from the window's edge

// The panels of `blocks` on a width x height window: top blocks downward, bottom ones upward,
// each side within its room: every block gets its keepLines first, in order, then the lines it
// wants, in order (a block with no room left is left out).
std::vector<HudPanel> layoutHud(const std::vector<HudBlock>& blocks, int width, int height,
                                float scale, HudRoom room = {});
// The window pixels the panels take at the top and at the bottom (margins included): the window
// draws the picture between them, so that no panel covers it.
std::pair<int, int> hudBands(const std::vector<HudPanel>& panels, int height, float scale);

class Hud {
  public:
    Hud();
    // Draws the panels on a width x height viewport (top blocks downward, bottom ones upward).
    void draw(ShaderLibrary& shaders, const std::vector<HudPanel>& panels, int width, int height,
              float scale);
    // Lines from a[k] to b[k] (pixels of the width x height viewport, y down) in `color`.
    void drawLines(ShaderLibrary& shaders, const std::vector<glm::vec2>& ends,
                   const glm::vec4& color, int width, int height);
    // Filled rectangles (x0, y0, x1, y1 in pixels of the width x height viewport, y down).
    void drawBoxes(ShaderLibrary& shaders, const std::vector<glm::vec4>& boxes,
                   const glm::vec4& color, int width, int height);
    // One line of text with its top-left corner at (x, y) (viewport pixels, y down).
    void drawLabel(ShaderLibrary& shaders, const HudLine& line, float x, float y, int width,
                   int height, float scale);

    static constexpr float kLineHeight = 11;  // stb_easy_font's glyphs are 7 high, plus spacing
    static constexpr float kGlyphRows = 9;    // the rows a line's ink takes, descenders included
    static constexpr float kPad = 4;

  private:
    Program& begin(ShaderLibrary& shaders, float w, float h);
    void end();
    void drawRect(Program& program, float x0, float y0, float x1, float y1, const glm::vec4& color);
    void drawText(Program& program, const HudLine& line, float x, float y);
    int printQuads(const std::string& text, float x, float y);  // into quads_: every quad
    VertexArray vao_;
    Buffer buffer_;
    std::vector<char> quads_;
    std::vector<float> triangles_;
};

}  // namespace sl
