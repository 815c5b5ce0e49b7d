// Summaries of frame times for the benchmark: the median and how far the frames spread.
#pragma once

#include <vector>

namespace sl {

struct TimeSummary {
    int count = 0;
    double median = 0, min = 0, max = 0;
    double p25 = 0, p75 = 0;  // quartiles (nearest rank); iqr = p75 - p25 is the spread we quote
    double iqr() const { return p75 - p25; }
};

// Nearest-rank percentile q in [0, 1] of `values` (any order). 0 for an empty list.
double percentile(std::vector<double> values, double q);

// Median (mean of the two middle values for an even count), min, max and quartiles.
// An empty list gives count 0 and zeros.
TimeSummary summarize(const std::vector<double>& values);

}  // namespace sl
