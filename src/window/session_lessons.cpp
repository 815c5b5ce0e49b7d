// Lessons (`n`), the label that follows the settings, and the split view's halves (`s`): the
// choices are lecture/lessons.h's (the browser page makes the same), on the window's state.
#include "window/session.h"

namespace sl {

LessonChoice WindowSession::lessons() const {
    Renderer& r = renderer();
    return {lessonsOf(args_.lessons, r.stage().id, treeName(r.shaders().tree())), lesson_};
}

// A lesson is on screen while its values, scene and view are: after `x`, `=` or `v` the label
// says the settings are no longer a lesson's, and names the lesson they are if one (`x` back to
// the defaults is the first). The lesson `n` chose wins among lessons of the same settings.
int WindowSession::matchingLesson() const {
    Renderer& r = renderer();
    return sl::matchingLesson(lessons(), {&r.params(), scene_, stageScene_, r.view});
}

void WindowSession::nextLesson() {
    const LessonChoice choice = lessons();
    if (choice.list.empty()) {
        flash("n: this stage has no lessons", false);
        return;
    }
    lesson_ = nextLessonIndex(choice, matchingLesson());
    const WindowLesson& l = *choice.list[lesson_];
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
    return sl::lessonLine(lessons(), matchingLesson());
}

std::string WindowSession::valuesName(const Sets& sets) const {
    Renderer& r = renderer();
    const auto list = lessons().list;
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
    const WindowLesson* l = lessons().list[std::size_t(k)];
    return l->topView ? l : nullptr;
}

std::vector<SplitHalf> WindowSession::splitHalves() const {
    return sl::splitHalves(renderer().params(), lessons(), matchingLesson());
}

}  // namespace sl
