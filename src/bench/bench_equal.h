// The bench's equal-accuracy group: for each method, the cheapest configuration (map size, light
// fit; the filter is part of the method's name) reaching edge p95 <= 2 px and error <= 0.1 % on
// the lecture scene at 640x480. Accuracy first (every candidate), then cost (only those that
// reach the bar, timed beside phong with the light moving: the map is re-rendered every frame,
// so its size shows in the cost).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "bench/bench_report.h"
#include "metrics/equal_accuracy.h"

namespace sl {

// The candidates searched: each method at map sizes 256..2048 and fits tight/sphere/fixed
// (quick: 256 and 1024, tight only). `series` is the method; configurations whose series does not
// contain `only` are left out.
std::vector<BenchConfig> equalAccuracyCandidates(bool quick, GlslTree tree,
                                                 const std::string& only);

// One row per method: group "equal-accuracy" with the cheapest configuration reaching the bar,
// or "equal-accuracy-unreached" with the candidate that came closest (timed all the same).
std::vector<Measured> searchEqualAccuracy(BenchRig& rig, const std::vector<BenchConfig>& candidates,
                                          int framesPerBlock, int blocks, const AccuracyBar& bar,
                                          const std::function<void(const std::string&)>& progress);

}  // namespace sl
