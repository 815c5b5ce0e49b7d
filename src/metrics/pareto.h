// Helpers for the benchmark: which settings are worth their cost, and where quality breaks.
#pragma once

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace sl {

struct CostError {
    double cost;
    double error;
    std::string label;
};

// Indices of the non-dominated points, sorted by cost (then error, then index). A point is
// dominated when another is no worse in both cost and error and better in at least one; so
// exact duplicates do not dominate each other and are all kept. Points with a NaN cost or error
// cannot be compared and are left out.
std::vector<std::size_t> paretoFront(const std::vector<CostError>& points);

// The first xs[k], scanning in the given order (ascending or descending), whose errors[k]
// exceeds `threshold` (strictly). NaN when none does (a NaN error never exceeds). Throws
// std::invalid_argument when the two lists differ in length.
double breakPoint(const std::vector<double>& xs, const std::vector<double>& errors,
                  double threshold);

// Where a method works along a swept axis. From the best point (smallest error, the first on a
// tie) the range extends each way while the error stays at or under `threshold`; the break points
// are the first values beyond it that exceed the threshold (found with breakPoint, scanning
// outward), NaN when the sweep never breaks on that side. `works` is false (and everything NaN
// but best) when even the best point is above the threshold. NaN errors count as broken.
struct WorkingRange {
    bool works = false;
    double best = NAN, bestError = NAN;
    double from = NAN, to = NAN;  // the working values, in the order of xs
    double breaksBefore = NAN, breaksAfter = NAN;
};
WorkingRange workingRange(const std::vector<double>& xs, const std::vector<double>& errors,
                          double threshold);

}  // namespace sl
