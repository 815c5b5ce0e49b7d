// Drawing a frame: the panels' bands, the picture between them (the stage, the split view's
// halves, the mirror seen from above, or a page of text in the picture's place: the keys, why
// there is no picture), then the panels.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <set>

#include "io/png.h"
#include "lecture/hud_text.h"
#include "math/mirror_topview.h"
#include "math/orbit.h"
#include "window/session.h"
#include "window/window_text.h"

namespace sl {

namespace {

constexpr float kFullPanelShare = 0.55f;  // the full HUD's two bands: the picture keeps 45 %
constexpr float kFullBottom = 0.15f;
constexpr HudRoom kCompactRoom{0.45f, 0.20f};  // the compact HUD's bands at most
// ... and with what floats over the picture's edge (a trial, a refusal, an error, a message).
constexpr HudRoom kCompactFloating{0.65f, 0.35f};
const glm::vec4 kBackground(0.1f, 0.1f, 0.12f, 1);
const glm::vec4 kErrorBackground(0.16f, 0.03f, 0.03f, 1);

std::string setsText(const Sets& sets) {
    std::string text;
    for (const auto& [name, value] : sets)
        text += (text.empty() ? "" : ", ") + name + " = " + value;
    return text.empty() ? "the defaults" : text;
}

}  // namespace

float WindowSession::textScale(int width, int height) const {
    return std::max(0.5f, hudScale(width, height) * args_.hudScale);
}

HudRoom WindowSession::hudRoom() const {
    // The most the panels take, the reserved bands and what floats over the picture's edge
    // together: the full panel pages in its band, the compact one cuts (its first error's file,
    // line and message come first).
    if (hudMode_ == HudMode::Full && height_ > 0)
        return HudRoom{float(reservedBands(width_, height_).first) / float(height_), kFullBottom};
    return hudMode_ == HudMode::Full ? HudRoom{kFullPanelShare, kFullBottom} : kCompactFloating;
}

// A picture that holds still. The bands the window keeps for the panels (and so the picture's
// rectangle) depend on the window's size, the HUD's mode and the stage, never on what the panels
// show now: the compact top band holds the title line with any parameter selected at any
// lesson's values and the longest of the stage's lesson lines; the bottom band the longest
// legend of the stage's views (and the split view's labels); the full panel has its room. A
// lesson, a value, a trial, a message or an error does not move the picture: what does not fit
// the band (an error, a trial, a refusal, a message) floats over the picture's edge.
std::pair<int, int> WindowSession::reservedBands(int width, int height) const {
    if (hudMode_ == HudMode::Hidden || width <= 0 || height <= 0) return {0, 0};
    const float scale = textScale(width, height);
    const HudRoom room =
        hudMode_ == HudMode::Full ? HudRoom{kFullPanelShare, kFullBottom} : kCompactRoom;
    const float w = width / scale, h = height / scale;
    const float inside = 2 * (kHudMargin + Hud::kPad);
    auto lines = [](const std::string& text, float wrapAt) {
        return int(wrapHudLines({{text, glm::vec4(1)}}, std::max(wrapAt, 8.0f)).size());
    };
    // A panel of n lines and the margin under it (the first panel has one above it too).
    auto panel = [](int n) {
        return n > 0 ? n * Hud::kLineHeight + 2 * Hud::kPad - 3 + kHudMargin : 0;
    };
    Renderer& r = renderer();
    const auto list = lessons().list;
    std::set<ViewMode> views = {r.view};  // the one on screen and those its lessons show
    for (const WindowLesson* l : list) views.insert(l->view);
    int legend = 0;
    for (ViewMode v : views)
        if (!viewLegend(r.stage(), v).empty())  // the final picture has none
            legend = std::max(legend, std::min(2, lines(viewLegend(r.stage(), v), w - inside)));
    float bottom = legend > 0 ? kHudMargin + panel(legend) : 0;
    if (split_) {  // each half's label, wrapped to its half, under the legend's panel
        int label = 0;
        for (const SplitHalf& half : splitHalves())
            label = std::max(label, lines(splitLabel(1, half), w / 2 - inside));
        bottom += (legend > 0 ? 0 : kHudMargin) + panel(label);
    }
    bottom = std::min(bottom, h * room.bottom);
    // The full panel: what leaves the picture its 45 %, a page at a time.
    float top = std::max(h * 0.25f, h * kFullPanelShare - bottom);
    if (hudMode_ == HudMode::Compact) {
        // Not the values on screen: a value no lesson has (`=`) must not move the picture
        // either (its title, if longer, floats a line over the picture's edge).
        const std::size_t params = std::max<std::size_t>(1, r.params().specs().size());
        int title = 0, lesson = 0;
        for (std::size_t k = 0; k <= list.size(); ++k) {  // the defaults, then each lesson
            ParamSet values(r.stage().params);
            if (k > 0) applySets(values, list[k - 1]->sets);
            for (std::size_t p = 0; p < params; ++p)
                title = std::max(title, lines(compactTitle(values, p), w - inside));
            if (k > 0)
                lesson = std::max(lesson,
                                  lines(lessonText(*list[k - 1], k - 1, list.size()), w - inside));
        }
        if (!list.empty())  // the settings of no lesson
            lesson = std::max(lesson, lines(noLessonText(list.size()), w - inside));
        top = std::min(h * room.top, kHudMargin + panel(title + lesson));
    }
    return {int(std::ceil(top * scale)), int(std::ceil(bottom * scale))};
}

void WindowSession::layOut(int width, int height) {
    bands_ = {0, 0};
    hudText_.clear();
    pageText_.clear();
    panels_.clear();
    if (hudMode_ != HudMode::Hidden) {
        const float scale = textScale(width, height);
        panels_ = layoutHud(hudBlocks(), width, height, scale, hudRoom());
        bands_ = reservedBands(width, height);
        for (const HudPanel& p : panels_) {
            for (const HudLine& l : p.lines) hudText_.push_back(l.text);
            if (!p.bottom && hudMode_ == HudMode::Full) {  // PgUp/PgDn: a page of the panel
                panelLines_ = p.pageLines > 0 ? p.pageLines : int(p.lines.size());
                hudScroll_ = std::clamp(hudScroll_, 0, std::max(0, p.wrappedLines - 1));
            }
        }
    }
    pictureArea_ = {0, bands_.second, width, std::max(1, height - bands_.first - bands_.second)};
}

std::string WindowSession::draw(int width, int height, const std::string& saveTo, bool withHud) {
    width_ = width;
    height_ = height;
    Renderer& r = renderer();
    auto start = Clock::now();
    if (animateLight_) {  // radians per second, whatever the frame rate (down to 1 frame a second;
                          // a longer gap is a pause, not a frame, and does not jump the light)
        double dt = std::min(std::chrono::duration<double>(start - lastAnimation_).count(), 1.0);
        r.lightPosition = circlingLight(r.lightPosition, kLightRadiansPerSecond, dt);
    }
    lastAnimation_ = start;
    std::string saved;
    if (!saveTo.empty() && !withHud) saved = writePng(saveTo, pictureAlone(width, height));
    layOut(width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    glClearColor(kBackground.r, kBackground.g, kBackground.b, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    drawPicture(pictureArea_);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);  // the stage's passes leave theirs
    hud_.draw(hudShaders_, panels_, width, height, textScale(width, height));
    if (!saveTo.empty() && withHud) saved = writePng(saveTo, readPixels());
    glFinish();
    drawMs_ = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    if (!watchdog_->running()) idleDrawMs_ = drawMs_;
    ++drawnFrames_;
    return saved;
}

Image WindowSession::pictureAlone(int width, int height) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    glClearColor(kBackground.r, kBackground.g, kBackground.b, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    drawPicture({0, 0, width, height});
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    return readPixels();
}

void WindowSession::drawPicture(const Rect& area) {
    halfAreas_.clear();
    halvesShow_.clear();
    topViewLabels_.clear();
    if (showHelp_) {  // asked for: the keys in the picture's place, in every HUD mode
        drawPage(area, helpLines(), kBackground, &pageScroll_);
        pictureShows_ = "help";
        return;
    }
    if (split_ && splitHalves().empty()) split_ = false;  // another stage, or its only lesson
    if (split_) {
        drawSplit(area);
        return;
    }
    const Sets onScreen = nonDefault(renderer().params());
    if (const WindowLesson* lesson = topViewLesson()) {  // the mirror from above, beside it
        const Rect left{area.x, area.y, area.width / 2, area.height};
        const Rect right{area.x + left.width, area.y, area.width - left.width, area.height};
        drawTopView(left, *lesson);
        pictureShows_ = drawStageIn(right, onScreen, true);
        halfAreas_ = {left, right};
        halvesShow_ = {"top-view", pictureShows_};
        return;
    }
    pictureShows_ = drawStageIn(area, onScreen, true);
}

// Both halves with the renderer's own camera and light, each with its settings (the stage's
// defaults and the lesson's), side by side in the picture's area.
void WindowSession::drawSplit(const Rect& area) {
    const auto halves = splitHalves();
    const int half = area.width / 2;
    pictureShows_ = "stage";
    for (std::size_t k = 0; k < halves.size() && k < 2; ++k) {
        const Rect part{area.x + int(k) * half, area.y, k == 0 ? half : area.width - half,
                        area.height};
        ParamSet values = renderer().params();
        applySets(values, halves[k].sets);
        const std::string shows = drawStageIn(part, nonDefault(values), false);
        if (shows != "stage") pictureShows_ = shows;
        halfAreas_.push_back(part);
        halvesShow_.push_back(shows);
    }
}

void WindowSession::noteRenderError(const std::string& why) {
    renderError_ = why;
    if (printedRenderError_ != why && saidErrors_.insert(why).second)
        std::cerr << "shadowlab: shader error (no good program for " << renderer().stage().id
                  << " yet): " << oneLine(why) << std::endl;
    printedRenderError_ = why;
}

std::string WindowSession::drawStageIn(const Rect& area, const Sets& sets, bool onScreen) {
    Renderer& r = renderer();
    const GlslTree tree = shownTree();
    const std::string& stage = r.stage().id;
    if (onScreen) renderError_.clear();
    // Built here from the files on disk only when those drew in the worker; while others are
    // tried (or were refused), what this renderer built before keeps drawing.
    const std::string here = std::string(treeName(tree)) + "/" + scene_ + "/" + stage;
    const bool held = watchdog_->adopted(tree, stage) && drawnHere_.count(here);
    if (!held && !watchdog_->diskIsGood(tree, stage)) {
        if (watchdog_->filesPending(tree, stage)) {
            const std::string who =
                request_.overlay.empty() ? "the changed files of " : folderText() + ", stage ";
            drawPage(area,
                     {{kTryingLine, glm::vec4(0.6f, 1, 0.6f, 1)},
                      {"(" + who + stage + ")", glm::vec4(0.85f)}},
                     kBackground, nullptr);
            return "trying";
        }
        std::string why = watchdog_->refused(tree, stage);
        if (why.empty()) why = watchdog_->lost(tree, stage);
        if (onScreen) noteRenderError(why);
        drawPage(area, errorPage(why), kErrorBackground, &pageScroll_);
        return "none";
    }
    const Sets use = watchdog_->drawable(tree, stage, sets);
    if (!onScreen && use != sets) {  // a half's values: its lesson is drawn, or said why not
        const std::string refused = watchdog_->valueRefused(tree, stage, sets);
        std::vector<HudLine> lines;
        if (refused.empty())
            lines = {{"trying " + setsText(sets) + " with your shaders in the worker first",
                      glm::vec4(0.6f, 1, 0.6f, 1)}};
        else
            lines = {{"these values did not draw in the trial worker (" + setsText(sets) + "):",
                      glm::vec4(1, 0.7f, 0.6f, 1)},
                     {refused, glm::vec4(1, 0.85f, 0.8f, 1)}};
        drawPage(area, lines, refused.empty() ? kBackground : kErrorBackground, nullptr);
        return refused.empty() ? "trying" : "none";
    }
    const ParamSet kept = r.params();
    const bool other = nonDefault(kept) != use;
    const Camera camera = r.camera;
    try {
        if (other) {
            applySets(r.params(), use);
            r.sceneChanged();  // another shadow map: no cached one carries over
        }
        // A split half or a tall window: the scene's width still fits (math/orbit.h).
        r.camera.fovyDegrees =
            fovyFittingWidth(r.camera.fovyDegrees, float(area.width) / float(area.height));
        const bool whole =
            area.x == 0 && area.y == 0 && area.width == width_ && area.height == height_;
        if (whole) {
            r.render(0, area.width, area.height);
        } else {
            picture_.resize(area.width, area.height);
            r.render(picture_.framebuffer(), area.width, area.height);
            blit(picture_.framebuffer(), area);
        }
        drawnHere_.insert(here);
        if (onScreen) drawnWith_ = use;
    } catch (const ShaderError& e) {  // built here for the first time and failed
        if (onScreen) noteRenderError(e.what());
        drawPage(area, errorPage(e.what()), kErrorBackground, &pageScroll_);
        r.camera = camera;
        if (other) r.params() = kept, r.sceneChanged();
        return "none";
    }
    r.camera = camera;
    if (other) r.params() = kept, r.sceneChanged();
    return "stage";
}

void WindowSession::blit(GLuint from, const Rect& to) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, from);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, to.width, to.height, to.x, to.y, to.x + to.width, to.y + to.height,
                      GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

// Lines of text in the picture's place, as large as the window's text when they fit, smaller
// (down to 7-pixel glyphs) when not, then a page at a time (PgUp/PgDn) with `scroll`.
void WindowSession::drawPage(const Rect& area, const std::vector<HudLine>& lines,
                             const glm::vec4& background, int* scroll) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glEnable(GL_SCISSOR_TEST);
    glScissor(area.x, area.y, area.width, area.height);
    glClearColor(background.r, background.g, background.b, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    const float most = textScale(width_, height_);
    float scale = most;
    std::vector<HudLine> wrapped;
    int rows = 0;
    for (;;) {
        const float wrapAt = area.width / scale - 2 * (kHudMargin + Hud::kPad);
        wrapped = wrapHudLines(lines, std::max(wrapAt, 8.0f));
        rows = int((area.height / scale - 2 * (kHudMargin + Hud::kPad) + 3) / Hud::kLineHeight);
        if (int(wrapped.size()) <= rows || scale <= std::min(1.0f, most)) break;
        scale = std::max(std::min(1.0f, most), scale * 0.85f);
    }
    HudBlock page;
    page.lines = lines;
    page.panel = glm::vec4(0);
    page.scrollable = scroll != nullptr;
    page.firstLine = scroll ? *scroll : 0;
    page.more = "(N more lines: a larger window shows them)";
    glViewport(area.x, area.y, area.width, area.height);
    const auto panels = layoutHud({page}, area.width, area.height, scale);
    hud_.draw(hudShaders_, panels, area.width, area.height, scale);
    glViewport(0, 0, width_, height_);
    for (const HudPanel& p : panels)
        for (const HudLine& l : p.lines) pageText_.push_back(l.text);
    if (scroll) {
        *scroll = std::clamp(*scroll, 0, std::max(0, int(wrapped.size()) - 1));
        pageLines_ = std::max(1, rows - 1);
    }
}

// The lecture's practice exercise from above: the mirror p1-p2, the viewer's eye and at, the
// reflected eye' and at', and the reflected camera's frustum, x to the right and z down the page,
// labelled at the HUD's text size (window/top_view_layout.h places them).
void WindowSession::drawTopView(const Rect& area, const WindowLesson& lesson) {
    const MirrorTopView v = practiceTopView(lesson.p1, lesson.p2, lesson.eye, lesson.at);
    drawPage(area, {}, kTopViewPaper, nullptr);
    const TopViewLayout f = layoutTopView(v, area.width, area.height, textScale(width_, height_));
    const int w = area.width, h = area.height;
    glViewport(area.x, area.y, w, h);
    hud_.draw(hudShaders_, f.caption, w, h, f.captionScale);
    for (const TopViewLayout::Stroke& s : f.strokes) {
        glLineWidth(s.width);  // a compatibility context: wide lines allowed
        hud_.drawLines(hudShaders_, {s.a, s.b}, s.color, w, h);
    }
    glLineWidth(1);
    for (const TopViewLayout::Stroke& m : f.markers)
        hud_.drawBoxes(hudShaders_, {{m.a, m.b}}, m.color, w, h);
    // Each label on its own patch of paper: a line it had to cross stays readable under it.
    for (const TopViewLayout::Label& l : f.labels) {
        if (!l.place.placed) continue;
        const LabelBox& b = l.place.box;
        hud_.drawBoxes(hudShaders_, {{b.x, b.y, b.x + b.width, b.y + b.height}}, kTopViewPaper, w,
                       h);
        hud_.drawLabel(hudShaders_, {l.place.key ? l.key : l.text, l.color}, b.x + f.pad,
                       b.y + f.pad, w, h, f.labelScale);
    }
    if (!f.legend.empty())
        hud_.drawLabel(hudShaders_, {f.legend, kTopViewInk}, f.legendBox.x + f.pad,
                       f.legendBox.y + f.pad, w, h, f.labelScale);
    glViewport(0, 0, width_, height_);
    topViewLabels_ = f.labels;
    topViewArea_ = area;
}

void WindowSession::PictureTarget::resize(int width, int height) {
    if (width == width_ && height == height_) return;
    width_ = width;
    height_ = height;
    colour_ = Renderbuffer::create();
    glBindRenderbuffer(GL_RENDERBUFFER, colour_.id());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    depthStencil_ = Renderbuffer::create();
    glBindRenderbuffer(GL_RENDERBUFFER, depthStencil_.id());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
    fbo_ = Framebuffer::create();
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_.id());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                              depthStencil_.id());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace sl
