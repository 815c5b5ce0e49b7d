#include "metrics/equal_accuracy.h"

#include <cmath>

namespace sl {

bool meetsBar(const Candidate& c, const AccuracyBar& bar) {
    return c.edgeP95Px <= bar.maxEdgeP95Px && c.errorPct <= bar.maxErrorPct;  // NaN: false
}

std::vector<MethodVerdict> cheapestAtEqualAccuracy(const std::vector<Candidate>& candidates,
                                                   const AccuracyBar& bar) {
    std::vector<MethodVerdict> out;
    auto verdictFor = [&](const std::string& method) -> MethodVerdict& {
        for (MethodVerdict& v : out)
            if (v.method == method) return v;
        out.push_back({method, std::nullopt, std::nullopt});
        return out.back();
    };
    auto nearer = [](const Candidate& a, const Candidate& b) {  // a nearer the bar than b
        if (std::isnan(b.errorPct)) return !std::isnan(a.errorPct);
        if (a.errorPct != b.errorPct) return a.errorPct < b.errorPct;
        return !std::isnan(a.edgeP95Px) && (std::isnan(b.edgeP95Px) || a.edgeP95Px < b.edgeP95Px);
    };
    for (std::size_t k = 0; k < candidates.size(); ++k) {
        const Candidate& c = candidates[k];
        MethodVerdict& v = verdictFor(c.method);
        if (!v.closest || nearer(c, candidates[*v.closest])) v.closest = k;
        if (!meetsBar(c, bar) || std::isnan(c.cost)) continue;
        if (!v.cheapest || c.cost < candidates[*v.cheapest].cost) v.cheapest = k;
    }
    return out;
}

}  // namespace sl
