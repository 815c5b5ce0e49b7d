#include "render/hud.h"

#include <stb_easy_font.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "gl/state.h"

namespace sl {

namespace {

float textWidth(const std::string& s) {
    return static_cast<float>(stb_easy_font_width(const_cast<char*>(s.c_str())));
}

}  // namespace

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
        while (textWidth(rest) > maxPixels && rest.size() > 1) {
            // The longest prefix that fits, ended at a space when there is one.
            std::size_t fit = 1;
            while (fit < rest.size() && textWidth(rest.substr(0, fit + 1)) <= maxPixels) ++fit;
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

std::vector<HudLine> layoutHudBlock(const HudBlock& block, float maxPixels) {
    std::vector<HudLine> lines = wrapHudLines(block.lines, maxPixels);
    if (block.maxLines > 0 && static_cast<int>(lines.size()) > block.maxLines) {
        std::size_t keep = static_cast<std::size_t>(std::max(block.maxLines - 1, 0));
        std::size_t more = lines.size() - keep;
        glm::vec4 colour = lines[keep].color;
        lines.resize(keep);
        lines.push_back({"(" + std::to_string(more) + " more lines)", colour});
    }
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

void Hud::drawText(Program& program, const HudLine& line, float x, float y) {
    quads_.assign(line.text.size() * 270 + 64, 0);
    int n = stb_easy_font_print(x, y, const_cast<char*>(line.text.c_str()), nullptr, quads_.data(),
                                static_cast<int>(quads_.size()));
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
                                float scale) {
    std::vector<HudPanel> panels;
    if (width <= 0 || height <= 0) return panels;
    const float w = width / scale, h = height / scale;  // the HUD's own (unscaled) pixels
    float top[2] = {kHudMargin, kHudMargin}, bottom[2] = {h - kHudMargin, h - kHudMargin};
    for (const HudBlock& block : blocks) {
        const int c = block.column == 1 ? 1 : 0;
        const float span = c == 1 || block.half ? w / 2 : w;
        HudPanel p;
        p.lines = layoutHudBlock(block, std::max(span - 2 * (kHudMargin + Hud::kPad), 8.0f));
        p.x = c * w / 2 + kHudMargin;
        if (p.lines.empty()) continue;
        p.width = 0;
        for (const auto& l : p.lines)
            p.width = std::max(p.width, textWidth(l.text) + 2 * Hud::kPad);
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

void Hud::draw(ShaderLibrary& shaders, const std::vector<HudBlock>& blocks, int width, int height,
               float scale) {
    if (width <= 0 || height <= 0) return;
    Program& program = shaders.program("hud", "text");
    ScopedEnable noDepth(GL_DEPTH_TEST, false);
    ScopedEnable blend(GL_BLEND, true);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    program.use();
    const float w = width / scale, h = height / scale;  // the HUD's own (unscaled) pixels
    program.set("projection", glm::ortho(0.0f, w, h, 0.0f));
    glBindVertexArray(vao_.id());
    glBindBuffer(GL_ARRAY_BUFFER, buffer_.id());
    glEnableVertexAttribArray(kPositionAttribute);
    // stb_easy_font writes 16-byte vertices: x, y, z as floats, then 4 colour bytes.
    glVertexAttribPointer(kPositionAttribute, 3, GL_FLOAT, GL_FALSE, 16, nullptr);
    for (const HudPanel& p : layoutHud(blocks, width, height, scale)) {
        drawRect(program, p.x, p.y, p.x + p.width, p.y + p.height, p.color);
        float y = p.y + kPad;
        for (const HudLine& line : p.lines) {
            drawText(program, line, p.x + kPad, y);
            y += kLineHeight;
        }
    }
    glDisableVertexAttribArray(kPositionAttribute);
    glBindVertexArray(0);
}

}  // namespace sl
