// The bench series the stages declare (StageDefinition::benchSeries): each is named after its
// stage, its settings and the axis bench adds are parameters the stage declares with allowed
// values, names are unique in a group, benchSeriesIn keeps its documented order, and a speed
// target is one the summary can state. A typo in a stage file fails here, not mid-bench.
#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "stages/registry.h"

namespace sl {
namespace {

const BenchGroup kGroups[] = {BenchGroup::MapSize, BenchGroup::Format, BenchGroup::Mirror,
                              BenchGroup::EqualAccuracy};

// The settings bench appends to a series of the group (cmd_bench.cpp, bench_equal.cpp), at one
// of the values it uses.
std::vector<std::pair<std::string, std::string>> axisOf(BenchGroup group) {
    switch (group) {
        case BenchGroup::MapSize:
        case BenchGroup::Format:
            return {{"map-size", "1024"}};
        case BenchGroup::EqualAccuracy:
            return {{"map-size", "256"}, {"light-fit", "sphere"}};
        case BenchGroup::Mirror:
            return {};
    }
    return {};
}

std::size_t stageIndex(const StageDefinition* s) {
    return static_cast<std::size_t>(s - stageRegistry().data());
}

TEST(BenchSeries, NamedAfterTheirStage) {
    for (BenchGroup g : kGroups)
        for (const StageSeries& s : benchSeriesIn(g)) {
            const std::string& name = s.series->name;
            EXPECT_TRUE(name == s.stage->id || name.rfind(s.stage->id + "/", 0) == 0)
                << name << " declared by stage " << s.stage->id;
        }
}

TEST(BenchSeries, SettingsAndAxisAreDeclaredParameters) {
    for (BenchGroup g : kGroups)
        for (const StageSeries& s : benchSeriesIn(g)) {
            ParamSet params(s.stage->params);
            auto sets = s.series->sets;
            for (const auto& setting : axisOf(g)) sets.push_back(setting);
            for (const auto& [name, value] : sets)
                EXPECT_EQ(params.set(name, value), "")
                    << s.series->name << " (" << benchGroupName(g) << "): " << name << "=" << value;
        }
}

TEST(BenchSeries, NamesAreUniqueInAGroup) {
    for (BenchGroup g : kGroups) {
        std::set<std::string> seen;
        for (const StageSeries& s : benchSeriesIn(g))
            EXPECT_TRUE(seen.insert(s.series->name).second)
                << s.series->name << " twice in " << benchGroupName(g);
    }
}

TEST(BenchSeries, OrderedByRankThenStageThenDeclaration) {
    std::size_t total = 0;
    for (BenchGroup g : kGroups) {
        std::vector<StageSeries> in = benchSeriesIn(g);
        for (std::size_t k = 1; k < in.size(); ++k) {
            const StageSeries &a = in[k - 1], &b = in[k];
            auto key = [](const StageSeries& s) {
                std::size_t declared =
                    static_cast<std::size_t>(s.series - s.stage->benchSeries.data());
                return std::make_tuple(s.series->rank, stageIndex(s.stage), declared);
            };
            EXPECT_LT(key(a), key(b)) << a.series->name << " before " << b.series->name;
        }
        total += in.size();
    }
    // Every declared series is in exactly one group's list.
    std::size_t declared = 0;
    for (const StageDefinition& s : stageRegistry()) declared += s.benchSeries.size();
    EXPECT_EQ(total, declared);
}

TEST(BenchSeries, TargetsCanBeStated) {
    for (BenchGroup g : kGroups)
        for (const StageSeries& s : benchSeriesIn(g))
            for (const BenchTarget& t : s.series->targets) {
                EXPECT_FALSE(t.what.empty()) << s.series->name;
                ASSERT_FALSE(t.bounds.empty()) << s.series->name;
                for (const BenchBound& b : t.bounds) {
                    EXPECT_GT(b.atMost, 0.0) << s.series->name << ": " << b.words;
                    EXPECT_NE(b.words.find("{ratio}"), std::string::npos)
                        << s.series->name << ": " << b.words;
                }
                if (t.mapSize != 0) {
                    ParamSet params(s.stage->params);
                    EXPECT_EQ(params.set("map-size", std::to_string(t.mapSize)), "")
                        << s.series->name;
                }
            }
}

}  // namespace
}  // namespace sl
