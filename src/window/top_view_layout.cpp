#include "window/top_view_layout.h"

#include <algorithm>

#include "metrics/mirror_figure.h"
#include "window/window_text.h"

namespace sl {

namespace {

const glm::vec4 kInk = kTopViewInk, kMirrorInk(0.1f, 0.35f, 0.9f, 1),
                kReflectedInk(0.85f, 0.35f, 0.05f, 1);

// A label's box for `text` at `scale`, `pad` of paper around it.
glm::vec2 labelSize(const std::string& text, float scale, float pad) {
    return {hudTextWidth(text) * scale + 2 * pad, Hud::kGlyphRows * scale + 2 * pad};
}

// Places the labels (and, when some fit only as keys or not at all, the legend line that names
// them, at the bottom of the paper, kept clear before the labels are placed again).
void placeTopViewLabels(TopViewLayout& f, const std::vector<glm::vec2>& unlabelled) {
    std::vector<PointLabel> wanted;
    for (const TopViewLayout::Label& l : f.labels)
        wanted.push_back({l.point, labelSize(l.text, f.labelScale, f.pad),
                          labelSize(l.key, f.labelScale, f.pad)});
    LabelObstacles also{unlabelled, {}, {}};
    for (const TopViewLayout::Stroke& s : f.strokes) also.lines.push_back({s.a, s.b, s.width});
    const float gap = 2 * f.labelScale;
    auto place = [&] {
        const auto placed = placeLabels(wanted, f.paper, gap, also);
        for (std::size_t k = 0; k < placed.size(); ++k) f.labels[k].place = placed[k];
    };
    place();
    auto legend = [&] {
        std::string text;
        for (const TopViewLayout::Label& l : f.labels) {
            if (l.place.placed && !l.place.key) continue;
            text += (text.empty() ? "" : "  ") +
                    (l.place.placed ? l.key + " " + l.text : l.text + " (no room)");
        }
        return text;
    };
    if (legend().empty()) return;
    const glm::vec2 size = labelSize("", f.labelScale, f.pad);
    f.legendBox = {f.paper.x, f.paper.y + f.paper.height - size.y, f.paper.width, size.y};
    also.boxes.push_back(f.legendBox);
    place();
    f.legend = legend();
}

}  // namespace

TopViewLayout layoutTopView(const MirrorTopView& v, int width, int height, float textScale) {
    TopViewLayout f;
    // The caption at 0.6 of the HUD's size (two lines of numbers beside a picture); the labels
    // at the HUD's own, readable from the back of a hall.
    f.captionScale = std::max(1.0f, textScale * 0.6f);
    f.labelScale = std::max(1.0f, textScale);
    f.pad = f.labelScale;
    HudBlock caption;  // what it shows, wrapped to the half
    caption.panel = glm::vec4(0);
    caption.lines = {{"the slides' exercise from above: the mirror p1-p2, eye and at, the "
                      "reflected eye' and at' and the frustum",
                      kInk},
                     {v.valid ? oneLine(describeTopView(v)) : v.reason, kReflectedInk}};
    f.caption = layoutHud({caption}, width, height, f.captionScale, HudRoom{0.4f, 0});
    const float top = hudBands(f.caption, height, f.captionScale).first;
    f.paper = {f.pad, top, width - 2 * f.pad, height - top - f.pad};

    std::vector<glm::vec2> all = {v.p1, v.p2, v.eye, v.at};
    if (v.valid) all.insert(all.end(), {v.eyePrime, v.atPrime, v.far1, v.far2});
    glm::vec2 lo = all[0], hi = all[0];
    for (const glm::vec2& p : all) lo = glm::min(lo, p), hi = glm::max(hi, p);
    // The figure's margin is the caption's two lines, as before the labels grew: they find
    // room of their own around the points, so the figure keeps its size.
    const float room = 2 * Hud::kLineHeight * f.captionScale;
    const float w = width - 2 * room, h = height - top - 2 * room;
    const float unit = std::max(
        0.0f, std::min(w / std::max(hi.x - lo.x, 1e-3f), h / std::max(hi.y - lo.y, 1e-3f)));
    const glm::vec2 origin(room + (w - unit * (hi.x - lo.x)) / 2,
                           top + room + (h - unit * (hi.y - lo.y)) / 2);
    auto at = [&](glm::vec2 p) { return origin + unit * (p - lo); };  // z grows down the page
    f.figure = {origin.x, origin.y, unit * (hi.x - lo.x), unit * (hi.y - lo.y)};

    const float thin = std::max(1.0f, f.captionScale / 2),
                thick = std::max(2.0f, f.captionScale * 1.5f);
    f.strokes.push_back({at(v.eye), at(v.at), kInk, thin});
    if (v.valid)
        for (const auto& [a, b] :
             std::vector<std::pair<glm::vec2, glm::vec2>>{{v.eyePrime, v.atPrime},
                                                          {v.eyePrime, v.far1},
                                                          {v.eyePrime, v.far2},
                                                          {v.far1, v.far2},
                                                          {v.eye, v.eyePrime}})
            f.strokes.push_back({at(a), at(b), kReflectedInk, thin});
    f.strokes.push_back({at(v.p1), at(v.p2), kMirrorInk, thick});

    f.labels = {{"p1", "", kMirrorInk, at(v.p1), {}},
                {"p2", "", kMirrorInk, at(v.p2), {}},
                {"eye", "", kInk, at(v.eye), {}},
                {"at", "", kInk, at(v.at), {}}};
    if (v.valid) {
        f.labels.push_back({"eye'", "", kReflectedInk, at(v.eyePrime), {}});
        f.labels.push_back({"at'", "", kReflectedInk, at(v.atPrime), {}});
    }
    const float dot = 0.7f * f.labelScale;
    for (std::size_t k = 0; k < f.labels.size(); ++k) {
        TopViewLayout::Label& l = f.labels[k];
        l.key = std::to_string(k + 1);
        f.markers.push_back({l.point - dot, l.point + dot, l.color});
    }
    std::vector<glm::vec2> unlabelled;
    if (v.valid) unlabelled = {at(v.far1), at(v.far2)};
    for (const glm::vec2& p : all) f.points.push_back(at(p));
    placeTopViewLabels(f, unlabelled);
    return f;
}

}  // namespace sl
