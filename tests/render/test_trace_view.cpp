// The browser's check traces its references in Web Workers from views found without GL
// (eval/trace_view.h) and hands them to its Evaluator by key. Every row `check` grades must look
// its reference up by the key its request's view predicts (else the page traces it again on its
// own thread), and a reference traced from the view must be the Evaluator's own, byte for byte.
#include <gtest/gtest.h>

#include "eval/evaluator.h"
#include "eval/trace_view.h"
#include "grade/check_run.h"
#include "stages/registry.h"

using namespace sl;

namespace {

constexpr std::uint64_t kSeed = 7;

// Every row `check --all --seed 7 --shaders OUR_TREE` grades in the core tree: each lesson from
// each view, the displaced views and the drawn rows (an overlay brings those).
std::vector<CheckCase> everyCoreRow() {
    std::vector<CheckCase> all;
    for (const StageDefinition& stage : stageRegistry()) {
        if (stage.legacyOnly) continue;
        RenderRequest base;
        base.stage = stage.id;
        base.tree = GlslTree::Core;
        base.overlay = shaderTreeRoot(GlslTree::Core);
        for (CheckCase& c : checkCases(base, false, false, kSeed)) all.push_back(std::move(c));
    }
    return all;
}

}  // namespace

TEST(TraceView, EveryRowLooksUpTheKeyItsViewPredicts) {
    Evaluator rig(Backend::Auto);
    std::size_t displaced = 0;
    const std::vector<CheckCase> rows = everyCoreRow();
    ASSERT_GT(rows.size(), stageRegistry().size());
    // Found as the page's check finds them: all at once, each scene loaded once.
    std::vector<const RenderRequest*> requests;
    for (const CheckCase& c : rows) requests.push_back(&c.request);
    const std::vector<std::optional<TraceView>> views = traceViewsOf(requests);
    ASSERT_EQ(views.size(), rows.size());
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const CheckCase& c = rows[k];
        rig.prepare(c.request);
        ASSERT_TRUE(views[k].has_value()) << c.request.stage << " " << c.view;
        EXPECT_EQ(rig.currentTraceKey(), traceKey(*views[k]))
            << c.request.stage << " " << c.view << " " << c.lesson;
        displaced += c.request.displaceSeed.has_value();
    }
    EXPECT_GT(displaced, 0u);  // the displaced and drawn views are among them
}

TEST(TraceView, AGivenReferenceIsUsedAndGradesAsTracedHere) {
    // A mirror stage's displaced view (camera and mirror moved) and a shadow stage's drawn row.
    std::vector<CheckCase> picked;
    for (const CheckCase& c : everyCoreRow())
        if (c.request.displaceSeed &&
            (stageNeedsMirror(c.request.stage) ? picked.empty() : picked.size() == 1))
            picked.push_back(c);
    ASSERT_EQ(picked.size(), 2u);
    for (const CheckCase& c : picked) {
        Evaluator here(Backend::Auto), given(Backend::Auto);
        const TraceView view = traceViewOf(c.request);
        const ReferenceImage traced = traceView(view);
        const std::string bytes = referenceBytes(traced);
        given.giveReference(traceKey(view),
                            referenceFromBytes(traced.width, traced.height, traced.mirrorObjectId,
                                               bytes.data(), bytes.size()));
        nlohmann::json a = checkJson(runCheck(here, c.request, ""));
        nlohmann::json b = checkJson(runCheck(given, c.request, ""));
        EXPECT_EQ(given.givenUsedCount(), 1) << c.request.stage << " " << c.view;
        EXPECT_EQ(given.tracedCount(), 0) << c.request.stage << " " << c.view;
        EXPECT_EQ(here.tracedCount(), 1);
        a.erase("seconds");
        b.erase("seconds");
        EXPECT_EQ(a, b) << c.request.stage << " " << c.view;
        EXPECT_EQ(referenceBytes(here.reference()), bytes) << c.request.stage << " " << c.view;
    }
}

TEST(TraceView, TheViewCrossesAsJsonAndTheReferenceAsBytes) {
    RenderRequest r;
    r.stage = stageRegistry().front().id;
    r.displaceSeed = 18446744073709551557ull;  // a seed past a double's exact integers
    const TraceView v = traceViewOf(r);
    EXPECT_EQ(traceKey(traceViewFromJson(nlohmann::json::parse(traceViewJson(v).dump()))),
              traceKey(v));
    EXPECT_THROW(traceViewFromJson({{"scene", "slides"}}), std::invalid_argument);
    ReferenceImage small;
    small.width = 2;
    small.height = 1;
    small.pixels.resize(2);
    small.pixels[1].objectId = 3;
    const std::string bytes = referenceBytes(small);
    EXPECT_EQ(referenceFromBytes(2, 1, -1, bytes.data(), bytes.size()).pixels[1].objectId, 3);
    EXPECT_THROW(referenceFromBytes(2, 2, -1, bytes.data(), bytes.size()), std::invalid_argument);
}
