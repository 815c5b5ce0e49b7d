// An assignment (docs/assignment.md): the stages due and their trees, the files a student hands
// in for each, the points of each stage split over its lesson entries and views, who sees each
// row (Gradescope's visibilities) and the instructor's own extra views. Validated like scenes:
// every error names the file, the JSON path and the line.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "course/assignment_error.h"
#include "grade/plan.h"
#include "gradebook/late_policy.h"
#include "io/usage_error.h"
#include "stages/request.h"

namespace sl {

// Gradescope's names: visible, hidden, after_due_date, after_published.
const std::vector<std::string>& visibilityNames();

struct WeightedView {
    double weight = 1;
    std::string visibility;  // "" = the stage's
};

struct AssignmentStage {
    std::string stage, tree;  // "margin", "core"
    bool due = true;
    std::vector<std::string> files;  // relative to the tree: "margin/lit.frag"
    double points = 0;
    std::string visibility = "visible";
    std::map<std::string, double> lessons;      // lesson label -> weight (absent: 1)
    std::map<std::string, WeightedView> views;  // view name -> weight, visibility (absent: 1)
    std::string todo;                           // what the student writes (release README)
};

// A view of the instructor's: graded in every due stage whose lessons use its scene, always
// hidden from students.
struct ExtraView {
    std::string name, scene;
    std::optional<glm::vec3> eye, at, light;
    std::optional<float> fovy;
    double weight = 1;
};

struct Assignment {
    std::string name, dueDate, origin;
    std::optional<LatePolicy> late;
    std::vector<AssignmentStage> stages;
    std::vector<ExtraView> extraViews;
    // The file name a hand-in may carry at its top: the student's own `check --report`, compared
    // with the grade, never trusted (grade/own_check.h). "" = none: such a file is any file.
    std::string ownCheckReport;
    nlohmann::json publicJson;         // what a student may see: no extra views, no hidden weights
    std::map<std::string, int> lines;  // every value's JSON pointer -> its line in the file
    std::vector<const AssignmentStage*> due() const;
    double maxPoints() const;  // of the due stages
    // "FILE: /json/path (line N)" for messages about the value at `path` (or its parent).
    std::string at(const std::string& path) const;
};

// Parses and checks an assignment: its syntax, types and ranges, then its meaning
// (checkAssignmentMeaning). Throws AssignmentError naming the file, the JSON path and the line.
Assignment parseAssignment(const std::string& text, const std::string& origin);
Assignment loadAssignment(const std::string& path);

// What a well-formed assignment may still not say (course/assignment_meaning.cpp): a view that
// cannot be drawn (eye on its target, looking straight up or down, eye or light inside or on an
// object of its scene), a due stage worth no points or whose rows all weigh 0. Throws
// AssignmentError naming the file, the JSON path and the line.
void checkAssignmentMeaning(const Assignment& a);

// Every row of a due stage for the submission at `overlay` (may be ""), in check order; the
// stage's points split over them by lesson weight times view weight. With a `seed`, the
// stage's lessons are also graded in the view displaced by it (a view named "displaced": its
// casters, light and camera, or the mirror stage's camera and mirror, moved by an amount drawn
// at grading time, so no shader can know it).
std::vector<RowPlan> planStage(const Assignment& a, const AssignmentStage& s,
                               const std::string& overlay,
                               std::optional<std::uint64_t> seed = std::nullopt, int width = 640,
                               int height = 480);

}  // namespace sl
