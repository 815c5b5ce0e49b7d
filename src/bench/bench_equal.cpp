#include "bench/bench_equal.h"

#include <map>

namespace sl {

std::vector<BenchConfig> equalAccuracyCandidates(bool quick, GlslTree tree,
                                                 const std::string& only) {
    struct Method {
        std::string series, stage;
        std::vector<std::pair<std::string, std::string>> sets;
    };
    const std::vector<Method> methods = {
        {"hardware/linear", "hardware", {}},
        {"hardware/nearest", "hardware", {{"filter", "nearest"}}},
        {"hardware/pcf3x3", "hardware", {{"filter", "pcf3x3"}}},
        {"margin/constant", "margin", {}},
        {"depth", "depth", {}},
        {"peers/learnopengl", "peers", {{"method", "learnopengl"}}},
        {"peers/opengl-tutorial", "peers", {{"method", "opengl-tutorial"}}},
        {"peers/normal-offset", "peers", {{"method", "normal-offset"}}},
    };
    std::vector<int> sizes =
        quick ? std::vector<int>{256, 1024} : std::vector<int>{256, 512, 1024, 2048};
    // not a stage id: the light fit "fixed" (--set light-fit)
    const std::vector<std::string> allFits = {"tight", "sphere", "fixed"};
    std::vector<std::string> fits = quick ? std::vector<std::string>{"tight"} : allFits;
    std::vector<BenchConfig> out;
    for (const Method& m : methods) {
        if (m.series.find(only) == std::string::npos) continue;
        for (const std::string& fit : fits)
            for (int size : sizes) {
                BenchConfig c;
                c.group = "equal-accuracy";
                c.series = m.series;
                c.stage = m.stage;
                c.tree = tree;
                c.sets = m.sets;
                c.sets.emplace_back("map-size", std::to_string(size));
                c.sets.emplace_back("light-fit", fit);
                out.push_back(c);
            }
    }
    return out;
}

std::vector<Measured> searchEqualAccuracy(BenchRig& rig, const std::vector<BenchConfig>& candidates,
                                          int framesPerBlock, int blocks, const AccuracyBar& bar,
                                          const std::function<void(const std::string&)>& progress) {
    std::vector<Candidate> found;
    std::vector<Accuracy> accuracy;
    for (const BenchConfig& c : candidates) {
        rig.prepare(c);
        Accuracy a = rig.accuracy();
        accuracy.push_back(a);
        found.push_back({c.series, c.setsText(), a.edgeP95Px, a.errorPct, NAN});
    }
    // Cost only where the accuracy is reached: the moving-light ratio to phong.
    std::map<std::size_t, BenchRig::Paired> moving;
    for (std::size_t k = 0; k < candidates.size(); ++k) {
        if (!meetsBar(found[k], bar)) continue;
        moving[k] = rig.timeBesidePhong(candidates[k], framesPerBlock, blocks, true);
        found[k].cost = moving[k].ratio.median;
        progress(candidates[k].series + " " + candidates[k].setsText() +
                 " reaches the bar: " + std::to_string(found[k].cost) + "x phong moving");
    }
    std::vector<Measured> out;
    for (const MethodVerdict& v : cheapestAtEqualAccuracy(found, bar)) {
        std::size_t k = v.cheapest ? *v.cheapest : *v.closest;
        BenchConfig c = candidates[k];
        c.group = v.cheapest ? "equal-accuracy" : "equal-accuracy-unreached";
        Measured m{c, c.sceneName(), {}, {}, {}, {}, {}, {}, accuracy[k], {}};
        auto still = rig.timeBesidePhong(candidates[k], framesPerBlock, blocks, false);
        auto move = moving.count(k)
                        ? moving[k]
                        : rig.timeBesidePhong(candidates[k], framesPerBlock, blocks, true);
        m.setTimes(still, move);
        progress(c.group + " " + c.series + ": " + c.setsText());
        out.push_back(m);
    }
    return out;
}

}  // namespace sl
