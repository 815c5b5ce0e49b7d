// A row's verdict from its figures: the lesson's bounds (src/stages/expectations.json) held
// against what was measured. The data says what a stage must show; the verdict is made here,
// in grade/, and nowhere else.
#pragma once

#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "grade/status.h"
#include "stages/displaced_bounds.h"
#include "stages/drawn.h"
#include "stages/expectations.h"

namespace sl {

// One side of one bound the judge held a figure to: the verdict's reasons as data, so a page
// renders them without reading the message (GUIDE section 6: pages never parse messages). A
// range (both a floor and a ceiling) is two of these, one per side.
struct FigureReason {
    enum class Side { AtLeast, AtMost };  // value >= bound, value <= bound
    std::string figure;                   // the figure table's name (metrics/figures.h)
    double value = NAN;                   // what was measured; NaN: not measured
    Side side = Side::AtMost;
    double bound = NAN;   // as held: a displaced view's widened bound, a drawn row's from ours
    bool passed = false;  // the value is on the bound's side (never for a value not measured)
    // A drawn pair's (judgeResponse): `value` is the figure's change from the first row, drawn at
    // these values ("margin=0.00053"); empty: the figure itself.
    std::string changeFrom;
    bool operator==(const FigureReason& o) const;
};
// ">=" or "<=", as the report writes a side; and back (nullopt for anything else).
const char* sideName(FigureReason::Side side);
std::optional<FigureReason::Side> sideFromName(const std::string& name);

struct Judgement {
    Status status = Status::Skip;       // PASS, FAIL, or SKIP (a bounded figure not measured)
    std::string message;                // why, in one line
    std::vector<FigureReason> reasons;  // every bound held, in the lesson's order of its limits
};

Judgement judge(const Expectation& e, const std::map<std::string, double>& figures);

// A displaced view is one nobody chose: its casters, light and camera may land where a lesson's
// bounds, measured over the curated views, are out of reach for any method (a shadow stretched
// at a grazing angle has a staircase edge wider than two pixels). There the submission is held
// to the lesson's bounds or to what the solution measures over displaced views (`ours`, shipped
// as data: stages/displaced_bounds.h; its extreme a quarter further, at least 0.5), whichever is
// wider. The same data at home and in the grader: a student edition judges as `grade` does.
// Where our shaders are the solution (not a student edition), `oursHere`, their figures in this
// very view, widen the range too: the data's twelve seeds do not hold every view's tail (the
// peers stage's edge p95 reached 26.7 px at one seed against 1.05 over the twelve), and a
// correct shader must never fail where ours would. Null `ours`: the lesson's bounds alone.
Judgement judgeDisplaced(const Expectation& e, const std::map<std::string, double>& theirs,
                         const DisplacedFigures* ours,
                         const std::map<std::string, double>* oursHere = nullptr);

// A row whose settings the seed drew (stages/drawn.h) has no lesson bounds of its own: each
// figure the row's tolerance names is held to ours at the same values and view, within
// [ours / factor - abs, ours * factor + abs] (the spread of valid formulations). The message names
// the drawn values, so `check --set NAME=VALUE ... --seed S` repeats the row.
Judgement judgeDrawn(const DrawnRow& row, const std::string& drawnValues,
                     const std::map<std::string, double>& theirs,
                     const std::map<std::string, double>& ours);

// The pair of a drawn entry's two rows (stages/drawn.h, DrawnResponse): the change of the
// response's figure from the first row (at `from`, "margin=0.00053") to the second, theirs held
// to ours within [d / factor - abs, d * factor + abs] (d = ours' change; mirrored when d < 0). A
// constant renders the same picture at both values (change 0), a quantizer jumps where ours
// moves a little. Judged only where ours changes by more than factor * abs: below that the band
// holds 0, and no pair of pictures tells a constant from the method (a SKIP that says so). The
// message says "FIGURE change from PARAM=VALUE"; the reason is FIGURE with its changeFrom.
Judgement judgeResponse(const DrawnResponse& response, const std::string& from,
                        const std::map<std::string, double>& theirsFirst,
                        const std::map<std::string, double>& theirsSecond,
                        const std::map<std::string, double>& oursFirst,
                        const std::map<std::string, double>& oursSecond);

// A second row's verdict from its own (judgeDrawn) and its pair's (judgeResponse): FAIL when
// either fails, the reasons of both; a pair not judged leaves the row's own, saying why.
Judgement withResponse(Judgement own, const Judgement& pair);

}  // namespace sl
