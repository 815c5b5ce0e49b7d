// What the solution measures in displaced views (src/stages/displaced_bounds.json): for each
// stage, tree and lesson, the lowest and highest value of each figure over the displaced views
// of the seeds listed there. Shipped as data (never the solutions), so a student edition, which
// has no solution to draw, holds a displaced row to the same bounds as the grader: one grading
// truth. Written by scripts/measure_displaced_bounds.py from `check --all --seed S` reports.
#pragma once

#include <map>
#include <string>

namespace sl {

struct FigureRange {
    double lowest = 0, highest = 0;
};
using DisplacedFigures = std::map<std::string, FigureRange>;  // by figure name

// <data dir>/src/stages/displaced_bounds.json
std::string displacedBoundsPath();

// The solution's range of each figure in displaced views of `stage`/`tree` under the lesson
// labelled `lesson` (Expectation::label()), or null when the data has no entry for it (then
// the lesson's own bounds judge alone). Throws ExpectationError on a malformed file.
const DisplacedFigures* displacedFiguresOf(const std::string& stage, const std::string& tree,
                                           const std::string& lesson);

}  // namespace sl
