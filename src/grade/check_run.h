// One check: a stage rendered at a request's settings, its figures measured against the
// reference (through the Evaluator, as bench and sweep measure them), and judged against the
// stage's entry in src/stages/expectations.json. Shared by `check` and `example`.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "eval/evaluator.h"
#include "grade/judge.h"
#include "grade/status.h"
#include "sandbox/worker.h"
#include "stages/expectations.h"

namespace sl {

struct CheckResult {
    std::string stage, tree, scene, overlay;
    std::string view;    // the grading view's name (expectations.json "views"), or "custom"
    std::string lesson;  // the expectation entry's label, e.g. "margin margin-kind=slope"
    int width = 0, height = 0;
    ParamSet parameters;  // every parameter's value used
    Camera camera;
    glm::vec3 light{0};
    Accuracy figures;
    long evaluated = 0, truthLit = 0, truthShadow = 0;  // pixel counts behind the percentages
    // A shadow stage's pixels outside the edge band, per object of the scene (by its name): where
    // the false shadow and false lit lie (ShadowFigures::byObject). Empty for the mirror.
    struct ObjectPixels {
        std::string name;
        ShadowFigures::ObjectCounts counts;
    };
    std::vector<ObjectPixels> objects;
    ExpectationMatch expectation;
    // The row's status (grade/status.h) and why, in one line. Figures are measured only for
    // PASS, FAIL and SKIP; MISSING, ERROR, TIMEOUT, CRASH and NOT GRADED rows have none.
    Status status = Status::Skip;
    std::string message;
    // The bounds the verdict held the figures to, side by side (grade/judge.h): what a page lists
    // (a failing figure, its value, its bound), never read back out of `message`. Empty where no
    // bound was held (an unjudged row, a stage with no entry) and in a record kept before the
    // field existed (its page shows the message instead: feedback/feedback_html.h).
    std::vector<FigureReason> reasons;
    std::vector<std::string> studentFiles;  // the submission's files this row used (relative)
    std::string diffFile;                   // the diff image written, or ""
    std::string note;                       // e.g. why no diff image was written
    // What the stage's source rules found in the student's files (StageDefinition::sourceRules):
    // notes for the instructor, e.g. a comparison of eyePosition with a constant; not a score.
    std::vector<std::string> sourceNotes;
    std::string backend, machine;  // the headless backend, machineLine() of the context used
    double seconds = 0;
    std::optional<std::uint64_t> seed;  // the displaced view's seed (RenderRequest::displaceSeed)

    std::string verdict() const { return statusName(status); }
    std::map<std::string, double> figureMap() const;
};

// A result naming what `request` checks (stage, tree, overlay, size), nothing measured yet.
CheckResult checkResultFor(const RenderRequest& request);

// A row naming what `r` checks (its settings, scene, camera, expectation) with nothing measured:
// the row of a stage that was not rendered (MISSING) or whose job gave no results.
CheckResult unrenderedResult(const RenderRequest& r);

// Renders and judges `request` (its view must be final); writes the diff image to `diffPath`
// when not empty (the mirror's: its difference from our stencil reflection). A shader that does
// not build is caught: the result is an ERROR with the compiler's first line, the full message
// goes to stderr and the rig is reset.
// Other failures propagate (bad input: UsageError; GL: std::runtime_error).
// A displaced case (RenderRequest::displaceSeed) is judged against the wider of the lesson's
// bounds and the solution's figures in displaced views (data: stages/displaced_bounds.h); one
// whose settings no lesson names but a drawn row covers (the seed's, or the same given with
// --set) is held to `shipped`, our shaders' figures at the same values and view, within the
// row's tolerance (judgeDrawn; the case's own figures when null). In a student edition, which
// cannot render ours, our figures for a submission's drawn row come from the data shipped for its
// seed (stages/drawn_figures.h); values it does not ship are a SKIP.
// `pictures` says which are written once the row is judged (RowPictures below): with the
// render and the truth's shading (the mirror: our stencil reflection) beside the diff image
// (DIFF.render.png, DIFF.truth.png), a feedback page shows the three side by side.
enum class RowPictures {
    Difference,        // the diff image alone (check --diff-dir without pictures)
    All,               // the three
    AllUnlessPassing,  // the three for a row that does not pass, none for one that does: a page
                       // shows a stage's first failing row, else its first row (`grade`)
};
// What a row says when the browser lost its WebGL context under it (NOT GRADED: the platform's,
// never the student's, whatever the row drew or failed to compile).
std::string contextLostMessage(const std::string& stage);
// The first row of a drawn pair, for judging its second (stages/drawn.h, DrawnResponse): the
// second's row, the first's drawn values ("margin=0.00053") and figures, theirs and ours (ours
// empty in a student edition: the shipped data's).
struct PairedRow {
    const DrawnRow* second = nullptr;
    std::string from;
    ParamSet values;
    std::map<std::string, double> theirs, ours;
};
CheckResult runCheck(Evaluator& rig, const RenderRequest& request, const std::string& diffPath,
                     const std::map<std::string, double>* shipped = nullptr,
                     RowPictures pictures = RowPictures::Difference,
                     const PairedRow* paired = nullptr);

// One thing a (stage, tree) check judges: a lesson entry's settings seen from one view.
struct CheckCase {
    RenderRequest request;
    std::string view, lesson;
    RowPictures pictures = RowPictures::Difference;
    const DrawnRow* drawn = nullptr;  // a drawn row's entry (stages/drawn.h), else null
};

// The file name of a row's images: "STAGE-TREE-VIEW-LESSON" with only [A-Za-z0-9._-].
std::string rowSlug(const CheckCase& c);

// What `check` runs for one stage and tree (`base`): every lesson entry of expectations.json
// that applies, each under its own scene and settings, unless the user narrowed it (`--set`,
// `--scene`: the base request alone); and each from every view of its scene, unless the user
// gave a camera or light (`--eye`, `--at`, `--fovy`, `--light`: one view named "custom").
// With a `seed`, the stage's own scene gets one more view, "displaced": the scene's casters,
// light and camera moved by the seed, or in a scene with a mirror its camera and mirror
// (displacedViewOf, scene/mirror_displace.h; GUIDE section 4: a shader that knows the fixed
// views' geometry or cameras cannot know this one's). With a seed and a submission's overlay
// (not narrowed, no custom view), each "drawn" row of the stage (stages/drawn.h) adds one more,
// view "drawn": the displaced view at settings the seed draws (in a student edition, at the
// seed of the shipped set that shippedDrawnSeed picks: stages/drawn_figures.h). An entry with a
// response adds two, its second right after its first: CaseSeries judges the pair on the second.
std::vector<CheckCase> checkCases(const RenderRequest& base, bool narrowed, bool customView,
                                  std::optional<std::uint64_t> seed = std::nullopt);

// A seed drawn now (std::random_device), for a run that was not given --seed.
std::uint64_t drawSeed();

// The cases of one stage and tree run in order on `rig`, one at a time (the browser edition runs
// a row between the page's frames). `diffPath(case)` names a case's diff image ("" for none). A
// shader that does not build fails the same way under every lesson and view: the series is done
// after the first row that could not be judged. A drawn pair's second row is judged with its
// first's figures (PairedRow), found among the rows run before it; one whose first is not in the
// series (an assignment's weight left it out) is judged by its own band, with a note.
class CaseSeries {
  public:
    CaseSeries(Evaluator& rig, std::vector<CheckCase> cases,
               std::function<std::string(const CheckCase&)> diffPath);
    bool done() const;
    const CheckResult& next();  // runs the next case; only while !done()
    const std::vector<CheckResult>& results() const { return results_; }

  private:
    static bool needsOurs(const CheckCase& c);
    void measureOurs();
    std::optional<PairedRow> pairOf(std::size_t k, std::string& note) const;
    Evaluator& rig_;
    std::vector<CheckCase> cases_;
    std::function<std::string(const CheckCase&)> diffPath_;
    std::map<std::size_t, std::map<std::string, double>> ours_;  // by case: our figures
    bool measured_ = false;
    std::vector<CheckResult> results_;
};

// The whole series at once, reporting each result to `progress` as it finishes.
std::vector<CheckResult> runCheckCases(Evaluator& rig, const std::vector<CheckCase>& cases,
                                       const std::function<std::string(const CheckCase&)>& diffPath,
                                       const std::function<void(const CheckResult&)>& progress);

// A result in the report (fields documented in docs/check.md).
nlohmann::json checkJson(const CheckResult& r);
// The result checkJson described (a worker's rows and a kept record's come back this way):
// checkJson of it is the same JSON. The expectation is found again in `book` by its stable id
// (expectations.json "id"), so an entry whose settings changed since is still found. backend and
// machine are not in the JSON and stay empty. Throws std::invalid_argument on a malformed one.
CheckResult checkResultFromJson(const nlohmann::json& j,
                                const std::vector<Expectation>& book = expectations());

// The same result with its message and note within kMaxRowMessage, its file list within
// kMaxListedFiles and its reasons within kMaxReasons (src/grade/bounds.h): whatever a worker
// sends, a row stays small.
void boundResult(CheckResult& r);

}  // namespace sl
