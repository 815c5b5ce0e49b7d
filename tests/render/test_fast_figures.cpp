// The fast figures (metrics/shadow_truth, metrics/distance, PixelRays, the evaluator's per-view
// caches) against the code they replaced (slow_figures.h, the evaluator's old shadowEvidence
// below), bit for bit, on real renders with the real reference: our shaders and students'
// overlays, both trees, a lesson's map size, a displaced view, the fixed-function stage (its own
// baseline). One evaluator serves every case in turn, as it serves a class, so its caches are
// reused across overlays and views and must never hand one case another's truth.
#include <gtest/gtest.h>

#include <cstring>

#include "eval/evaluator.h"
#include "metrics/mirror_metrics.h"
#include "platform/headless.h"
#include "render_fixture.h"
#include "slow_figures.h"
#include "stages/registry.h"

using namespace sl;

namespace {

bool sameBits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;  // NaN is NaN; 0 and -0 differ
}

void expectSameFigures(const ShadowFigures& fast, const ShadowFigures& slow,
                       const std::string& what) {
#define SL_SAME_BITS(f) \
    EXPECT_TRUE(sameBits(fast.f, slow.f)) << what << ": " #f " " << fast.f << " vs " << slow.f
    SL_SAME_BITS(falseShadowPct);
    SL_SAME_BITS(falseLitPct);
    SL_SAME_BITS(falseShadowBandPct);
    SL_SAME_BITS(falseLitBandPct);
    SL_SAME_BITS(darkWithoutCasterPct);
    SL_SAME_BITS(falseShadowSpecklePct);
    SL_SAME_BITS(shadowLevelOffPct);
    SL_SAME_BITS(litLightLostPct);
    SL_SAME_BITS(litTooBrightPct);
    SL_SAME_BITS(edgeMeanPx);
    SL_SAME_BITS(edgeP95Px);
#undef SL_SAME_BITS
    EXPECT_EQ(fast.edgeDefined, slow.edgeDefined) << what;
    EXPECT_EQ(fast.evaluated, slow.evaluated) << what;
    EXPECT_EQ(fast.truthLit, slow.truthLit) << what;
    EXPECT_EQ(fast.truthShadow, slow.truthShadow) << what;
    EXPECT_EQ(fast.litOutside, slow.litOutside) << what;
    EXPECT_EQ(fast.shadowOutside, slow.shadowOutside) << what;
    EXPECT_EQ(fast.renderedBoundary, slow.renderedBoundary) << what;
    EXPECT_EQ(fast.trueBoundary, slow.trueBoundary) << what;
    EXPECT_TRUE(fast.band == slow.band) << what << ": the edge band differs";
    EXPECT_TRUE(fast.evaluatedMask == slow.evaluatedMask)
        << what << ": the evaluated pixels differ";
}

// A renderer of our shipped shaders over a variant of the stage's scene, as the evaluator made
// them (one per context).
std::unique_ptr<Renderer> shipped(Renderer& r, Scene scene, int height) {
    GlslTree tree = r.shaders().tree();
    return std::make_unique<Renderer>(
        std::move(scene), ShaderLibrary(tree, shaderTreeRoot(tree), ""), height, stageInfos());
}

Image renderWith(HeadlessContext& context, const Renderer& r, Renderer& other,
                 const std::string& stage) {
    other.selectStage(stage);
    other.camera = r.camera;
    other.lightPosition = r.lightPosition;
    other.view = ViewMode::Final;
    other.allLit = false;
    other.render(context.framebuffer(), context.width(), context.height());
    return context.read();
}

struct SlowEvidence {
    Image withShadows;
    Image withShadowsAgain;  // the stage drawn once more after the others (the mirror's "shown")
    std::vector<std::uint8_t> shadowed;
    ShadowFigures figures;
    ReferenceImage reference;
};

// Evaluator::shadowEvidence as it was (src/eval/evaluator.cpp at b11b40d): a fresh context, the
// stage's renderer and our three shipped ones, every render drawn, the slow figures.
SlowEvidence slowEvidence(const RenderRequest& request, Evaluator::EdgeTolerance tolerance) {
    auto context =
        createHeadlessContext(Backend::Auto, request.tree, request.width, request.height);
    installGlDebugOutput(true);
    RenderRequest q = request;
    q.scene = effectiveScene(request);
    q.sceneGiven = true;
    std::unique_ptr<Renderer> stage = makeRenderer(q);
    Renderer& r = *stage;
    const int w = request.width, h = request.height;
    SlowEvidence s;
    s.reference = traceReference(r.scene(), r.camera, r.lightPosition, w, h);
    const ReferenceImage& ref = s.reference;
    r.allLit = false;
    r.render(context->framebuffer(), w, h);
    s.withShadows = context->read();
    r.allLit = true;
    r.render(context->framebuffer(), w, h);
    Image allLit = context->read();
    r.allLit = false;
    Scene unhighlighted = r.scene();
    unhighlighted.material.specular = 0.0f;
    auto baselineRenderer = shipped(r, unhighlighted, h);
    auto idRenderer = shipped(r, idColouredScene(r.scene()), h);
    auto litRenderer = shipped(r, r.scene(), h);
    const std::string unshadowed = r.stage().unshadowedIsOwn ? "" : lightingStage().id;
    Image baseline =
        unshadowed.empty() ? allLit : renderWith(*context, r, *baselineRenderer, unshadowed);
    ShadowFigureInputs inputs;
    inputs.renderedIds = decodeIdImage(renderWith(*context, r, *idRenderer, "phong"),
                                       int(r.scene().objects.size()), 1.0f);
    ReferenceShades shades = slow::referenceShades(r.scene(), r.camera, ref, r.lightPosition);
    inputs.shadowVisible = slow::shadowVisiblePixels(shades, 1.5f, ClassifyOptions{});
    if (tolerance == Evaluator::EdgeTolerance::MapTexel)
        inputs.bandPx =
            slow::mapTexelOnScreen(ref, r.camera, r.stats.lightViewProjection, r.stats.mapSize);
    inputs.darkWithoutCaster = slow::classifyShadowed(allLit, baseline, ClassifyOptions{});
    inputs.litTooBright = slow::classifyShadowed(renderWith(*context, r, *litRenderer, "phong"),
                                                 allLit, ClassifyOptions{});
    s.shadowed = slow::classifyShadowed(s.withShadows, allLit, ClassifyOptions{});
    for (std::size_t k = 0; k < s.shadowed.size(); ++k)
        s.shadowed[k] = s.shadowed[k] || inputs.darkWithoutCaster[k];
    inputs.shadowLevelOff =
        slow::shadowLevelOff(s.withShadows, allLit, shades, ClassifyOptions{0.10f, 6.0f});
    inputs.lightLost = slow::lightLost(s.withShadows, allLit, shades, 6.0f);
    s.figures = slow::shadowFigures(ref, s.shadowed, inputs);
    r.render(context->framebuffer(), w, h);
    s.withShadowsAgain = context->read();
    return s;
}

std::string overlay(const std::string& student) {
    return std::string(SHADOWLAB_SOURCE_DIR) + "/tests/students/" + student;
}

RenderRequest request(const std::string& stage, GlslTree tree, const std::string& student = "",
                      test::Settings sets = {}) {
    RenderRequest r = test::smallRequest(stage, tree, std::move(sets));
    r.scene = "slides";
    r.sceneGiven = false;  // the stage's own scene, as check draws it
    if (!student.empty()) r.overlay = overlay(student);
    return r;
}

void expectSameAsSlow(Evaluator& rig, const RenderRequest& q, const std::string& what,
                      Evaluator::EdgeTolerance tolerance = Evaluator::EdgeTolerance::MapTexel) {
    SCOPED_TRACE(what);
    SlowEvidence slow = slowEvidence(q, tolerance);
    rig.prepare(q);
    ShadowEvidence fast = rig.shadowEvidence();
    const ReferenceImage& ref = rig.reference();
    // The rays, hence the reference: PixelRays is pixelRay without the per-pixel matrix.
    const PixelRays rays(rig.renderer().camera, q.width, q.height);
    int rayMismatches = 0;
    for (int j = 0; j <= q.height; j += 7)
        for (int i = 0; i <= q.width; ++i) {
            Ray a = rays(i, j), b = slow::pixelRay(rig.renderer().camera, i, j, q.width, q.height);
            rayMismatches += std::memcmp(&a.direction, &b.direction, sizeof a.direction) != 0 ||
                             std::memcmp(&a.origin, &b.origin, sizeof a.origin) != 0;
        }
    EXPECT_EQ(rayMismatches, 0);
    ASSERT_EQ(ref.pixels.size(), slow.reference.pixels.size());
    int referenceMismatches = 0;
    for (std::size_t k = 0; k < ref.pixels.size(); ++k) {
        const ReferencePixel &a = ref.pixels[k], &b = slow.reference.pixels[k];
        referenceMismatches += a.objectId != b.objectId || a.blocked != b.blocked ||
                               a.facesLight != b.facesLight ||
                               a.shadowEdgeAtSilhouette != b.shadowEdgeAtSilhouette ||
                               std::memcmp(&a.position, &b.position, sizeof a.position) != 0;
    }
    EXPECT_EQ(referenceMismatches, 0);
    EXPECT_TRUE(fast.withShadows.rgba == slow.withShadows.rgba) << "the render differs";
    EXPECT_TRUE(slow.withShadowsAgain.rgba == slow.withShadows.rgba)
        << "drawing the stage again changed it (the mirror reuses its first picture)";
    EXPECT_TRUE(fast.shadowed == slow.shadowed) << "the classification differs";
    expectSameFigures(fast.figures, slow.figures, what);
    Image fastDiff = diffImage(ref, fast.shadowed, fast.withShadows, fast.figures.evaluatedMask,
                               fast.figures.band);
    Image slowDiff = slow::diffImage(slow.reference, slow.shadowed, slow.withShadows,
                                     slow.figures.evaluatedMask, slow.figures.band);
    EXPECT_TRUE(fastDiff.rgba == slowDiff.rgba) << "the diff image differs";
}

}  // namespace

TEST(FastFigures, SameBitsAsTheSlowCodeAcrossOverlaysViewsAndLessons) {
    Evaluator rig(Backend::Auto);
    expectSameAsSlow(rig, request("margin", GlslTree::Core), "margin, ours");
    expectSameAsSlow(rig, request("margin", GlslTree::Core, "margin_zero"), "margin, margin_zero");
    expectSameAsSlow(rig, request("margin", GlslTree::Core, "margin_wrong_sign"),
                     "margin, margin_wrong_sign");
    // Three overlays, one view: traced once, our pictures of it drawn once.
    EXPECT_EQ(rig.tracedCount(), 1);
    EXPECT_EQ(rig.shippedViewCount(), 1);
    // Another map size on the same view: the same truth, another band.
    expectSameAsSlow(rig, request("margin", GlslTree::Core, "", {{"map-size", "64"}}),
                     "margin, map-size 64");
    expectSameAsSlow(rig, request("depth", GlslTree::Core, "depth_black_shadows"),
                     "depth, depth_black_shadows");
    expectSameAsSlow(rig, request("phong", GlslTree::Core, "phong_flat_white"),
                     "phong, phong_flat_white");
    // The other tree: our pictures drawn again by its shaders.
    expectSameAsSlow(rig, request("hardware", GlslTree::Legacy, "hw_black_shadows_legacy"),
                     "hardware legacy, hw_black_shadows_legacy");
    EXPECT_EQ(rig.tracedCount(), 1);
    EXPECT_EQ(rig.shippedViewCount(), 2);
    // The fixed-function stage is its own baseline.
    expectSameAsSlow(rig, request("fixed", GlslTree::Legacy), "fixed legacy");
    // Two displaced views of the same stage: another scene each, never the first one's truth.
    RenderRequest displaced = request("margin", GlslTree::Core, "margin_tan_clamp");
    displaced.displaceSeed = 7;
    expectSameAsSlow(rig, displaced, "margin displaced 7, margin_tan_clamp");
    displaced.displaceSeed = 8;
    expectSameAsSlow(rig, displaced, "margin displaced 8, margin_tan_clamp");
    // The mirror stage in its own scene, and back to the first view.
    expectSameAsSlow(rig, request("mirror", GlslTree::Core, "mirror_tint_after_branch"),
                     "mirror, mirror_tint_after_branch");
    expectSameAsSlow(rig, request("margin", GlslTree::Core, "margin_zero"),
                     "margin again, margin_zero");
}

TEST(FastFigures, SameBitsAsTheSlowCodeAtFullSizeToThePixel) {
    // The bench and sweeps measure to the pixel (no map-texel band), at the charts' size.
    Evaluator rig(Backend::Auto, Evaluator::EdgeTolerance::Pixel);
    RenderRequest q = request("rgb", GlslTree::Core, "", {{"margin", "0"}});
    q.width = 640, q.height = 480;
    expectSameAsSlow(rig, q, "rgb 640x480 margin 0", Evaluator::EdgeTolerance::Pixel);
}

TEST(FastFigures, OurShadersAreMeasuredOnceAConfiguration) {
    // check measures our shaders in each displaced view for every student's bounds.
    Evaluator rig(Backend::Auto);
    RenderRequest ours = request("margin", GlslTree::Core);
    ours.displaceSeed = 7;
    RenderRequest finer = ours;
    finer.sets = {{"map-size", "2048"}};
    auto expectSame = [](const Accuracy& a, const Accuracy& b, const std::string& what) {
        EXPECT_TRUE(sameBits(a.falseShadowPct, b.falseShadowPct)) << what;
        EXPECT_TRUE(sameBits(a.falseLitPct, b.falseLitPct)) << what;
        EXPECT_TRUE(sameBits(a.edgeMeanPx, b.edgeMeanPx)) << what;
        EXPECT_TRUE(sameBits(a.edgeP95Px, b.edgeP95Px)) << what;
        EXPECT_TRUE(sameBits(a.litLightLostPct, b.litLightLostPct)) << what;
        EXPECT_TRUE(sameBits(a.falseShadowBandPct, b.falseShadowBandPct)) << what;
    };
    rig.prepare(ours);
    const Accuracy first = rig.accuracy();
    expectSame(first,
               shadowAccuracy(slowEvidence(ours, Evaluator::EdgeTolerance::MapTexel).figures),
               "ours");
    rig.prepare(finer);
    const Accuracy second = rig.accuracy();
    expectSame(second,
               shadowAccuracy(slowEvidence(finer, Evaluator::EdgeTolerance::MapTexel).figures),
               "ours, map-size 2048");
    EXPECT_FALSE(sameBits(first.edgeP95Px, second.edgeP95Px) &&
                 sameBits(first.falseShadowBandPct, second.falseShadowBandPct))
        << "another map size measures the same: the test shows nothing";
    // A student in between, then ours again: measured twice in all, for the two settings.
    rig.prepare(request("margin", GlslTree::Core, "margin_zero"));
    rig.accuracy();
    rig.prepare(ours);
    expectSame(rig.accuracy(), first, "ours again");
    rig.prepare(finer);
    expectSame(rig.accuracy(), second, "ours again, map-size 2048");
    EXPECT_EQ(rig.oursMeasuredCount(), 2);
}
