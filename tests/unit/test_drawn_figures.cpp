// Our figures in drawn rows, shipped as data for the student edition (stages/drawn_figures.h):
// every drawn row of every stage and tree has them at every shipped seed, for the values the seed
// draws today and every figure its tolerance names (else rerun scripts/measure_drawn_figures.py),
// and a run's seed maps into the shipped set.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include "stages/drawn.h"
#include "stages/drawn_figures.h"
#include "stages/registry.h"
#include "stages/stage.h"

namespace sl {
namespace {

void useSourceTree() {
    setenv("SHADOWLAB_DATA_DIR", SHADOWLAB_SOURCE_DIR, 1);
}

TEST(DrawnFigures, EveryDrawnRowHasOurFiguresAtEveryShippedSeed) {
    useSourceTree();
    const std::vector<std::uint64_t>& seeds = shippedDrawnSeeds();
    ASSERT_FALSE(seeds.empty()) << drawnFiguresPath();
    std::size_t checked = 0, rows = 0;
    for (const StageInfo& info : stageRegistry())
        for (const char* tree : {"core", "legacy"})
            for (const DrawnRow* row : drawnRowsOf(info.id, tree)) {
                if (info.legacyOnly && std::string(tree) == "core") continue;
                ++rows;
                for (std::uint64_t seed : seeds) {
                    const ShippedDrawn* data = shippedDrawnOf(*row, tree, seed);
                    ASSERT_NE(data, nullptr) << row->label() << " (" << tree << ") seed " << seed;
                    EXPECT_EQ(data->drawn, drawnValuesText(*row, seed))
                        << row->label() << " (" << tree << ") seed " << seed
                        << ": the seed draws other values now";
                    for (const DrawnTolerance& t : row->tolerances)
                        EXPECT_TRUE(data->figures.count(t.figure))
                            << row->label() << " seed " << seed << ": no " << t.figure;
                    ++checked;
                }
            }
    EXPECT_EQ(checked, rows * seeds.size());
    EXPECT_GT(rows, 0u);
}

TEST(DrawnFigures, ARunsSeedMapsIntoTheShippedSet) {
    useSourceTree();
    const std::vector<std::uint64_t>& seeds = shippedDrawnSeeds();
    ASSERT_FALSE(seeds.empty());
    for (std::uint64_t s : seeds) EXPECT_EQ(shippedDrawnSeed(s), s) << "a shipped seed is kept";
    for (std::uint64_t s : {std::uint64_t(0), std::uint64_t(4242), std::uint64_t(278778061542)}) {
        std::uint64_t at = shippedDrawnSeed(s);
        EXPECT_NE(std::find(seeds.begin(), seeds.end(), at), seeds.end()) << s << " -> " << at;
        EXPECT_EQ(shippedDrawnSeed(s), at) << "the same run's seed, the same shipped one";
    }
}

}  // namespace
}  // namespace sl
