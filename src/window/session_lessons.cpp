// Lessons (`n`), the label that follows the settings, and the split view's halves (`s`).
#include "window/session.h"

namespace sl {

std::vector<const WindowLesson*> WindowSession::lessons() const {
    std::vector<const WindowLesson*> list;
    Renderer& r = renderer();
    const std::string tree = treeName(r.shaders().tree());
    for (const WindowLesson& l : args_.lessons) {
        bool inTree = l.trees.empty();
        for (const auto& t : l.trees) inTree = inTree || t == tree;
        if (l.stage == r.stage().id && inTree) list.push_back(&l);
    }
    return list;
}

// A lesson is on screen while its values, scene and view are: after `x`, `=` or `v` the label
// says the settings are no longer a lesson's, and names the lesson they are if one (`x` back to
// the defaults is the first). The lesson `n` chose wins among lessons of the same settings.
int WindowSession::matchingLesson() const {
    const auto list = lessons();
    Renderer& r = renderer();
    const Sets now = nonDefault(r.params());
    auto matches = [&](const WindowLesson& l) {
        ParamSet p(r.stage().params);
        applySets(p, l.sets);
        const std::string scene = l.scene.empty() ? stageScene_ : l.scene;
        return nonDefault(p) == now && scene == scene_ && l.view == r.view;
    };
    if (lesson_ < list.size() && matches(*list[lesson_])) return int(lesson_);
    for (std::size_t k = 0; k < list.size(); ++k)
        if (matches(*list[k])) return int(k);
    return -1;
}

void WindowSession::nextLesson() {
    auto list = lessons();
    if (list.empty()) {
        flash("n: this stage has no lessons", false);
        return;
    }
    const int shown = matchingLesson();
    lesson_ = (shown >= 0 ? std::size_t(shown) + 1 : lesson_ + 1) % list.size();
    const WindowLesson& l = *list[lesson_];
    const StageInfo& s = renderer().stage();
    lessonScene_ = {s.id, l.scene};
    if (sceneFor(s) != scene_) selectStage(renderer().stageIndex(), tree_);  // its scene
    Renderer& r = renderer();
    std::string refused;
    applySets(r.params(), {});
    for (const auto& [name, value] : l.sets) {
        std::string e = r.params().set(name, value);
        if (!e.empty()) refused = e;
    }
    if (offers(r.stage(), l.view)) r.view = l.view;
    if (!refused.empty()) complain("n: " + refused);  // else the HUD names the lesson
}

std::string WindowSession::lessonLine() const {
    auto list = lessons();
    if (list.empty()) return "";
    const int k = matchingLesson();
    if (k < 0) return noLessonText(list.size());
    return lessonText(std::size_t(k), list.size());
}

std::string WindowSession::noLessonText(std::size_t lessons) {
    return "the settings on screen are none of the " + std::to_string(lessons) +
           " lessons (n: the next lesson, x: the defaults)";
}

std::string WindowSession::lessonText(std::size_t k, std::size_t of) const {
    const WindowLesson& l = *lessons()[k];
    std::string line =
        "lesson " + std::to_string(k + 1) + "/" + std::to_string(of) + " (n): " + l.name;
    if (!l.look.empty()) line += ". Look for: " + l.look;
    return line;
}

std::string WindowSession::valuesName(const Sets& sets) const {
    Renderer& r = renderer();
    const auto list = lessons();
    std::string values;
    for (const auto& [name, value] : sets)
        values += (values.empty() ? "" : ", ") + name + " = " + value;
    if (values.empty()) values = "the defaults";
    for (std::size_t k = 0; k < list.size(); ++k) {
        ParamSet p(r.stage().params);
        applySets(p, list[k]->sets);
        if (nonDefault(p) == sets)
            return "lesson " + std::to_string(k + 1) + "/" + std::to_string(list.size()) + " of " +
                   r.stage().id + " (" + values + ")";
    }
    return r.stage().id + " (" + values + ")";
}

const WindowLesson* WindowSession::topViewLesson() const {
    const int k = matchingLesson();
    if (k < 0) return nullptr;
    const WindowLesson* l = lessons()[std::size_t(k)];
    return l->topView ? l : nullptr;
}

std::vector<WindowSession::Half> WindowSession::splitHalves() const {
    Renderer& r = renderer();
    if (const ParamSpec* method = r.params().find("mirror-method")) {
        std::vector<Half> halves;
        for (const auto& choice : method->choices)
            halves.push_back({"mirror-method=" + choice, {{"mirror-method", choice}}});
        if (halves.size() >= 2) halves.resize(2);
        return halves;
    }
    auto list = lessons();
    if (list.size() < 2) return {};
    const int shown = matchingLesson();
    const std::size_t k = (shown >= 0 ? std::size_t(shown) : lesson_) % list.size();
    for (std::size_t step = 1; step < list.size(); ++step) {
        const WindowLesson& next = *list[(k + step) % list.size()];
        if (next.scene == list[k]->scene && next.view == list[k]->view && !next.topView)
            return {{list[k]->name, list[k]->sets}, {next.name, next.sets}};
    }
    return {};
}

}  // namespace sl
