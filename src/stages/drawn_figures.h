// Our shaders' figures in drawn rows (stages/drawn.h) at a fixed set of seeds, shipped as data
// (src/stages/drawn_figures.json), as the displaced views' bounds are (stages/displaced_bounds.h).
// A student edition has only stubs to draw with: it picks its drawn rows' seed from this set and
// holds the student's render to these figures by the same rule as the grader (judgeDrawn). Only
// figures, never code: the file holds the figures the rows' tolerances name, per setting.
// Written by scripts/measure_drawn_figures.py from `check --shaders <the solution>` reports.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "stages/drawn.h"

namespace sl {

struct ShippedDrawn {
    std::string drawn;                      // "slope-k=0.0061 slope-min=0.0021": the values drawn
    std::map<std::string, double> figures;  // by figure name: our shaders' figures there
};

// <data dir>/src/stages/drawn_figures.json
std::string drawnFiguresPath();

// The seeds the data covers, in the file's order. Throws ExpectationError on a malformed file.
const std::vector<std::uint64_t>& shippedDrawnSeeds();

// The seed a student edition draws its drawn rows at for a run's `seed`: `seed` itself when the
// data has it, else the data's seed number (seed mod its count). `seed` when the data has none.
std::uint64_t shippedDrawnSeed(std::uint64_t seed);

// Our figures for `row` (in `tree`) at `seed`, or null when the data has none for them.
const ShippedDrawn* shippedDrawnOf(const DrawnRow& row, const std::string& tree,
                                   std::uint64_t seed);

// "drawn" values as the data writes them: the drawn settings of `row` at `seed`, "NAME=VALUE"
// separated by spaces (drawnSettings without the row's fixed ones).
std::string drawnValuesText(const DrawnRow& row, std::uint64_t seed);

}  // namespace sl
