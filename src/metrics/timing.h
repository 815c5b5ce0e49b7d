// Summaries of frame times for the benchmark: the median and how far the frames spread.
#pragma once

#include <cmath>
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

// A cost ratio measured in short interleaved blocks (configuration against a baseline in the
// same block): the median of the per-block ratios and their quartiles. Load that drifts over the
// run hits both sides of a block alike, so the per-block ratio cancels it; what is left shows as
// the spread.
struct RatioSummary {
    int blocks = 0;
    double median = NAN, p25 = NAN, p75 = NAN;
    double iqr() const { return p75 - p25; }
    // The spread relative to the ratio: the IQR over the median (NaN without blocks).
    double relativeSpread() const { return blocks ? iqr() / median : NAN; }
    // Whether the ratio is tight enough to publish as a figure.
    bool trusted(double maxRelativeSpread = kMaxRelativeSpread) const {
        return blocks >= 3 && relativeSpread() <= maxRelativeSpread;
    }
    static constexpr double kMaxRelativeSpread = 0.10;
};

// Per-block ratios config[k] / base[k] (block medians, say), summarised. Blocks where either
// side is missing or not positive are skipped. Unequal lengths use the shorter.
RatioSummary summarizeRatios(const std::vector<double>& config, const std::vector<double>& base);

// ABBA order of interleaved blocks: block 0 runs the baseline first, block 1 the configuration
// first, and so on, so a drift within a block favours neither side over the run.
inline bool configFirst(int block) {
    return block % 2 == 1;
}

}  // namespace sl
