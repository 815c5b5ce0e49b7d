// What the panels say. Compact (the default, for a projector): the stage, its tree, the
// student's folder, the selected parameter, the lesson, and the first error's file, line and
// message; full (`i`): everything, a page at a time; the keys (`h`) in the picture's place.
#include <sstream>

#include "lecture/hud_text.h"
#include "window/session.h"
#include "window/window_text.h"

namespace sl {

namespace {

const glm::vec4 kWhite(1), kGrey(0.85f, 0.85f, 0.85f, 1), kYellow(1, 1, 0.6f, 1),
    kGreen(0.6f, 1, 0.6f, 1), kBlue(0.75f, 0.85f, 1, 1), kErrorText(1, 0.85f, 0.8f, 1),
    kErrorTitle(1, 0.7f, 0.6f, 1);
const glm::vec4 kErrorPanel(0.25f, 0.02f, 0.02f, 0.92f);

}  // namespace

const char* const WindowSession::kTryingLine =
    "trying your shaders in a bounded worker first: a loop or a crash cannot freeze this window";

// The title line and the marks are lecture/hud_text.h's (the page shows the same).
std::string WindowSession::compactTitle(const ParamSet& values, std::size_t selected) const {
    return sl::compactTitle(renderer(), values, selected, {request_.overlay, request_.tree});
}

std::string WindowSession::title() const {
    return stageTitle(renderer());
}

std::string WindowSession::treeText() const {
    std::string t = std::string("tree ") + treeName(shownTree());
    if (renderer().stage().legacyOnly && tree_ == GlslTree::Core) t += " (fixed-function needs it)";
    return t;
}

// The student's folder as the compact HUD names it: over ours in this tree, or not used here.
std::string WindowSession::folderText() const {
    if (request_.overlay.empty()) return "";
    if (!renderer().shaders().overlay().empty()) return "your shaders: " + request_.overlay;
    return "your shaders (" + request_.overlay + ") are for the " + treeName(request_.tree) +
           " tree: ours here";
}

std::string WindowSession::ignoredMark(const std::string& param) const {
    return sl::ignoredMark(renderer(), param);
}

// What the values on screen (or the split view's halves) wait for: "" when they drew. It names
// them (the lesson they are) and, once their trial runs, its CPU budget.
std::string WindowSession::valuesLine() const {
    const auto screen = onScreen();
    for (const Sets& sets : screen.sets)
        if (watchdog_->valuePending(screen.tree, screen.stage, sets)) {
            std::string budget;
            const auto& tried = watchdog_->tried();
            if (watchdog_->running() && !tried.empty() && tried.back().what == "values" &&
                tried.back().sets == sets && tried.back().budgetSeconds > 0)
                budget = " (CPU budget " + secondsText(tried.back().budgetSeconds) + ")";
            return "trying " + valuesName(sets) + " with your shaders in the worker" + budget +
                   ": the last values that drew show meanwhile";
        }
    return "";
}

// The last refusal of values, while the values it put back are still those on screen.
std::string WindowSession::refusalLine() const {
    Renderer& r = renderer();
    if (refusal_.line.empty() || refusal_.stage != r.stage().id || refusal_.tree != shownTree() ||
        nonDefault(r.params()) != refusal_.backTo)
        return "";
    return refusal_.line;
}

// The lines saying what is being tried, if anything concerns the picture.
std::vector<HudLine> WindowSession::tryingLines() const {
    std::vector<HudLine> lines;
    const GlslTree tree = shownTree();
    const std::string& stage = renderer().stage().id;
    if (watchdog_->filesPending(tree, stage) && watchdog_->adopted(tree, stage))
        lines.push_back(
            {"trying your saved files in the worker first: the last good program "
             "draws meanwhile",
             kGreen});
    const std::string values = valuesLine();
    if (!values.empty()) lines.push_back({values, kGreen});
    const std::string refused = refusalLine();
    if (!refused.empty()) lines.push_back({refused, kErrorText});
    return lines;
}

std::vector<HudLine> WindowSession::helpLines() const {
    std::vector<HudLine> lines = {{"the keys (h: back to the picture)", kYellow}};
    for (const auto& h : windowHelp()) lines.push_back({h, kWhite});
    return lines;
}

// The errors: the first one's file, line and message first, then (all) every line of each.
std::vector<HudLine> WindowSession::errorLines(bool all) const {
    std::vector<HudLine> lines;
    const auto errors = shownErrors();
    if (errors.empty()) return lines;
    lines.push_back({firstErrorLine(errors[0]), kErrorText});
    if (!all) return lines;
    lines.front().color = kErrorTitle;
    for (const auto& e : errors)
        for (const auto& line : nonBlankLines(e)) lines.push_back({line, kErrorText});
    return lines;
}

// A page in the picture's place for a stage with no good program: why, in full.
std::vector<HudLine> WindowSession::errorPage(const std::string& why) const {
    std::vector<HudLine> lines = {
        {"no good program for " + renderer().stage().id + " yet, so no picture:", kErrorTitle}};
    const std::string first = firstErrorLine(why);  // the line to read first, marked
    for (const auto& line : nonBlankLines(why))
        lines.push_back({line, firstErrorLine(line) == first ? kYellow : kErrorText});
    lines.push_back({"save a repair: it is tried at once (r: try again now)", kGrey});
    return lines;
}

std::vector<HudBlock> WindowSession::hudBlocks() const {
    Renderer& r = renderer();
    const StageInfo& s = r.stage();
    std::vector<HudBlock> blocks;
    const std::string view = viewLabel(s, r.view);
    const std::string legend = viewLegend(s, r.view);
    const auto errors = shownErrors();
    std::size_t errorLinesTotal = 0;
    for (const auto& e : errors) errorLinesTotal += nonBlankLines(e).size();
    auto addLegendAndFlash = [&] {  // at the bottom, in both modes
        if (!legend.empty()) {
            HudBlock b;
            b.bottom = true;
            b.lines = {{legend, kWhite}};
            b.maxLines = 2;
            blocks.push_back(b);
        }
        if (!flash_.empty()) {
            HudBlock b;
            b.bottom = true;
            b.lines = {{flash_, flashIsError_ ? kErrorText : kGreen}};
            b.maxLines = 3;
            if (flashIsError_) b.more = "(N more lines: the terminal has all of it)";
            b.panel = flashIsError_ ? kErrorPanel : glm::vec4(0, 0, 0, 0.75f);
            blocks.push_back(b);
        }
    };
    if (split_ || !halfAreas_.empty()) {
        const auto halves = splitHalves();
        for (std::size_t k = 0; split_ && k < halves.size() && k < 2; ++k) {
            HudBlock b;
            b.bottom = true;
            b.column = int(k);
            b.half = true;
            b.lines = {{splitLabel(k, halves[k]), kWhite}};
            b.keepLines = 1000;  // whole: the band at the bottom keeps room for it
            blocks.push_back(b);
        }
    }
    const auto& specs = r.params().specs();
    if (hudMode_ == HudMode::Compact) {  // for a projector: what the picture is, how to read it
        // The title and the lesson, whole (what to look for is never cut): the band the window
        // keeps at the top holds them. What comes and goes (a trial, a refusal) is a panel of
        // its own under them, over the picture's edge.
        HudBlock top;
        top.lines.push_back({compactTitle(r.params(), selectedParam_), kYellow});
        const std::string lesson = lessonLine();
        if (!lesson.empty()) top.lines.push_back({lesson, kWhite});
        top.keepLines = 1000;
        top.more = "i: the lesson and the rest (N more lines)";
        HudBlock trying;
        trying.lines = tryingLines();
        trying.more = "i: the rest (N more lines)";
        if (!errors.empty()) {  // first: the first error's file, line and message, wrapped
            HudBlock e;
            e.lines = errorLines(false);
            const std::size_t more = errorLinesTotal + (errors.size() > 1 ? 1 : 0);
            e.lines.push_back(
                {"i: the whole text (" + std::to_string(more) + (more == 1 ? " line" : " lines") +
                     (errors.size() > 1 ? ", " + std::to_string(errors.size()) + " errors)" : ")"),
                 kGrey});
            e.more = "i: the rest of it (N more lines)";
            e.keepLines = 3;  // its first line and the count, then the title and the lesson
            e.panel = kErrorPanel;
            blocks.push_back(e);
        }
        blocks.push_back(top);
        if (!trying.lines.empty()) blocks.push_back(trying);
        addLegendAndFlash();
        return blocks;
    }

    HudBlock top;  // the full panel, a page at a time: the errors first, in full
    top.scrollable = true;
    top.firstLine = hudScroll_;
    if (!errors.empty()) {
        top.lines.push_back({renderError_.empty()
                                 ? "shader error (the last good program keeps drawing):"
                                 : "shader error (no good program for this stage yet):",
                             kErrorTitle});
        for (const HudLine& l : errorLines(true)) top.lines.push_back(l);
    }
    top.lines.push_back({title() + ": " + s.title, kYellow});
    std::ostringstream status;
    status << treeText() << " | scene " << scene_ << " | view " << view << " | ";
    if (drawnFrames_ == 0)  // the time is known once the frame is done: the first one has none
        status << "first frame";
    else
        status << static_cast<int>(drawMs_ * 10) / 10.0 << " ms to draw";
    top.lines.push_back({status.str(), kWhite});
    for (const HudLine& l : tryingLines()) top.lines.push_back(l);
    if (scene_ != startScene_)
        top.lines.push_back({"scene " + scene_ + ": the " + s.id +
                                 " stage brings its own (back to " + startScene_ +
                                 " when you leave it)",
                             kBlue});
    if (!request_.overlay.empty())
        top.lines.push_back({folderText() + (r.shaders().overlay().empty() ? "" : " (over ours)"),
                             r.shaders().overlay().empty() ? kGrey : kGreen});
    for (std::size_t i = 0; i < specs.size(); ++i) {
        bool selected = i == selectedParam_ % specs.size();
        top.lines.push_back({std::string(selected ? "> " : "  ") + specs[i].name + " = " +
                                 r.params().text(specs[i].name) + ignoredMark(specs[i].name),
                             selected ? kGreen : kGrey});
    }
    const std::string lesson = lessonLine();
    if (!lesson.empty()) top.lines.push_back({lesson, kWhite});
    for (const auto& n : r.stats.notes) top.lines.push_back({n, kBlue});
    top.lines.push_back({"h: the keys    PgUp/PgDn: this panel a page at a time", kGrey});
    blocks.push_back(top);
    addLegendAndFlash();
    return blocks;
}

}  // namespace sl
