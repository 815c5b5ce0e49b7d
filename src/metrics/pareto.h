// Helpers for the benchmark: which settings are worth their cost, and where quality breaks.
#pragma once

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

}  // namespace sl
