// Cost at equal accuracy: a fair comparison of methods fixes the accuracy first (edge p95 and
// error under a bar), then asks which configuration of each method reaches it most cheaply.
#pragma once

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace sl {

struct AccuracyBar {
    double maxEdgeP95Px = 2.0;
    double maxErrorPct = 0.1;
};

// One searched configuration of a method. `cost` is what "cheapest" compares: any positive
// measure (instructions per frame when counted, else a time ratio); NaN when unknown.
struct Candidate {
    std::string method, settings;
    double edgeP95Px = NAN, errorPct = NAN, cost = NAN;
};

// Whether a candidate reaches the bar (a NaN figure does not).
bool meetsBar(const Candidate& c, const AccuracyBar& bar);

// Per method, in order of first appearance: the index of the cheapest candidate that meets the
// bar (ties: the first), or nullopt when none does; `closest` is then the candidate nearest the
// bar (smallest error, then smallest edge), so a report can say how far each method fell short.
struct MethodVerdict {
    std::string method;
    std::optional<std::size_t> cheapest;
    std::optional<std::size_t> closest;
};
std::vector<MethodVerdict> cheapestAtEqualAccuracy(const std::vector<Candidate>& candidates,
                                                   const AccuracyBar& bar);

}  // namespace sl
