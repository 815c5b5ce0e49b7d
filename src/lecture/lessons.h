// The lecture's lessons and the choices made from them, with no window and no page: which lesson
// the settings on screen are, which one `n` brings next, and the split view's two halves (`s`).
// The window (window/session_lessons.cpp) and the browser page (web/web_main.cpp) both call
// these, so the page steps and splits as the window does (docs/web.md).
#pragma once

#include <cstddef>
#include <glm/glm.hpp>
#include <string>
#include <utility>
#include <vector>

#include "render/stage_interface.h"
#include "render/stage_params.h"

namespace sl {

// Parameters off their defaults, as NAME=VALUE pairs in declaration order.
using Sets = std::vector<std::pair<std::string, std::string>>;

// A lesson the window steps through with `n`: an entry of expectations.json or a lecture figure
// of slides_examples/, with its settings and what to look for on screen.
struct WindowLesson {
    std::string stage;
    std::string scene;               // "": the stage's own
    std::vector<std::string> trees;  // empty: every tree the stage runs in
    Sets sets;
    std::string name;  // "margin margin-kind=slope: almost no acne"
    std::string look;  // what to look for, one short line
    ViewMode view = ViewMode::Final;
    // The lecture's mirror exercise drawn from above beside the picture (slides_examples'
    // "figure": the mirror's ends p1, p2, the eye and at in the x-z plane).
    bool topView = false;
    glm::vec2 p1{0.0f}, p2{0.0f}, eye{0.0f}, at{0.0f};
};

// The lessons of expectations.json and slides_examples/, in that order per stage.
std::vector<WindowLesson> windowLessons();

// The lessons of `stage` that run in the GLSL tree named `tree` ("core", "legacy"), in order.
std::vector<const WindowLesson*> lessonsOf(const std::vector<WindowLesson>& all,
                                           const std::string& stage, const std::string& tree);

// The parameters of `params` off their defaults; `params` at its defaults, then `sets` applied.
Sets nonDefault(const ParamSet& params);
void applySets(ParamSet& params, const Sets& sets);

// What is on screen, as a lesson's settings are compared with it.
struct OnScreenSettings {
    const ParamSet* values = nullptr;
    std::string scene;       // the scene shown
    std::string stageScene;  // the stage's own scene (a lesson without one is in it)
    ViewMode view = ViewMode::Final;
};

// A lecture's lessons of one stage and the one `n` chose last (an index into `list`).
struct LessonChoice {
    std::vector<const WindowLesson*> list;
    std::size_t chosen = 0;
};

// The lesson whose settings (values, scene, view) are those on screen, -1 if none: after `x`,
// `=` or `v` the settings are no longer a lesson's unless they are another's. The one chosen wins
// among lessons of the same settings.
int matchingLesson(const LessonChoice& lessons, const OnScreenSettings& now);
// The lesson `n` brings: the one after the lesson on screen (`shown`, -1: none), else after the
// one chosen last; after the last, the first.
std::size_t nextLessonIndex(const LessonChoice& lessons, int shown);

// The HUD's lesson line: "lesson 2/4 (n): NAME. Look for: LOOK", or that the settings are none
// of the stage's lessons; "" for a stage without lessons.
std::string lessonLine(const LessonChoice& lessons, int shown);
std::string lessonText(const WindowLesson& lesson, std::size_t k, std::size_t of);  // k 0-based
std::string noLessonText(std::size_t lessons);

// A half of the split view: its label and its settings.
struct SplitHalf {
    std::string name;
    Sets sets;
};
// The split view's two halves: the mirror's first two methods where the stage declares
// `mirror-method`; else the lesson on screen (or the one chosen) and the next one in the same
// scene and view, its failure beside its fix. Empty: the stage has no such pair.
std::vector<SplitHalf> splitHalves(const ParamSet& values, const LessonChoice& lessons, int shown);
// The label over half `k` (0: left, 1: right).
std::string splitLabel(std::size_t k, const SplitHalf& half);

}  // namespace sl
