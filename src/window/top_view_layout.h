// The mirror exercise from above, as the window draws it beside the mirror scene, laid out
// without GL: the caption at the top, the figure below it, and each point's label at the HUD's
// text size in free space beside its point (render/label_layout.h); a label that fits nowhere
// becomes a number that a legend line under the figure names.
#pragma once

#include <string>
#include <vector>

#include "math/mirror_topview.h"
#include "render/hud.h"
#include "render/label_layout.h"

namespace sl {

struct TopViewLayout {
    struct Stroke {
        glm::vec2 a{0.0f}, b{0.0f};
        glm::vec4 color{1.0f};
        float width = 1;  // pixels
    };
    struct Label {
        std::string text;  // "eye'"
        std::string key;   // its legend key, drawn instead when `place.key`
        glm::vec4 color{1.0f};
        glm::vec2 point{0.0f};
        PlacedLabel place;  // the box includes `pad` around the text
    };
    float captionScale = 1;  // the caption's text size (the figure's lines follow it)
    float labelScale = 1;    // the labels', the HUD's text size
    float pad = 0;           // paper around a label's text, pixels
    std::vector<HudPanel> caption;
    LabelBox figure;                // where the points lie: the figure's size
    LabelBox paper;                 // the area below the caption, where the labels lie
    std::vector<Stroke> strokes;    // the mirror, the view, the reflected camera
    std::vector<Stroke> markers;    // a dot on each labelled point (a square from a to b)
    std::vector<glm::vec2> points;  // every point drawn, the frustum's far corners too
    std::vector<Label> labels;      // p1, p2, eye, at, eye', at'
    std::string legend;             // "1 eye'  2 at'" when some label is a key, else ""
    LabelBox legendBox;
};

inline const glm::vec4 kTopViewPaper(0.96f, 0.96f, 0.94f, 1), kTopViewInk(0.1f, 0.1f, 0.1f, 1);

// The layout on a width x height area (pixels, y down), the HUD's text size `textScale`.
TopViewLayout layoutTopView(const MirrorTopView& view, int width, int height, float textScale);

}  // namespace sl
