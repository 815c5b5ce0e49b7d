#include "bench/bench_equal.h"

#include <map>

#include "stages/registry.h"

namespace sl {

std::vector<BenchConfig> equalAccuracyCandidates(bool quick, GlslTree tree,
                                                 const std::string& only) {
    std::vector<int> sizes =
        quick ? std::vector<int>{256, 1024} : std::vector<int>{256, 512, 1024, 2048};
    // not a stage id: the light fit "fixed" (--set light-fit)
    const std::vector<std::string> allFits = {"tight", "sphere", "fixed"};
    std::vector<std::string> fits = quick ? std::vector<std::string>{"tight"} : allFits;
    std::vector<BenchConfig> out;
    // The methods: each stage's equal-accuracy series (StageDefinition::benchSeries).
    for (const StageSeries& m : benchSeriesIn(BenchGroup::EqualAccuracy)) {
        if (m.series->name.find(only) == std::string::npos) continue;
        for (const std::string& fit : fits)
            for (int size : sizes) {
                BenchConfig c;
                c.group = benchGroupName(BenchGroup::EqualAccuracy);
                c.series = m.series->name;
                c.stage = m.stage->id;
                c.tree = tree;
                c.sets = m.series->sets;
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
