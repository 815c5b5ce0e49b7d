// Rows whose settings the run's seed draws (expectations.json "drawn"): a stage's method
// parameters (margin, slope k/min/max, map size, polygon offset, filter, depth format) drawn
// within each lesson's meaningful range and seen from the displaced view. Such a row has no
// lesson bounds of its own: the student's render is held to our shipped shaders' render at the
// same values (grade/judge.h, judgeDrawn). A shader that ignores a uniform its method uses, or
// recognises a lesson by a uniform's value or textureSize, cannot follow values nobody chose.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "stages/expectations.h"

namespace sl {

// One drawn parameter: a number or integer drawn in [min, max], or one of `choices`.
struct DrawnParam {
    std::string name;
    double min = 0, max = 0;
    std::vector<std::string> choices;  // non-empty for a choice parameter
};

// How far a figure of theirs may be from ours: within [ours / factor - abs, ours * factor + abs]
// (a factor, not a difference: acne percentages of valid formulations differ by ratios).
struct DrawnTolerance {
    std::string figure;
    double abs = 0, factor = 1;
};

// The second row of a drawn entry (expectations.json "response"): the same settings and view but
// one drawn number, `param`, moved by a ratio r the seed draws in [ratioMin, ratioMax] (times r,
// or divided by r where that would leave the range). One picture cannot tell a constant from the
// value it happens to be near; a pair can: a constant renders the same picture at both values,
// where ours changes. Besides its own band, the change of `change.figure` from the first row to
// this one is held to ours (grade/judge.h, judgeResponse).
struct DrawnResponse {
    std::string param;
    double ratioMin = 1, ratioMax = 1;
    DrawnTolerance change;  // the figure whose change is judged, and the band's slack
};

struct DrawnRow {
    std::string stage;
    std::string scene;                                     // "" = the stage's default scene
    std::vector<std::string> trees;                        // empty = every tree
    std::vector<std::pair<std::string, std::string>> set;  // fixed settings (margin-kind=slope)
    std::vector<DrawnParam> draw;
    std::vector<DrawnTolerance> tolerances;
    std::string why;
    std::optional<DrawnResponse> response;  // set on an entry's second row only
    // "margin margin-kind=slope": the entry's fixed part, the same for every seed and both rows
    std::string entryLabel() const;
    // entryLabel(), and " response:PARAM" for an entry's second row ("depth response:margin")
    std::string label() const;
};

// Parses the data file's "drawn" list (absent = none); checks stages, parameters and ranges
// against the registry and figure names against figureNames(). `origin` names the file. An
// entry with a "response" gives two rows, the entry's and its second (DrawnResponse), in order.
std::vector<DrawnRow> parseDrawnRows(const std::string& text, const std::string& origin);
const std::vector<DrawnRow>& drawnRows();  // from expectationsPath(), loaded once
std::vector<const DrawnRow*> drawnRowsOf(const std::string& stage, const std::string& tree);

// The first row of the pair whose second is `row` (its DrawnResponse set), from drawnRows():
// null for a row that is no entry's second.
const DrawnRow* pairedRowOf(const DrawnRow& row);

// The settings of `row` for `seed`: its fixed ones, then each drawn one (numbers to two
// significant digits, three where the range would hold fewer than 20 values; integers to a
// multiple of 64 where the range allows), never a number the stage's default or a lesson names
// (drawn again: a shader that recognises the lesson's map size or margin must not meet it). The
// same on every platform (mt19937_64's output is fixed; the mapping is ours). An entry's second
// row draws the same values, then its response's parameter moved by the ratio its seed draws
// (to the same digits, within the range, never the first row's value nor a lesson's).
std::vector<std::pair<std::string, std::string>> drawnSettings(const DrawnRow& row,
                                                               std::uint64_t seed);

// The row covering `values` in (stage, scene, tree): its fixed settings equal, its drawn ones
// within their ranges, every other parameter at its default. nullptr when none does. An entry's
// second row is never returned: its values are within its first row's, judged alone by its band.
const DrawnRow* drawnRowFor(const std::string& stage, const std::string& scene,
                            const std::string& tree, const ParamSet& values);

}  // namespace sl
