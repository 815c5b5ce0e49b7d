#include "render/label_layout.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace sl {

namespace {

constexpr float kSlack = 1e-3f;  // float noise: a candidate is exactly `gap` from its point

// The positions around p for a w x h box, `gap` from p: right, left, above, below, then the
// diagonals (up-right, up-left, down-right, down-left).
std::array<LabelBox, 8> candidates(const glm::vec2& p, const glm::vec2& size, float gap) {
    const float w = size.x, h = size.y;
    const float right = p.x + gap, left = p.x - gap - w, midX = p.x - w / 2;
    const float above = p.y - gap - h, below = p.y + gap, midY = p.y - h / 2;
    return {{{right, midY, w, h},
             {left, midY, w, h},
             {midX, above, w, h},
             {midX, below, w, h},
             {right, above, w, h},
             {left, above, w, h},
             {right, below, w, h},
             {left, below, w, h}}};
}

bool isFree(const LabelBox& box, const LabelBox& figure, float gap,
            const std::vector<glm::vec2>& points, const std::vector<LabelBox>& taken) {
    if (!boxInside(box, figure)) return false;
    for (const glm::vec2& p : points)
        if (distanceToBox(p, box) < gap - kSlack) return false;
    for (const LabelBox& t : taken)
        if (boxesOverlap(box, t)) return false;
    return true;
}

float crossingCost(const LabelBox& box, const std::vector<LabelLine>& lines) {
    float cost = 0;
    for (const LabelLine& l : lines)
        if (segmentCrossesBox(l.a, l.b, box)) cost += l.weight;
    return cost;
}

}  // namespace

bool boxesOverlap(const LabelBox& a, const LabelBox& b) {
    return a.x < b.x + b.width - kSlack && b.x < a.x + a.width - kSlack &&
           a.y < b.y + b.height - kSlack && b.y < a.y + a.height - kSlack;
}

float distanceToBox(const glm::vec2& p, const LabelBox& box) {
    const float dx = std::max({box.x - p.x, 0.0f, p.x - (box.x + box.width)});
    const float dy = std::max({box.y - p.y, 0.0f, p.y - (box.y + box.height)});
    return std::sqrt(dx * dx + dy * dy);
}

bool boxInside(const LabelBox& inner, const LabelBox& outer) {
    return inner.x >= outer.x - kSlack && inner.y >= outer.y - kSlack &&
           inner.x + inner.width <= outer.x + outer.width + kSlack &&
           inner.y + inner.height <= outer.y + outer.height + kSlack;
}

// Liang-Barsky: the part of a-b inside the box is not empty.
bool segmentCrossesBox(const glm::vec2& a, const glm::vec2& b, const LabelBox& box) {
    const glm::vec2 d = b - a;
    float t0 = 0, t1 = 1;
    const std::array<std::pair<float, float>, 4> sides = {{{-d.x, a.x - box.x},
                                                           {d.x, box.x + box.width - a.x},
                                                           {-d.y, a.y - box.y},
                                                           {d.y, box.y + box.height - a.y}}};
    for (const auto& [p, q] : sides) {
        if (p == 0) {
            if (q < 0) return false;  // parallel to this side and outside it
            continue;
        }
        const float t = q / p;
        if (p < 0)
            t0 = std::max(t0, t);
        else
            t1 = std::min(t1, t);
        if (t0 > t1) return false;
    }
    return true;
}

std::vector<PlacedLabel> placeLabels(const std::vector<PointLabel>& labels, const LabelBox& figure,
                                     float gap, const LabelObstacles& also) {
    std::vector<glm::vec2> points = also.points;
    for (const PointLabel& l : labels) points.push_back(l.point);
    std::vector<LabelBox> taken = also.boxes;
    std::vector<PlacedLabel> placed;
    for (const PointLabel& label : labels) {
        PlacedLabel out;
        for (bool key : {false, true}) {  // the whole label, else its key
            float least = 0;
            for (const LabelBox& box :
                 candidates(label.point, key ? label.keySize : label.size, gap)) {
                if (!isFree(box, figure, gap, points, taken)) continue;
                const float cost = crossingCost(box, also.lines);
                if (!out.placed || cost < least) out = {box, key, true}, least = cost;
            }
            if (out.placed) break;
        }
        if (out.placed) taken.push_back(out.box);
        placed.push_back(out);
    }
    return placed;
}

}  // namespace sl
