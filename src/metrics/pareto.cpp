#include "metrics/pareto.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace sl {

namespace {

bool dominates(const CostError& a, const CostError& b) {
    bool noWorse = a.cost <= b.cost && a.error <= b.error;
    bool better = a.cost < b.cost || a.error < b.error;
    return noWorse && better;
}

}  // namespace

std::vector<std::size_t> paretoFront(const std::vector<CostError>& points) {
    // A direct check of every pair: benchmark sweeps have tens of points, and this reads as the
    // definition does.
    std::vector<std::size_t> front;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (std::isnan(points[i].cost) || std::isnan(points[i].error)) continue;
        bool dominated = false;
        for (std::size_t j = 0; j < points.size() && !dominated; ++j)
            dominated = j != i && dominates(points[j], points[i]);
        if (!dominated) front.push_back(i);
    }
    std::sort(front.begin(), front.end(), [&](std::size_t a, std::size_t b) {
        if (points[a].cost != points[b].cost) return points[a].cost < points[b].cost;
        if (points[a].error != points[b].error) return points[a].error < points[b].error;
        return a < b;
    });
    return front;
}

double breakPoint(const std::vector<double>& xs, const std::vector<double>& errors,
                  double threshold) {
    if (xs.size() != errors.size())
        throw std::invalid_argument("breakPoint: xs and errors differ in length");
    for (std::size_t k = 0; k < xs.size(); ++k)
        if (errors[k] > threshold) return xs[k];
    return std::numeric_limits<double>::quiet_NaN();
}

WorkingRange workingRange(const std::vector<double>& xs, const std::vector<double>& errors,
                          double threshold) {
    if (xs.size() != errors.size())
        throw std::invalid_argument("workingRange: xs and errors differ in length");
    WorkingRange r;
    std::size_t best = xs.size();
    for (std::size_t k = 0; k < xs.size(); ++k)
        if (!std::isnan(errors[k]) && (best == xs.size() || errors[k] < errors[best])) best = k;
    if (best == xs.size()) return r;
    r.best = xs[best];
    r.bestError = errors[best];
    if (!(errors[best] <= threshold)) return r;
    r.works = true;
    // NaN never exceeds in breakPoint, so treat it as broken explicitly with +infinity.
    auto broken = [](double e) { return std::isnan(e) ? INFINITY : e; };
    std::vector<double> afterX, afterE, beforeX, beforeE;
    for (std::size_t k = best; k < xs.size(); ++k) {
        afterX.push_back(xs[k]);
        afterE.push_back(broken(errors[k]));
    }
    for (std::size_t k = best + 1; k-- > 0;) {
        beforeX.push_back(xs[k]);
        beforeE.push_back(broken(errors[k]));
    }
    r.breaksAfter = breakPoint(afterX, afterE, threshold);
    r.breaksBefore = breakPoint(beforeX, beforeE, threshold);
    // The last working value on each side is the one just before the break (or the end).
    auto lastWorking = [&](const std::vector<double>& x, double brk) {
        for (std::size_t k = 1; k < x.size(); ++k)
            if (x[k] == brk) return x[k - 1];
        return x.back();
    };
    r.to = std::isnan(r.breaksAfter) ? afterX.back() : lastWorking(afterX, r.breaksAfter);
    r.from = std::isnan(r.breaksBefore) ? beforeX.back() : lastWorking(beforeX, r.breaksBefore);
    return r;
}

}  // namespace sl
