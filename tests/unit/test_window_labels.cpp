// Labels placed beside their points (render/label_layout.h), and the window's top view of the
// mirror exercise labelled with them at the HUD's text size (window/top_view_layout.h): no label
// over another or over a drawn point, each inside the figure and next to its point, the lines
// crossed as little as there is room for, a key where the whole label fits nowhere.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>

#include "render/label_layout.h"
#include "window/top_view_layout.h"
#include "window/window_args.h"

using namespace sl;

namespace {

std::string str(const LabelBox& b) {
    std::ostringstream s;
    s << "[" << b.x << ", " << b.y << ", " << b.width << " x " << b.height << "]";
    return s.str();
}

// Every promise of placeLabels for one call: what breaks them, said.
std::vector<std::string> broken(const std::vector<PointLabel>& labels,
                                const std::vector<PlacedLabel>& placed, const LabelBox& figure,
                                float gap, const LabelObstacles& also = {}) {
    std::vector<std::string> out;
    if (placed.size() != labels.size()) return {"one result per label"};
    std::vector<glm::vec2> points = also.points;
    for (const PointLabel& l : labels) points.push_back(l.point);
    for (std::size_t k = 0; k < placed.size(); ++k) {
        if (!placed[k].placed) continue;
        const LabelBox& b = placed[k].box;
        const std::string name = "label " + std::to_string(k) + " " + str(b);
        const glm::vec2 size = placed[k].key ? labels[k].keySize : labels[k].size;
        if (b.width != size.x || b.height != size.y) out.push_back(name + ": not its size");
        if (!boxInside(b, figure)) out.push_back(name + ": outside the figure " + str(figure));
        const float d = distanceToBox(labels[k].point, b);
        if (d < gap - 0.01f || d > gap * std::sqrt(2.0f) + 0.01f)
            out.push_back(name + ": " + std::to_string(d) + " px from its point, not next to it");
        for (const glm::vec2& p : points)
            if (distanceToBox(p, b) < gap - 0.01f)
                out.push_back(name + ": covers the point " + std::to_string(p.x) + ", " +
                              std::to_string(p.y));
        for (std::size_t j = 0; j < k; ++j)
            if (placed[j].placed && boxesOverlap(b, placed[j].box))
                out.push_back(name + ": overlaps label " + std::to_string(j));
        for (const LabelBox& taken : also.boxes)
            if (boxesOverlap(b, taken)) out.push_back(name + ": overlaps the box " + str(taken));
    }
    return out;
}

std::string joined(const std::vector<std::string>& lines) {
    std::string s;
    for (const std::string& l : lines) s += l + "\n";
    return s;
}

}  // namespace

TEST(LabelLayout, BoxGeometry) {
    const LabelBox box{10, 10, 20, 10};
    EXPECT_TRUE(segmentCrossesBox({0, 15}, {40, 15}, box));   // straight through
    EXPECT_TRUE(segmentCrossesBox({15, 12}, {16, 13}, box));  // wholly inside
    EXPECT_FALSE(segmentCrossesBox({0, 0}, {40, 5}, box));    // above it
    EXPECT_FALSE(segmentCrossesBox({0, 15}, {9, 15}, box));   // stops short of it
    EXPECT_FALSE(segmentCrossesBox({0, 30}, {30, 21}, box));  // below its corner
    EXPECT_TRUE(boxesOverlap(box, {29, 19, 5, 5}));
    EXPECT_FALSE(boxesOverlap(box, {30, 10, 5, 5}));  // touching is not overlapping
    EXPECT_FLOAT_EQ(distanceToBox({33, 24}, box), 5.0f);
    EXPECT_FLOAT_EQ(distanceToBox({15, 15}, box), 0.0f);
    EXPECT_TRUE(boxInside({10, 10, 20, 10}, box));
    EXPECT_FALSE(boxInside({9, 10, 20, 10}, box));
}

// Random crowds of points and labels of every size: wherever a label goes, it keeps every
// promise; most of them find room whole.
TEST(LabelLayout, RandomCrowdsKeepEveryPromise) {
    std::mt19937 random(40);
    std::uniform_real_distribution<float> unit(0, 1);
    const LabelBox figure{20, 30, 400, 300};
    const float gap = 6;
    int whole = 0, keys = 0, total = 0;
    for (int trial = 0; trial < 300; ++trial) {
        std::vector<PointLabel> labels;
        const int n = 2 + trial % 9;
        for (int k = 0; k < n; ++k)
            labels.push_back(
                {{figure.x + unit(random) * figure.width, figure.y + unit(random) * figure.height},
                 {20 + 100 * unit(random), 12 + 20 * unit(random)},
                 {8, 12}});
        LabelObstacles also;
        also.points = {{figure.x + unit(random) * figure.width, figure.y + 150}};
        also.lines = {{labels[0].point, labels[1].point, 1}};
        const auto placed = placeLabels(labels, figure, gap, also);
        const auto why = broken(labels, placed, figure, gap, also);
        ASSERT_TRUE(why.empty()) << "trial " << trial << ":\n" << joined(why);
        for (const PlacedLabel& p : placed) {
            whole += p.placed && !p.key;
            keys += p.placed && p.key;
        }
        total += n;
    }
    std::cout << whole << " of " << total << " labels whole, " << keys << " keys\n";
    EXPECT_GT(whole, total * 8 / 10) << "most labels find room whole";
    EXPECT_GT(keys, 0) << "the crowds are crowded enough to need keys";
}

// The pair that overlapped when the labels grew (eye' and at', close together): both whole,
// apart, each next to its own point.
TEST(LabelLayout, ClosePointsGetLabelsApart) {
    const std::vector<PointLabel> labels = {{{200, 100}, {130, 60}, {30, 60}},
                                            {{215, 130}, {92, 60}, {30, 60}}};
    const LabelBox figure{0, 0, 600, 400};
    const auto placed = placeLabels(labels, figure, 11);
    EXPECT_TRUE(broken(labels, placed, figure, 11).empty())
        << joined(broken(labels, placed, figure, 11));
    for (const PlacedLabel& p : placed) EXPECT_TRUE(p.placed && !p.key) << str(p.box);
}

// A point on a thick line running right and a thin one running up: the label goes where it
// crosses neither (left). Among random lines through and around the point, it goes to the place
// beside its point whose crossed lines weigh least: the eight places as the header lists them.
TEST(LabelLayout, LinesAreCrossedAsLittleAsPossible) {
    const glm::vec2 p{200, 200};
    const glm::vec2 size{60, 20};
    const std::vector<PointLabel> labels = {{p, size, {10, 20}}};
    const LabelBox figure{0, 0, 400, 400};
    const float gap = 5;
    LabelObstacles also;
    also.lines = {{p, {380, 200}, 4}, {p, {200, 20}, 1}};
    auto placed = placeLabels(labels, figure, gap, also);
    ASSERT_TRUE(placed[0].placed);
    EXPECT_LT(placed[0].box.x + placed[0].box.width, p.x) << "left of its point";
    for (const LabelLine& l : also.lines)
        EXPECT_FALSE(segmentCrossesBox(l.a, l.b, placed[0].box)) << str(placed[0].box);

    auto cost = [&](const LabelBox& box) {
        float c = 0;
        for (const LabelLine& l : also.lines) c += segmentCrossesBox(l.a, l.b, box) ? l.weight : 0;
        return c;
    };
    const float w = size.x, h = size.y;
    const std::vector<LabelBox> places = {
        {p.x + gap, p.y - h / 2, w, h},     {p.x - gap - w, p.y - h / 2, w, h},
        {p.x - w / 2, p.y - gap - h, w, h}, {p.x - w / 2, p.y + gap, w, h},
        {p.x + gap, p.y - gap - h, w, h},   {p.x - gap - w, p.y - gap - h, w, h},
        {p.x + gap, p.y + gap, w, h},       {p.x - gap - w, p.y + gap, w, h}};
    std::mt19937 random(8);
    std::uniform_real_distribution<float> angle(0, 6.2832f), weight(0.5f, 4);
    int crossedSome = 0;
    for (int trial = 0; trial < 200; ++trial) {
        also.lines.clear();
        for (int k = 0; k < 5; ++k) {
            const float a = angle(random);
            const glm::vec2 through = p + glm::vec2(std::cos(a), std::sin(a)) * 10.0f * float(k);
            const glm::vec2 along(std::cos(angle(random)), std::sin(angle(random)));
            also.lines.push_back(
                {through - 300.0f * along, through + 300.0f * along, weight(random)});
        }
        placed = placeLabels(labels, figure, gap, also);
        ASSERT_TRUE(placed[0].placed && !placed[0].key);
        float least = 1e9f;
        for (const LabelBox& b : places) least = std::min(least, cost(b));
        EXPECT_FLOAT_EQ(cost(placed[0].box), least) << "trial " << trial << str(placed[0].box);
        crossedSome += least > 0;
    }
    EXPECT_GT(crossedSome, 20) << "the lines leave no clear place often enough to matter";
}

// No room for the whole label anywhere: its key goes beside the point; no room for the key
// either: it is left unplaced.
TEST(LabelLayout, KeyWhereTheWholeLabelFitsNowhere) {
    const std::vector<PointLabel> labels = {{{50, 30}, {120, 20}, {10, 14}}};
    const LabelBox figure{0, 0, 100, 60};
    auto placed = placeLabels(labels, figure, 4);
    ASSERT_TRUE(placed[0].placed);
    EXPECT_TRUE(placed[0].key);
    EXPECT_TRUE(broken(labels, placed, figure, 4).empty())
        << joined(broken(labels, placed, figure, 4));
    placed = placeLabels(labels, {40, 20, 20, 20}, 4);
    EXPECT_FALSE(placed[0].placed);
}

namespace {

const WindowLesson& topViewLesson() {
    static const std::vector<WindowLesson> lessons = windowLessons();
    for (const WindowLesson& l : lessons)
        if (l.topView) return l;
    throw std::runtime_error("no lesson brings a top view (slides_examples' \"figure\")");
}

std::vector<std::string> brokenFigure(const TopViewLayout& f) {
    std::vector<PointLabel> labels;
    std::vector<PlacedLabel> placed;
    for (const TopViewLayout::Label& l : f.labels) {
        const glm::vec2 text =
            l.place.box.width > 0 ? glm::vec2(l.place.box.width, l.place.box.height) : glm::vec2(0);
        labels.push_back({l.point, text, text});  // its own size either way
        placed.push_back(l.place);
    }
    LabelObstacles also{f.points, {}, {}};
    if (!f.legend.empty()) also.boxes.push_back(f.legendBox);
    return broken(labels, placed, f.paper, 2 * f.labelScale, also);
}

}  // namespace

// The window's top view of the slides' exercise in the half of a 1920x1080 window (the area
// the window gives it there): every label whole, at the HUD's text size, the figure as large as
// before they grew (the last try at large labels shrank it to a third).
TEST(TopViewLabels, WholeAtTheHudsSizeAt1920x1080) {
    const WindowLesson& lesson = topViewLesson();
    const MirrorTopView view = practiceTopView(lesson.p1, lesson.p2, lesson.eye, lesson.at);
    ASSERT_TRUE(view.valid) << view.reason;
    const float scale = hudScale(1920, 1080);
    const TopViewLayout f = layoutTopView(view, 960, 783, scale);
    ASSERT_EQ(f.labels.size(), 6u);
    EXPECT_TRUE(brokenFigure(f).empty()) << joined(brokenFigure(f));
    EXPECT_EQ(f.legend, "") << "no key needed";
    for (const TopViewLayout::Label& l : f.labels) {
        EXPECT_TRUE(l.place.placed && !l.place.key) << l.text;
        EXPECT_FLOAT_EQ(l.place.box.height - 2 * f.pad, Hud::kGlyphRows * scale) << l.text;
        EXPECT_FLOAT_EQ(l.place.box.width - 2 * f.pad, hudTextWidth(l.text) * scale) << l.text;
    }
    const float room = 2 * Hud::kLineHeight * std::max(1.0f, 0.6f * scale);  // its old margin
    EXPECT_TRUE(std::abs(f.figure.width - (960 - 2 * room)) < 1 ||
                std::abs(f.figure.height - (f.paper.height + f.pad - 2 * room)) < 1)
        << "the figure fills its area, less the margin it had before: " << str(f.figure);
}

// Windows from 320x240 to full HD and a HUD scaled up to twice: the labels keep every promise
// wherever they go; those shortened to keys are named by the legend, which covers no label.
TEST(TopViewLabels, EverySizeKeepsEveryPromise) {
    const WindowLesson& lesson = topViewLesson();
    const MirrorTopView view = practiceTopView(lesson.p1, lesson.p2, lesson.eye, lesson.at);
    int keyed = 0;
    for (const auto& [w, h] : std::vector<std::pair<int, int>>{
             {320, 240}, {640, 480}, {800, 600}, {1024, 768}, {1280, 720}, {1920, 1080}})
        for (float hud : {1.0f, 1.5f, 2.0f}) {
            const float scale = hudScale(w, h) * hud;
            const TopViewLayout f = layoutTopView(view, w / 2, int(h * 0.7f), scale);
            const std::string at =
                std::to_string(w) + "x" + std::to_string(h) + " x" + std::to_string(hud) + ": ";
            EXPECT_TRUE(brokenFigure(f).empty()) << at << joined(brokenFigure(f));
            for (const TopViewLayout::Label& l : f.labels) {
                if (l.place.placed && !l.place.key) continue;
                ++keyed;
                EXPECT_NE(f.legend.find(l.text), std::string::npos) << at << f.legend;
            }
        }
    std::cout << keyed << " labels shortened to keys or left to the legend\n";
}
