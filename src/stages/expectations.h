// What each stage is expected to show, read from one data file (src/stages/expectations.json):
// the lesson of a stage's defaults, and of a few named settings (the slides' figures). A lesson
// may be a failure (acne, the inverted -0.5, phong's missing shadows); the limits then say that
// it fails and by how much. `check`, `example` and `stages` all read this one file.
#pragma once

#include <cmath>
#include <glm/glm.hpp>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "stages/params.h"

namespace sl {

// A broken or inconsistent data file (names the file and the entry); exit code 2.
class ExpectationError : public std::invalid_argument {
  public:
    using std::invalid_argument::invalid_argument;
};

// The text of one of the stages' data files (expectations.json, displaced_bounds.json,
// drawn_figures.json); throws ExpectationError naming it when it cannot be read.
std::string readStageData(const std::string& path);

// A bound on one figure (names as in the check report: false_shadow_pct, mirror_psnr_db, ...).
// NaN = no bound on that side.
struct Limit {
    std::string figure;
    double min = NAN, max = NAN;
    std::string bound() const;  // ">= 20", "<= 5", "in [0, 5]"
};

struct Expectation {
    std::string stage;
    // The entry's name for good, unique within its stage ("defaults", "slope", "lab-factor-40"):
    // kept records and a worker's rows name their entry by it, so its settings (its label) and
    // wording may change without a class being regraded.
    std::string id;
    std::string scene;                                     // "" = the stage's own default scene
    std::vector<std::string> trees;                        // empty = every tree the stage runs in
    std::vector<std::pair<std::string, std::string>> set;  // the settings it is about
    std::string outcome;  // the lesson in a few words: "acne", "no shadows", "correct", ...
    std::string why;
    std::string look;  // what to look for on screen, one short line (the window shows it)
    std::vector<Limit> limits;
    // "rgb", "margin margin-kind=slope", "hardware scene=lab offset-factor=20 ..."
    std::string label() const;
};

// A view a stage is graded from: a camera and, if useful, a light (GUIDE section 4). Views live
// in the data file per scene, chosen so that every object receives a cast shadow somewhere in
// one of them and one is near grazing; unset fields keep the scene's own.
struct GradingView {
    std::string name;
    std::optional<glm::vec3> eye, at, light;
    std::optional<float> fovy;
    std::string why;
};

// The figure names a limit may use, in report order (metrics/figures.h: figureTable()).
const std::vector<std::string>& figureNames();

// The stage's own default scene ("slides" unless it names one).
std::string defaultSceneOf(const std::string& stage);

// Parses the data file's text; `origin` names it in errors. Checks every entry against the
// stage registry (stage, scene, parameter names and values), that each has an id (lower-case
// words joined by '-') no other entry of its stage has, and that each stage has exactly one
// defaults entry (no scene, no settings) per tree.
std::vector<Expectation> parseExpectations(const std::string& text, const std::string& origin);
// <data dir>/src/stages/expectations.json, loaded once.
std::string expectationsPath();
const std::vector<Expectation>& expectations();
// The views of a scene from the same file (parsed with it); a scene it does not list is graded
// from its own camera alone (one view named "scene").
std::vector<GradingView> parseViews(const std::string& text, const std::string& origin,
                                    const std::string& scene);
const std::vector<GradingView>& gradingViews(const std::string& scene);
// The entry of `stage` named `id` that applies to `tree`; nullptr when there is none.
const Expectation* expectationById(const std::vector<Expectation>& book, const std::string& stage,
                                   const std::string& id, const std::string& tree);
// Every entry of `stage` for `tree`, the defaults' entry first, then in file order.
std::vector<const Expectation*> lessonsOf(const std::vector<Expectation>& book,
                                          const std::string& stage, const std::string& tree);

// The entry for what is being checked: the one whose scene, tree and settings match exactly
// (every parameter equal, compared through ParamSet so 0.01 == 0.010); else the stage's defaults
// entry, and `exact` is false (the settings are judged against the defaults' lesson).
struct ExpectationMatch {
    const Expectation* entry = nullptr;
    bool exact = false;
};
ExpectationMatch findExpectation(const std::vector<Expectation>& book, const std::string& stage,
                                 const std::string& sceneName, const std::string& tree,
                                 const ParamSet& values);

}  // namespace sl
