// On-screen text for the window (stage, parameters, ms per frame, errors), drawn with
// stb_easy_font's quads.
#pragma once

#include <string>
#include <vector>

#include "gl/shader_library.h"

namespace sl {

struct HudLine {
    std::string text;
    glm::vec4 color{1.0f};
};

class Hud {
public:
    Hud();
    // Draws the lines from the top-left corner of a width x height framebuffer.
    void draw(ShaderLibrary& shaders, const std::vector<HudLine>& lines, int width, int height, float scale);

private:
    VertexArray vao_;
    Buffer buffer_;
};

}  // namespace sl
