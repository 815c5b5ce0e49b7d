#include "grade/case_judge.h"

#include "grade/judge.h"
#include "stages/displaced_bounds.h"
#include "stages/drawn.h"
#include "stages/drawn_figures.h"
#include "stages/request.h"

namespace sl {

namespace {

// "slope-k=0.0061 slope-min=0.0021": the drawn parameters' values, as --set takes them.
std::string drawnValues(const DrawnRow& row, const ParamSet& values) {
    std::string text;
    for (const DrawnParam& d : row.draw)
        text += (text.empty() ? "" : " ") + d.name + "=" + values.text(d.name);
    return text;
}

// Our figures shipped for `row` at `seed` when they are for these very values (a --set that
// repeats the seed's row), else null: the student edition cannot render ours.
const ShippedDrawn* shippedDrawnAt(const DrawnRow& row, const std::string& tree, std::uint64_t seed,
                                   const ParamSet& values) {
    const ShippedDrawn* data = shippedDrawnOf(row, tree, seed);
    if (!data || data->drawn != drawnValuesText(row, seed)) return nullptr;
    ParamSet expected(values.specs());
    for (const auto& [name, value] : drawnSettings(row, seed)) expected.set(name, value);
    for (const DrawnParam& d : row.draw)
        if (expected.text(d.name) != values.text(d.name)) return nullptr;
    return data;
}

std::string seedList(const std::vector<std::uint64_t>& seeds) {
    std::string text;
    for (std::uint64_t s : seeds) text += (text.empty() ? "" : ", ") + std::to_string(s);
    return text.empty() ? "none" : text;
}

// Our figures shipped for values `row` covers at `seed`: its own, or those of its entry's second
// row (drawn at the same seed, its response's parameter moved), else null.
const ShippedDrawn* shippedDrawnFor(const DrawnRow& row, const std::string& tree,
                                    std::uint64_t seed, const ParamSet& values) {
    if (const ShippedDrawn* data = shippedDrawnAt(row, tree, seed, values)) return data;
    for (const DrawnRow* second : drawnRowsOf(row.stage, tree))
        if (pairedRowOf(*second) == &row)
            if (const ShippedDrawn* data = shippedDrawnAt(*second, tree, seed, values)) return data;
    return nullptr;
}

// A pair's second row: its own judgement and the pair's, ours for the first row rendered beside
// theirs (`paired.ours`) or shipped as data in a student edition (none: the pair is a SKIP).
Judgement withPair(const RenderRequest& request, const CheckResult& r, Judgement own,
                   const std::map<std::string, double>& oursHere, const PairedRow& paired) {
    const DrawnResponse& response = *paired.second->response;
    const DrawnRow& first = *pairedRowOf(*paired.second);
    std::map<std::string, double> oursFirst = paired.ours;
    if (isStudentEdition(request.tree)) {
        const ShippedDrawn* data =
            shippedDrawnAt(first, r.tree, *request.displaceSeed, paired.values);
        oursFirst = data ? data->figures : std::map<std::string, double>();
    } else if (request.overlay.empty()) {
        oursFirst = paired.theirs;  // ours laid over nothing: theirs are ours
    }
    return withResponse(std::move(own), judgeResponse(response, paired.from, paired.theirs,
                                                      r.figureMap(), oursFirst, oursHere));
}

// A drawn row's judgement: against our figures at the same values and view, rendered here
// (`shipped`) or, in a student edition, shipped as data for the seed (none: a SKIP); a pair's
// second row also by its pair (withPair).
Judgement judgeDrawnCase(const RenderRequest& request, const CheckResult& r, const DrawnRow& row,
                         const std::map<std::string, double>* shipped, const PairedRow* paired) {
    const std::map<std::string, double> theirs = r.figureMap();
    const std::string values = drawnValues(row, r.parameters);
    // Our figures: rendered beside theirs, or theirs when they are ours (no folder laid over);
    // a student edition's own shaders are stubs, never a measure (the data below, folder or not).
    if (shipped || !isStudentEdition(request.tree)) {
        const std::map<std::string, double>& ours = shipped ? *shipped : theirs;
        Judgement own = judgeDrawn(row, values, theirs, ours);
        return paired ? withPair(request, r, std::move(own), ours, *paired) : own;
    }
    const std::uint64_t seed = *request.displaceSeed;
    const ShippedDrawn* data = shippedDrawnFor(row, r.tree, seed, r.parameters);
    if (!data)
        return {Status::Skip,
                "drawn " + values + " at seed " + std::to_string(seed) +
                    ": this student edition ships our figures only at the values "
                    "drawn at seeds " +
                    seedList(shippedDrawnSeeds()) + " (" + drawnFiguresPath() +
                    "); the grader judges it",
                {}};
    Judgement j = judgeDrawn(row, values, theirs, data->figures);
    if (paired) j = withPair(request, r, std::move(j), data->figures, *paired);
    j.message += " [student edition: our figures shipped for seed " + std::to_string(seed) +
                 ", one of " + std::to_string(shippedDrawnSeeds().size()) +
                 " (src/stages/drawn_figures.json); the grader draws at its own seed]";
    return j;
}

}  // namespace

// The row's judgement once measured (its expectation found): a drawn row against ours, a
// displaced one against the wider of the lesson's and the solution's, else the lesson's bounds.
Judgement judgeCase(const RenderRequest& request, const CheckResult& r,
                    const std::map<std::string, double>* shipped, const PairedRow* paired) {
    // Settings no lesson names but a drawn row covers (the seed's, or the same typed with --set):
    // held to ours at the same values, not to the defaults' lesson.
    const DrawnRow* drawn = request.displaceSeed && !r.expectation.exact
                                ? drawnRowFor(r.stage, r.scene, r.tree, r.parameters)
                                : nullptr;
    if (drawn) return judgeDrawnCase(request, r, *drawn, shipped, paired);
    const Expectation& lesson = *r.expectation.entry;
    const std::map<std::string, double> theirs = r.figureMap();
    // Ours in a displaced view: theirs when they are ours, never a student edition's stubs.
    const bool theirsAreOurs = request.overlay.empty() && !isStudentEdition(request.tree);
    Judgement j =
        request.displaceSeed
            ? judgeDisplaced(lesson, theirs, displacedFiguresOf(r.stage, r.tree, lesson.label()),
                             theirsAreOurs ? &theirs : shipped)
            : judge(lesson, theirs);
    if (!r.expectation.exact)
        j.message += " [no entry for these settings: judged by the defaults' lesson]";
    return j;
}

}  // namespace sl
