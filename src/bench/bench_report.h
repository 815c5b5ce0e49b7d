// What `bench` writes: bench.csv and bench.json (one row per configuration and light mode), the
// charts (error against time with each method's Pareto front, time against map size and against
// window size) and a summary with the speed targets.
#pragma once

#include <string>
#include <vector>

#include "bench/bench_run.h"

namespace sl {

struct Measured {
    BenchConfig config;
    std::string scene;
    PassTimes still, moving;
    PassTimes phongStill, phongMoving;     // phong measured in blocks alternating with this one
    RatioSummary ratioStill, ratioMoving;  // per-block ratios to phong (median, spread)
    Accuracy accuracy;
    // `bench --instructions`: callgrind's instructions per frame and their ratio to phong's in the
    // same context (NaN when not counted).
    struct Instructions {
        double still = NAN, moving = NAN, ratioStill = NAN, ratioMoving = NAN;
    } instructions;
    const RatioSummary& ratios(bool movingLight) const {
        return movingLight ? ratioMoving : ratioStill;
    }
    double ratio(bool movingLight) const { return ratios(movingLight).median; }
    // Takes the times of a configuration measured beside phong, still light and moving.
    void setTimes(const BenchRig::Paired& stillLight, const BenchRig::Paired& movingLight) {
        still = stillLight.config;
        phongStill = stillLight.phong;
        ratioStill = stillLight.ratio;
        moving = movingLight.config;
        phongMoving = movingLight.phong;
        ratioMoving = movingLight.ratio;
    }
};

// "tree/scene/WxH": configurations with the same key share a context and a phong baseline.
std::string contextKey(const BenchConfig& c, const std::string& scene);

struct BenchReport {
    std::string summary;       // the table printed at the end
    std::string chartProblem;  // "" or why the charts are missing
};

// Writes bench.csv, bench.json, the chart data and charts into `dir`.
BenchReport writeBenchReport(const std::string& dir, const std::string& machine,
                             const std::vector<Measured>& results);

}  // namespace sl
