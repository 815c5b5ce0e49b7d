// The figures a check measures, named once (GUIDE section 4): the name every report,
// expectations.json, bench.csv and sweep CSV use, the unit, which way is better, and the words a
// student's page says. Everything that lists, writes, reads or explains a figure reads this table.
#pragma once

#include <cmath>
#include <string>
#include <vector>

namespace sl {

// The accuracy figures of one render (GUIDE section 4). Non-applicable ones stay NaN.
struct Accuracy {
    double falseShadowPct = NAN, falseLitPct = NAN;
    double falseShadowBandPct = NAN, falseLitBandPct = NAN;
    double edgeMeanPx = NAN, edgeP95Px = NAN;
    double darkWithoutCasterPct = NAN, falseShadowSpecklePct = NAN, shadowLevelOffPct = NAN;
    double litLightLostPct = NAN, litTooBrightPct = NAN;
    double mirrorIdPct = NAN, mirrorPsnrDb = NAN;
    // One number for charts, not judged (so not in the table): shadow stages the balanced error
    // (false shadow % + false lit %) / 2 outside the edge band; the mirror 100 - id agreement %.
    double errorPct = NAN;
};

enum class Better { Lower, Higher };

// Which figures a kind of output shows: bench and sweep chart the shadow figures (and bench the
// mirror's); the look figures only judge.
enum class FigureKind {
    Shadow,  // pixel classification against the truth, and the edge distance
    Look,    // what the picture looks like where the classification cannot tell
    Mirror   // the mirror against the reference's bounce and the stencil reflection
};

struct FigureInfo {
    const char* name;  // "false_shadow_pct": the unit is its suffix
    double Accuracy::*field;
    const char* unit;  // "%", "px", "dB"
    Better better;
    FigureKind kind;
    const char* words;  // what it measures, as a page's sentence says it: "<words> is 3 %"
    // False for a figure added after records were first kept: a kept record without it reads it
    // as not measured (NaN); without any other figure it is not a record of ours.
    bool inEveryRecord = true;
};

// Every figure, in the order reports and error messages list them.
const std::vector<FigureInfo>& figureTable();
// The figure named `name`, or nullptr.
const FigureInfo* findFigure(const std::string& name);
// The names of the figures of `kind`, in table order.
std::vector<std::string> figureNamesOf(FigureKind kind);

}  // namespace sl
