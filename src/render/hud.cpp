#include "render/hud.h"

#include <stb_easy_font.h>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/state.h"

namespace sl {

Hud::Hud() : vao_(VertexArray::create()), buffer_(Buffer::create()) {}

void Hud::draw(ShaderLibrary& shaders, const std::vector<HudLine>& lines, int width, int height,
               float scale) {
    Program& program = shaders.program("hud", "text");
    ScopedEnable noDepth(GL_DEPTH_TEST, false);
    ScopedEnable blend(GL_BLEND, true);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    program.use();
    program.set("projection", glm::ortho(0.0f, width / scale, height / scale, 0.0f));
    glBindVertexArray(vao_.id());
    glBindBuffer(GL_ARRAY_BUFFER, buffer_.id());
    glEnableVertexAttribArray(kPositionAttribute);
    // stb_easy_font writes 16-byte vertices: x, y, z as floats, then 4 colour bytes.
    glVertexAttribPointer(kPositionAttribute, 3, GL_FLOAT, GL_FALSE, 16, nullptr);
    float y = 6;
    std::vector<char> quads;
    std::vector<float> triangles;
    for (const HudLine& line : lines) {
        for (int pass = 0; pass < 2; ++pass) {  // a dark shadow first, then the text, for contrast
            quads.assign(line.text.size() * 270 + 64, 0);
            float offset = pass == 0 ? 1.0f : 0.0f;
            int n = stb_easy_font_print(6 + offset, y + offset, const_cast<char*>(line.text.c_str()),
                                        nullptr, quads.data(), static_cast<int>(quads.size()));
            triangles.clear();
            const float* v = reinterpret_cast<const float*>(quads.data());
            for (int q = 0; q < n; ++q)  // each quad -> two triangles (core profiles have no quads)
                for (int k : {0, 1, 2, 0, 2, 3}) {
                    const float* p = v + (q * 4 + k) * 4;
                    triangles.insert(triangles.end(), {p[0], p[1], p[2], 0.0f});
                }
            glBufferData(GL_ARRAY_BUFFER, triangles.size() * sizeof(float), triangles.data(), GL_STREAM_DRAW);
            program.set("textColor", pass == 0 ? glm::vec4(0, 0, 0, 0.8f) : line.color);
            glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(triangles.size() / 4));
        }
        y += 11;
    }
    glBindVertexArray(0);
}

}  // namespace sl
