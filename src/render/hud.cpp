#include "render/hud.h"

#include <stb_easy_font.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "gl/state.h"

namespace sl {

float hudTextWidth(const std::string& s) {
    return static_cast<float>(stb_easy_font_width(const_cast<char*>(s.c_str())));
}

float hudScale(int width, int height) {
    // 200 rows of HUD pixels on the smaller side: 7-pixel glyphs are 3.5 % of a projected
    // 1080-line picture (they were 2 %, unreadable from the back of a lecture hall).
    return std::clamp(std::min(width, height) / 200.0f, 1.0f, 8.0f);
}

std::vector<HudLine> wrapHudLines(const std::vector<HudLine>& lines, float maxPixels) {
    std::vector<HudLine> out;
    for (const HudLine& line : lines) {
        std::string rest = line.text;
        // Every piece takes at least one character, so this ends even in a 1-pixel window.
        while (hudTextWidth(rest) > maxPixels && rest.size() > 1) {
            // The longest prefix that fits, ended at a space when there is one.
            std::size_t fit = 1;
            while (fit < rest.size() && hudTextWidth(rest.substr(0, fit + 1)) <= maxPixels) ++fit;
            std::size_t cut = rest.rfind(' ', fit);
            if (cut == std::string::npos || cut == 0) cut = fit;
            out.push_back({rest.substr(0, cut), line.color});
            std::size_t start = rest.find_first_not_of(' ', cut);
            rest = start == std::string::npos ? "" : rest.substr(start);
        }
        if (!rest.empty() || line.text.empty()) out.push_back({rest, line.color});
    }
    return out;
}

std::vector<HudLine> layoutHudBlock(const HudBlock& block, float maxPixels, int maxLines) {
    std::vector<HudLine> lines = wrapHudLines(block.lines, maxPixels);
    const int most = maxLines > 0 ? maxLines : block.maxLines;
    const int total = static_cast<int>(lines.size());
    if (most <= 0 || total <= most) return lines;
    if (most == 1) return {lines.front()};  // a count alone would say nothing
    const int keep = most - 1;
    if (block.scrollable) {  // whole pages of `keep` lines (the last one shorter): every line
                             // is on one page, and the last line says which page shows
        const int pages = (total + keep - 1) / keep;
        const int page = std::clamp(block.firstLine / keep, 0, pages - 1);
        const int first = page * keep, end = std::min(total, first + keep);
        std::vector<HudLine> shown(lines.begin() + first, lines.begin() + end);
        shown.push_back({"PgUp/PgDn: page " + std::to_string(page + 1) + " of " +
                             std::to_string(pages) + " (lines " + std::to_string(first + 1) + "-" +
                             std::to_string(end) + " of " + std::to_string(total) + ")",
                         glm::vec4(0.85f, 0.85f, 0.85f, 1)});
        return shown;
    }
    const std::size_t more = static_cast<std::size_t>(total - keep);
    glm::vec4 colour = lines[std::size_t(keep)].color;
    lines.resize(std::size_t(keep));
    std::string text = block.more.empty() ? "(N more lines)" : block.more;
    const std::size_t n = text.find('N');
    if (n != std::string::npos) text.replace(n, 1, std::to_string(more));
    lines.push_back({text, colour});
    return lines;
}

Hud::Hud() : vao_(VertexArray::create()), buffer_(Buffer::create()) {}

void Hud::drawRect(Program& program, float x0, float y0, float x1, float y1,
                   const glm::vec4& color) {
    const float v[] = {x0, y0, 0, 0, x1, y0, 0, 0, x1, y1, 0, 0,
                       x0, y0, 0, 0, x1, y1, 0, 0, x0, y1, 0, 0};
    glBufferData(GL_ARRAY_BUFFER, sizeof v, v, GL_STREAM_DRAW);
    program.set("textColor", color);
    glDrawArrays(GL_TRIANGLES, 0, 6);
}

// stb_easy_font drops the quads that do not fit in the buffer it is given, without a word: a
// glyph has up to 11 (X), so a fixed guess per character cut the last letter of words full of
// many-stroked ones ("averaged" drawn "averagec"). A quad is 64 bytes; when the buffer keeps
// one quad's room free, none was dropped.
int Hud::printQuads(const std::string& text, float x, float y) {
    constexpr std::size_t kQuadBytes = 64;
    std::size_t bytes = (text.size() * 4 + 1) * kQuadBytes;
    for (;;) {
        quads_.assign(bytes, 0);
        const int n = stb_easy_font_print(x, y, const_cast<char*>(text.c_str()), nullptr,
                                          quads_.data(), static_cast<int>(bytes));
        if ((std::size_t(n) + 1) * kQuadBytes <= bytes) return n;
        bytes *= 2;
    }
}

void Hud::drawText(Program& program, const HudLine& line, float x, float y) {
    const int n = printQuads(line.text, x, y);
    triangles_.clear();
    const float* v = reinterpret_cast<const float*>(quads_.data());
    for (int q = 0; q < n; ++q)  // each quad -> two triangles (core profiles have no quads)
        for (int k : {0, 1, 2, 0, 2, 3}) {
            const float* p = v + (q * 4 + k) * 4;
            triangles_.insert(triangles_.end(), {p[0], p[1], p[2], 0.0f});
        }
    if (triangles_.empty()) return;
    glBufferData(GL_ARRAY_BUFFER, triangles_.size() * sizeof(float), triangles_.data(),
                 GL_STREAM_DRAW);
    program.set("textColor", line.color);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(triangles_.size() / 4));
}

std::vector<HudPanel> layoutHud(const std::vector<HudBlock>& blocks, int width, int height,
                                float scale, HudRoom room) {
    std::vector<HudPanel> panels;
    if (width <= 0 || height <= 0) return panels;
    const float w = width / scale, h = height / scale;      // the HUD's own (unscaled) pixels
    const float overhead = 2 * Hud::kPad - 3 + kHudMargin;  // a panel's own pixels
    // Each side (top, bottom) of each column has room for so many lines: every block first
    // gets its keepLines, in order, then what more it wants, in order.
    std::vector<int> wanted(blocks.size()), given(blocks.size(), 0);
    std::vector<std::vector<HudLine>> wrapped(blocks.size());
    for (std::size_t k = 0; k < blocks.size(); ++k) {
        const HudBlock& b = blocks[k];
        const float span = b.column == 1 || b.half ? w / 2 : w;
        wrapped[k] = wrapHudLines(b.lines, std::max(span - 2 * (kHudMargin + Hud::kPad), 8.0f));
        wanted[k] = static_cast<int>(wrapped[k].size());
        if (b.maxLines > 0) wanted[k] = std::min(wanted[k], b.maxLines);
    }
    for (int side = 0; side < 4; ++side) {
        const bool bottom = side >= 2;
        const int column = side % 2;
        float left = (bottom ? h * room.bottom : h * room.top) - kHudMargin;
        std::vector<std::size_t> here;
        for (std::size_t k = 0; k < blocks.size(); ++k)
            if (blocks[k].bottom == bottom && (blocks[k].column == 1 ? 1 : 0) == column &&
                wanted[k] > 0)
                here.push_back(k);
        for (int pass = 0; pass < 2; ++pass)
            for (std::size_t k : here) {
                const int goal =
                    pass == 0 ? std::min(wanted[k], std::max(1, blocks[k].keepLines)) : wanted[k];
                const float cost = given[k] == 0 ? overhead : 0;
                const int fit = static_cast<int>((left - cost) / Hud::kLineHeight);
                const int more = std::min(goal - given[k], fit);
                if (more <= 0) continue;
                left -= cost + more * Hud::kLineHeight;
                given[k] += more;
            }
    }
    float top[2] = {kHudMargin, kHudMargin}, bottom[2] = {h - kHudMargin, h - kHudMargin};
    for (std::size_t k = 0; k < blocks.size(); ++k) {
        if (given[k] <= 0) continue;  // no room left for it
        const HudBlock& block = blocks[k];
        const int c = block.column == 1 ? 1 : 0;
        const float span = c == 1 || block.half ? w / 2 : w;
        HudPanel p;
        p.wrappedLines = static_cast<int>(wrapped[k].size());
        p.lines =
            layoutHudBlock(block, std::max(span - 2 * (kHudMargin + Hud::kPad), 8.0f), given[k]);
        if (block.scrollable && p.wrappedLines > given[k] && given[k] > 1)
            p.pageLines = given[k] - 1;  // the last line says which page shows
        p.x = c * w / 2 + kHudMargin;
        p.width = 0;
        for (const auto& l : p.lines)
            p.width = std::max(p.width, hudTextWidth(l.text) + 2 * Hud::kPad);
        p.height = p.lines.size() * Hud::kLineHeight + 2 * Hud::kPad - 3;
        p.y = block.bottom ? bottom[c] - p.height : top[c];
        p.bottom = block.bottom;
        p.color = block.panel;
        if (block.bottom)
            bottom[c] = p.y - kHudMargin;
        else
            top[c] = p.y + p.height + kHudMargin;
        panels.push_back(std::move(p));
    }
    return panels;
}

std::pair<int, int> hudBands(const std::vector<HudPanel>& panels, int height, float scale) {
    float top = 0, bottom = 0;
    const float h = height / scale;
    for (const HudPanel& p : panels) {
        if (p.bottom)
            bottom = std::max(bottom, h - p.y + kHudMargin);
        else
            top = std::max(top, p.y + p.height + kHudMargin);
    }
    return {static_cast<int>(std::ceil(top * scale)), static_cast<int>(std::ceil(bottom * scale))};
}

Program& Hud::begin(ShaderLibrary& shaders, float w, float h) {
    Program& program = shaders.program("hud", "text");
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    program.use();
    program.set("projection", glm::ortho(0.0f, w, h, 0.0f));
    glBindVertexArray(vao_.id());
    glBindBuffer(GL_ARRAY_BUFFER, buffer_.id());
    glEnableVertexAttribArray(kPositionAttribute);
    // stb_easy_font writes 16-byte vertices: x, y, z as floats, then 4 colour bytes.
    glVertexAttribPointer(kPositionAttribute, 3, GL_FLOAT, GL_FALSE, 16, nullptr);
    return program;
}

void Hud::end() {
    glDisableVertexAttribArray(kPositionAttribute);
    glBindVertexArray(0);
}

void Hud::draw(ShaderLibrary& shaders, const std::vector<HudPanel>& panels, int width, int height,
               float scale) {
    if (width <= 0 || height <= 0 || panels.empty()) return;
    ScopedEnable noDepth(GL_DEPTH_TEST, false);
    ScopedEnable blend(GL_BLEND, true);
    Program& program = begin(shaders, width / scale, height / scale);  // the HUD's own pixels
    for (const HudPanel& p : panels) {
        drawRect(program, p.x, p.y, p.x + p.width, p.y + p.height, p.color);
        float y = p.y + kPad;
        for (const HudLine& line : p.lines) {
            drawText(program, line, p.x + kPad, y);
            y += kLineHeight;
        }
    }
    end();
}

void Hud::drawLines(ShaderLibrary& shaders, const std::vector<glm::vec2>& ends,
                    const glm::vec4& color, int width, int height) {
    if (width <= 0 || height <= 0 || ends.size() < 2) return;
    ScopedEnable noDepth(GL_DEPTH_TEST, false);
    ScopedEnable blend(GL_BLEND, true);
    Program& program = begin(shaders, float(width), float(height));
    std::vector<float> v;
    for (const glm::vec2& p : ends) v.insert(v.end(), {p.x, p.y, 0.0f, 0.0f});
    glBufferData(GL_ARRAY_BUFFER, v.size() * sizeof(float), v.data(), GL_STREAM_DRAW);
    program.set("textColor", color);
    glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(ends.size() / 2 * 2));
    end();
}

void Hud::drawBoxes(ShaderLibrary& shaders, const std::vector<glm::vec4>& boxes,
                    const glm::vec4& color, int width, int height) {
    if (width <= 0 || height <= 0 || boxes.empty()) return;
    ScopedEnable noDepth(GL_DEPTH_TEST, false);
    ScopedEnable blend(GL_BLEND, true);
    Program& program = begin(shaders, float(width), float(height));
    for (const glm::vec4& b : boxes) drawRect(program, b.x, b.y, b.z, b.w, color);
    end();
}

void Hud::drawLabel(ShaderLibrary& shaders, const HudLine& line, float x, float y, int width,
                    int height, float scale) {
    if (width <= 0 || height <= 0) return;
    ScopedEnable noDepth(GL_DEPTH_TEST, false);
    ScopedEnable blend(GL_BLEND, true);
    Program& program = begin(shaders, width / scale, height / scale);
    drawText(program, line, x / scale, y / scale);
    end();
}

}  // namespace sl
