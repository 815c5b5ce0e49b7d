// What the window and the browser page both choose, without either (lecture/lessons.h): the
// lesson on screen, the one `n` brings, the split view's halves; and the field of view a
// half is drawn with (math/orbit.h). Every stage of the registry with its lessons from the data.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/glm.hpp>
#include <set>

#include "lecture/lessons.h"
#include "math/orbit.h"
#include "stages/registry.h"

using namespace sl;

namespace {

const std::vector<WindowLesson>& allLessons() {
    static const std::vector<WindowLesson> all = windowLessons();
    return all;
}

// The settings a lesson puts on screen, as `n` applies them.
struct Screen {
    ParamSet values;
    std::string scene;
    ViewMode view = ViewMode::Final;
};

OnScreenSettings settingsOf(const Screen& s, const std::string& stageScene) {
    return {&s.values, s.scene, stageScene, s.view};
}

}  // namespace

// From a stage's defaults, as many presses of `n` as it has lessons show each lesson once, each
// then the lesson on screen (its line names it), in the order of the data after the first.
TEST(LectureLessons, NextStepsThroughEveryLessonOnce) {
    int stepped = 0;
    for (const StageDefinition& stage : stageRegistry()) {
        const std::string stageScene = "own";
        LessonChoice choice{lessonsOf(allLessons(), stage.id, "core"), 0};
        const std::size_t n = choice.list.size();
        Screen screen{ParamSet(stage.params), stageScene, ViewMode::Final};
        std::set<std::size_t> seen;
        for (std::size_t press = 0; press < n; ++press) {
            const int shown = matchingLesson(choice, settingsOf(screen, stageScene));
            choice.chosen = nextLessonIndex(choice, shown);
            const WindowLesson& l = *choice.list[choice.chosen];
            applySets(screen.values, l.sets);
            screen.scene = l.scene.empty() ? stageScene : l.scene;
            screen.view = l.view;
            const int now = matchingLesson(choice, settingsOf(screen, stageScene));
            ASSERT_EQ(now, int(choice.chosen)) << stage.id << " press " << press;
            EXPECT_EQ(lessonLine(choice, now)
                          .rfind("lesson " + std::to_string(now + 1) + "/" + std::to_string(n) +
                                     " (n): " + l.name,
                                 0),
                      0u);
            seen.insert(choice.chosen);
        }
        EXPECT_EQ(seen.size(), n) << stage.id;
        stepped += int(n);
    }
    EXPECT_GT(stepped, 0);
}

// The split: the mirror's two methods where the stage declares them; else the lesson on screen
// beside the next one of the same scene and view, each with its own settings; a stage with one
// lesson has none. After `x` (the defaults) the first lesson is on screen where it is the
// defaults.
TEST(LectureLessons, SplitIsTheLessonOnScreenBesideTheNextInItsScene) {
    int split = 0;
    for (const StageDefinition& stage : stageRegistry()) {
        LessonChoice choice{lessonsOf(allLessons(), stage.id, "core"), 0};
        const ParamSet defaults(stage.params);
        const int shown = matchingLesson(choice, {&defaults, "own", "own", ViewMode::Final});
        const auto halves = splitHalves(defaults, choice, shown);
        if (const ParamSpec* method = defaults.find("mirror-method")) {
            ASSERT_EQ(halves.size(), 2u) << stage.id;
            for (std::size_t k = 0; k < 2; ++k)
                EXPECT_EQ(halves[k].sets, (Sets{{"mirror-method", method->choices[k]}}));
            ++split;
            continue;
        }
        if (choice.list.size() < 2) {
            EXPECT_TRUE(halves.empty()) << stage.id;
            continue;
        }
        if (halves.empty()) continue;  // no second lesson in the scene and view of the first
        ++split;
        ASSERT_EQ(halves.size(), 2u);
        const WindowLesson& first = *choice.list[std::size_t(std::max(shown, 0))];
        EXPECT_EQ(halves[0].name, first.name) << stage.id;
        EXPECT_EQ(halves[0].sets, first.sets) << stage.id;
        EXPECT_NE(halves[1].sets, halves[0].sets) << stage.id;
        bool found = false;
        for (const WindowLesson* l : choice.list)
            found = found || (l->name == halves[1].name && l->sets == halves[1].sets &&
                              l->scene == first.scene && l->view == first.view);
        EXPECT_TRUE(found) << stage.id << ": " << halves[1].name;
        EXPECT_EQ(splitLabel(0, halves[0]), "left: " + halves[0].name);
        EXPECT_EQ(splitLabel(1, halves[1]), "right: " + halves[1].name);
    }
    EXPECT_GE(split, 2);  // the shadow stages' lessons and the mirror's methods
}

// A half (320x480 of a 640x480 picture) is narrower than the scenes' 4:3: its field of view
// widens so the scene's width still fits (the same horizontal extent); 4:3 and wider keep it.
TEST(LectureLessons, NarrowPictureWidensTheFieldOfViewToKeepTheWidth) {
    EXPECT_FLOAT_EQ(fovyFittingWidth(45, 4.0f / 3.0f), 45);
    EXPECT_FLOAT_EQ(fovyFittingWidth(45, 16.0f / 9.0f), 45);
    const float aspect = 320.0f / 480.0f;
    const float fovy = fovyFittingWidth(45, aspect);
    const float width = std::tan(glm::radians(fovy) / 2) * aspect;
    EXPECT_NEAR(width, std::tan(glm::radians(45.0f) / 2) * 4 / 3, 1e-5);
    EXPECT_FLOAT_EQ(fovyFittingWidth(45, 0.01f), 150);
}
