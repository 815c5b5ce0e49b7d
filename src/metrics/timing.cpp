#include "metrics/timing.h"

#include <algorithm>
#include <cmath>

namespace sl {

double percentile(std::vector<double> values, double q) {
    if (values.empty()) return 0;
    std::sort(values.begin(), values.end());
    // Nearest rank: the smallest value with at least q of the list at or below it.
    auto rank = static_cast<std::size_t>(std::ceil(std::clamp(q, 0.0, 1.0) * values.size()));
    return values[rank == 0 ? 0 : rank - 1];
}

TimeSummary summarize(const std::vector<double>& values) {
    TimeSummary s;
    s.count = static_cast<int>(values.size());
    if (values.empty()) return s;
    std::vector<double> v = values;
    std::sort(v.begin(), v.end());
    std::size_t n = v.size();
    s.median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    s.min = v.front();
    s.max = v.back();
    s.p25 = percentile(v, 0.25);
    s.p75 = percentile(v, 0.75);
    return s;
}

RatioSummary summarizeRatios(const std::vector<double>& config, const std::vector<double>& base) {
    std::vector<double> ratios;
    for (std::size_t k = 0; k < std::min(config.size(), base.size()); ++k)
        if (config[k] > 0 && base[k] > 0) ratios.push_back(config[k] / base[k]);
    RatioSummary r;
    if (ratios.empty()) return r;
    TimeSummary t = summarize(ratios);
    r.blocks = t.count;
    r.median = t.median;
    r.p25 = t.p25;
    r.p75 = t.p75;
    return r;
}

}  // namespace sl
