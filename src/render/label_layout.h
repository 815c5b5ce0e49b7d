// Where a figure's point labels go: each in free space beside its point (right, left, above,
// below, then the diagonals), overlapping no other label and no drawn point, inside the figure,
// clear of the figure's lines where it can be; a label that fits nowhere is shortened to its
// legend key. Plain geometry (pixels, y down), no GL: the window's top view of the mirror draws
// its labels at the HUD's text size with it.
#pragma once

#include <glm/glm.hpp>
#include <vector>

namespace sl {

struct LabelBox {
    float x = 0, y = 0, width = 0, height = 0;  // top-left corner, y down
};

struct PointLabel {
    glm::vec2 point{0.0f};    // what it names
    glm::vec2 size{0.0f};     // the whole label's box
    glm::vec2 keySize{0.0f};  // its legend key's box, when the whole label fits nowhere
};

struct PlacedLabel {
    LabelBox box;
    bool key = false;     // shortened to its legend key
    bool placed = false;  // false: not even the key fits (the legend alone names it)
};

// A line of the figure; crossing it costs `weight` (its width: a thin line hidden under a label
// for a few pixels is a smaller loss than the thick one the figure is about).
struct LabelLine {
    glm::vec2 a{0.0f}, b{0.0f};
    float weight = 1;
};

// What the labels keep clear of besides each other and their own points: other drawn points,
// boxes already taken (a legend), and lines, crossed as little as possible.
struct LabelObstacles {
    std::vector<glm::vec2> points;
    std::vector<LabelBox> boxes;
    std::vector<LabelLine> lines;
};

// Places the labels in order. A label's candidates keep `gap` from its point: beside it (right,
// left, above, below) or diagonal to it. A candidate is free when it lies inside `figure`,
// overlaps no label placed before it nor a box of `also`, and keeps at least `gap` from every
// point (the labels' own and `also`'s). Of the free candidates of the whole label, the one whose
// crossed lines weigh least wins (the first in that order on a tie); when none is free, the key's
// the same way; else the label is left unplaced.
std::vector<PlacedLabel> placeLabels(const std::vector<PointLabel>& labels, const LabelBox& figure,
                                     float gap, const LabelObstacles& also = {});

// Geometry the placement and its tests share.
bool boxesOverlap(const LabelBox& a, const LabelBox& b);       // a positive area in common
float distanceToBox(const glm::vec2& p, const LabelBox& box);  // 0 inside
bool boxInside(const LabelBox& inner, const LabelBox& outer);  // edges may touch
bool segmentCrossesBox(const glm::vec2& a, const glm::vec2& b, const LabelBox& box);

}  // namespace sl
