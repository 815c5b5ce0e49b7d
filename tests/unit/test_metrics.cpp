#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "eval/evaluator.h"
#include "metrics/mirror_metrics.h"
#include "metrics/pareto.h"
#include "metrics/shadow_metrics.h"

using namespace sl;

namespace {

// A reference where every pixel is on object 1 and faces the light; tests then carve it up.
ReferenceImage evaluatedEverywhere(int w, int h) {
    ReferenceImage ref;
    ref.width = w;
    ref.height = h;
    ref.pixels.resize(std::size_t(w) * h);
    for (ReferencePixel& p : ref.pixels) {
        p.objectId = 1;
        p.facesLight = true;
    }
    return ref;
}

ReferencePixel& pixel(ReferenceImage& ref, int i, int j) {
    return ref.pixels[std::size_t(j) * ref.width + i];
}

// Marks the rectangle [i0, i1) x [j0, j1): truth (blocked) in the reference, or a rendered mask.
void blockRect(ReferenceImage& ref, int i0, int j0, int i1, int j1) {
    for (int j = j0; j < j1; ++j)
        for (int i = i0; i < i1; ++i) pixel(ref, i, j).blocked = true;
}
std::vector<std::uint8_t> maskRect(int w, int h, int i0, int j0, int i1, int j1) {
    std::vector<std::uint8_t> mask(std::size_t(w) * h, 0);
    for (int j = j0; j < j1; ++j)
        for (int i = i0; i < i1; ++i) mask[std::size_t(j) * w + i] = 1;
    return mask;
}

void setGrey(Image& image, int i, int j, int level) {
    std::uint8_t* p = image.at(i, j);
    p[0] = p[1] = p[2] = std::uint8_t(level);
    p[3] = 255;
}

void expectColor(const Image& image, int i, int j, int r, int g, int b) {
    const std::uint8_t* p = image.at(i, j);
    EXPECT_EQ(p[0], r) << "at " << i << "," << j;
    EXPECT_EQ(p[1], g) << "at " << i << "," << j;
    EXPECT_EQ(p[2], b) << "at " << i << "," << j;
    EXPECT_EQ(p[3], 255);
}

}  // namespace

TEST(Metrics, SquareShadowShiftedTwoPixelsRight) {
    // Truth: the 10 x 10 square [10, 20)^2. Rendered: the same square two columns to the right.
    ReferenceImage ref = evaluatedEverywhere(40, 40);
    blockRect(ref, 10, 10, 20, 20);
    ShadowFigures f = shadowFigures(ref, maskRect(40, 40, 12, 10, 22, 20));
    EXPECT_EQ(f.evaluated, 1600);
    EXPECT_EQ(f.truthShadow, 100);
    EXPECT_EQ(f.truthLit, 1500);
    // Band: the pixels with a 4-neighbour of the other truth: the square's 36 perimeter pixels
    // and the 40 pixels of the ring around it less its corners.
    // False shadow: columns 20, 21 (rows 10..19). Column 20 lies in the outer ring.
    EXPECT_NEAR(f.falseShadowPct, 100.0 * 10 / (1500 - 40), 1e-9);
    EXPECT_NEAR(f.falseShadowBandPct, 100.0 * 10 / 40, 1e-9);
    // False lit: columns 10, 11. All of column 10 and rows 10, 19 of column 11 are perimeter;
    // 8 pixels of column 11 are among the 64 interior ones.
    EXPECT_NEAR(f.falseLitPct, 100.0 * 8 / 64, 1e-9);
    EXPECT_NEAR(f.falseLitBandPct, 100.0 * 12 / 36, 1e-9);
    // Boundaries: the shadow-side perimeters, 36 each. Distances from the true one to the
    // rendered one: top and bottom rows 2, 1, 0 x 8; left column (x = 10, rows 11..18) 2 x 8;
    // right column (x = 19) 1, 2, 2, 2, 2, 2, 2, 1 (the rendered top and bottom rows pass
    // through x = 19). Sum 3 + 3 + 16 + 14 = 36 over 36 pixels: mean 1. The 35th of 36 is 2.
    EXPECT_EQ(f.trueBoundary, 36);
    EXPECT_EQ(f.renderedBoundary, 36);
    EXPECT_TRUE(f.edgeDefined);
    EXPECT_NEAR(f.edgeMeanPx, 1.0, 1e-9);
    EXPECT_NEAR(f.edgeP95Px, 2.0, 1e-9);
}

TEST(Metrics, ErrorsAreCountedOnTheObjectTheyLieOn) {
    // Two objects side by side: id 1 on the left half, id 2 on the right. Truth: nothing blocked.
    // Rendered: specks at (5, 5) and (6, 15) on object 1 and a block [25, 30) x [0, 4) on object 2.
    ReferenceImage ref = evaluatedEverywhere(40, 20);
    for (int j = 0; j < 20; ++j)
        for (int i = 20; i < 40; ++i) pixel(ref, i, j).objectId = 2;
    std::vector<std::uint8_t> shown = maskRect(40, 20, 25, 0, 30, 4);
    shown[5 * 40 + 5] = shown[15 * 40 + 6] = 1;
    ShadowFigures f = shadowFigures(ref, shown);
    ASSERT_EQ(f.byObject.size(), 3u);  // ids 0 (background), 1, 2
    EXPECT_EQ(f.byObject[1].lit, 400);
    EXPECT_EQ(f.byObject[1].falseShadow, 2);
    EXPECT_EQ(f.byObject[2].lit, 400);
    EXPECT_EQ(f.byObject[2].falseShadow, 20);
    EXPECT_EQ(f.byObject[0].lit + f.byObject[0].shadow, 0);
    long lit = 0, wrong = 0;
    for (const ShadowFigures::ObjectCounts& o : f.byObject) lit += o.lit, wrong += o.falseShadow;
    EXPECT_EQ(lit, f.litOutside);
    EXPECT_NEAR(f.falseShadowPct, 100.0 * wrong / lit, 1e-9);
}

TEST(Metrics, StraightEdgeShiftedTwoPixelsIsTwoPixelsOff) {
    // Truth: everything left of x = 10 in shadow; rendered: left of x = 12.
    ReferenceImage ref = evaluatedEverywhere(30, 20);
    blockRect(ref, 0, 0, 10, 20);
    ShadowFigures f = shadowFigures(ref, maskRect(30, 20, 0, 0, 12, 20));
    EXPECT_EQ(f.trueBoundary, 20);      // column 9
    EXPECT_EQ(f.renderedBoundary, 20);  // column 11
    EXPECT_NEAR(f.edgeMeanPx, 2.0, 1e-9);
    EXPECT_NEAR(f.edgeP95Px, 2.0, 1e-9);
    // Column 10 is in the band (lit side), column 11 is not: 20 of 20 * 20 - 20 lit outside.
    EXPECT_NEAR(f.falseShadowPct, 100.0 * 20 / 380, 1e-9);
    EXPECT_NEAR(f.falseShadowBandPct, 100.0, 1e-9);
    EXPECT_EQ(f.falseLitPct, 0.0);
    EXPECT_EQ(f.falseLitBandPct, 0.0);
}

TEST(Metrics, PerfectRenderHasNoErrors) {
    ReferenceImage ref = evaluatedEverywhere(30, 20);
    blockRect(ref, 5, 5, 15, 12);
    ShadowFigures f = shadowFigures(ref, maskRect(30, 20, 5, 5, 15, 12));
    EXPECT_EQ(f.falseShadowPct, 0.0);
    EXPECT_EQ(f.falseLitPct, 0.0);
    EXPECT_EQ(f.falseShadowBandPct, 0.0);
    EXPECT_EQ(f.falseLitBandPct, 0.0);
    EXPECT_EQ(f.edgeMeanPx, 0.0);
    EXPECT_EQ(f.edgeP95Px, 0.0);
    EXPECT_EQ(f.trueBoundary, f.renderedBoundary);
}

TEST(Metrics, EdgeDistanceIsUndefinedWithoutBoundaries) {
    ReferenceImage ref = evaluatedEverywhere(10, 10);  // no shadow at all
    ShadowFigures f = shadowFigures(ref, maskRect(10, 10, 2, 2, 5, 5));
    EXPECT_FALSE(f.edgeDefined);
    EXPECT_EQ(f.edgeMeanPx, -1.0);
    EXPECT_EQ(f.edgeP95Px, -1.0);
    EXPECT_EQ(f.trueBoundary, 0);
    EXPECT_EQ(f.renderedBoundary, 9 - 1);  // the 3 x 3 square's perimeter
    EXPECT_EQ(f.falseLitPct, 0.0);         // no truth-shadowed pixels: 0, not NaN
    EXPECT_NEAR(f.falseShadowPct, 100.0 * 9 / 100, 1e-9);
}

TEST(Metrics, BackgroundMirrorAndPixelsFacingAwayAreIgnored) {
    // One row: background, shadowed, lit, mirror, facing away.
    ReferenceImage ref = evaluatedEverywhere(5, 1);
    ref.mirrorObjectId = 7;
    pixel(ref, 0, 0).objectId = 0;
    pixel(ref, 1, 0).blocked = true;
    pixel(ref, 3, 0).objectId = 7;
    pixel(ref, 3, 0).blocked = true;
    pixel(ref, 4, 0).facesLight = false;
    pixel(ref, 4, 0).blocked = true;
    std::vector<std::uint8_t> allShadowed(5, 1);
    ShadowFigures f = shadowFigures(ref, allShadowed);
    EXPECT_EQ(f.evaluated, 2);
    EXPECT_EQ(f.truthShadow, 1);
    EXPECT_EQ(f.truthLit, 1);
    EXPECT_EQ(f.falseShadowBandPct, 100.0);  // pixel 2 is next to the true edge
    EXPECT_EQ(f.falseShadowPct, 0.0);
    EXPECT_EQ(f.trueBoundary, 1);
    // Every evaluated pixel is rendered shadowed: no rendered boundary, even next to the
    // background and the mirror.
    EXPECT_EQ(f.renderedBoundary, 0);
    EXPECT_FALSE(f.edgeDefined);

    Image render(5, 1);
    Image diff = diffImage(ref, allShadowed, render);
    expectColor(diff, 0, 0, 255, 255, 255);
    expectColor(diff, 3, 0, 255, 255, 255);
    expectColor(diff, 4, 0, 255, 255, 255);
}

TEST(Metrics, SizeMismatchesAreRejected) {
    ReferenceImage ref = evaluatedEverywhere(4, 4);
    EXPECT_THROW(shadowFigures(ref, std::vector<std::uint8_t>(15)), std::invalid_argument);
    EXPECT_THROW(diffImage(ref, std::vector<std::uint8_t>(16), Image(4, 3)), std::invalid_argument);
    EXPECT_THROW(classifyShadowed(Image(4, 4), Image(4, 3)), std::invalid_argument);
}

TEST(Metrics, DistanceTransformMatchesBruteForce) {
    const int w = 23, h = 17;
    std::vector<std::uint8_t> feature(w * h, 0);
    unsigned state = 12345;  // a fixed pseudo-random pattern, about 1 pixel in 16
    for (auto& f : feature) {
        state = state * 1103515245u + 12345u;
        f = (state >> 16) % 16 == 0;
    }
    std::vector<float> d = distanceToFeatures(feature, w, h);
    int features = 0;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            double best = std::numeric_limits<double>::infinity();
            for (int fj = 0; fj < h; ++fj)
                for (int fi = 0; fi < w; ++fi)
                    if (feature[fj * w + fi]) best = std::min(best, std::hypot(fi - i, fj - j));
            features += feature[j * w + i];
            ASSERT_NEAR(d[j * w + i], best, 1e-5) << "at " << i << "," << j;
        }
    EXPECT_GT(features, 5);

    std::vector<float> none = distanceToFeatures(std::vector<std::uint8_t>(12, 0), 4, 3);
    for (float v : none) EXPECT_TRUE(std::isinf(v));
}

TEST(Metrics, ClassificationNeedsBothDrops) {
    Image lit(4, 1), shadows(4, 1);
    // Grey levels, so luma equals the level.
    setGrey(lit, 0, 0, 100), setGrey(shadows, 0, 0, 84);  // -16 %, -16 levels: shadowed
    setGrey(lit, 1, 0, 100), setGrey(shadows, 1, 0, 86);  // -14 %: not enough
    setGrey(lit, 2, 0, 30), setGrey(shadows, 2, 0, 20);   // -33 %, -10 levels: shadowed
    setGrey(lit, 3, 0, 30), setGrey(shadows, 3, 0, 25);   // -17 % but only -5 levels: not
    std::vector<std::uint8_t> s = classifyShadowed(shadows, lit);
    EXPECT_EQ(s, (std::vector<std::uint8_t>{1, 0, 1, 0}));

    ClassifyOptions loose;
    loose.relativeDrop = 0.10f;
    loose.absoluteDrop = 4.0f;
    EXPECT_EQ(classifyShadowed(shadows, lit, loose), (std::vector<std::uint8_t>{1, 1, 1, 1}));
    // Brighter than all-lit is never shadow.
    EXPECT_EQ(classifyShadowed(lit, shadows, loose), (std::vector<std::uint8_t>{0, 0, 0, 0}));
}

TEST(Metrics, DiffImageColours) {
    // Row: false shadow, false lit, agreeing lit (black render), agreeing shadow (white render).
    ReferenceImage ref = evaluatedEverywhere(4, 1);
    pixel(ref, 1, 0).blocked = true;
    pixel(ref, 3, 0).blocked = true;
    std::vector<std::uint8_t> shadowed{1, 0, 0, 1};
    Image render(4, 1);
    setGrey(render, 3, 0, 255);
    Image diff = diffImage(ref, shadowed, render);
    expectColor(diff, 0, 0, 220, 40, 40);
    expectColor(diff, 1, 0, 40, 80, 230);
    expectColor(diff, 2, 0, 60, 60, 60);
    expectColor(diff, 3, 0, 200, 200, 200);
}

TEST(Metrics, PsnrInMask) {
    Image a(3, 1), b(3, 1);
    std::vector<std::uint8_t> mask{1, 1, 0};
    EXPECT_EQ(psnrInMask(a, b, mask), kPsnrIdentical);
    EXPECT_EQ(psnrInMask(a, b, mask), 99.0);
    b.at(2, 0)[1] = 200;  // outside the mask
    b.at(1, 0)[3] = 7;    // alpha does not count
    EXPECT_EQ(psnrInMask(a, b, mask), 99.0);
    // One red sample off by 10 among 2 pixels x 3 channels: MSE = 100 / 6,
    // PSNR = 10 log10(255^2 * 6 / 100) = 35.9123 dB.
    b.at(0, 0)[0] = 10;
    EXPECT_NEAR(psnrInMask(a, b, mask), 35.9123, 1e-4);
    EXPECT_EQ(psnrInMask(a, b, std::vector<std::uint8_t>(3, 0)), 0.0);
    EXPECT_THROW(psnrInMask(a, Image(2, 1), mask), std::invalid_argument);
}

TEST(Metrics, MirrorIdAgreementAndMask) {
    Scene scene;
    scene.objects.resize(3);  // so the mirror's id is 4
    ReferenceImage ref = evaluatedEverywhere(6, 1);
    ref.mirrorObjectId = mirrorId(scene);
    // Four front mirror pixels seeing 1, 1, background, 3; one mirror back; one plain object.
    int bounces[4] = {1, 1, 0, 3};
    for (int i = 0; i < 4; ++i) {
        pixel(ref, i, 0).objectId = 4;
        pixel(ref, i, 0).bounceObjectId = bounces[i];
    }
    pixel(ref, 4, 0).objectId = 4;  // back: bounceObjectId stays -1
    std::vector<int> rendered{1, 2, 0, -1, 4, 1};
    EXPECT_NEAR(mirrorIdAgreementPct(ref, rendered), 50.0, 1e-9);
    EXPECT_EQ(mirrorMask(ref, scene), (std::vector<std::uint8_t>{1, 1, 1, 1, 0, 0}));

    ReferenceImage noMirror = evaluatedEverywhere(6, 1);
    EXPECT_EQ(mirrorIdAgreementPct(noMirror, rendered), 0.0);
    EXPECT_THROW(mirrorIdAgreementPct(ref, std::vector<int>(5)), std::invalid_argument);
}

TEST(Metrics, ParetoFrontKeepsOnlyUndominatedPoints) {
    std::vector<CostError> points{
        {1.0, 10.0, "a"},  // cheapest but one: on the front
        {2.0, 5.0, "b"},   //
        {3.0, 7.0, "c"},   // b is cheaper and better
        {4.0, 1.0, "d"},   //
        {2.0, 5.0, "e"},   // the same as b: neither dominates the other
        {0.5, 20.0, "f"},  // cheapest of all
        {5.0, 1.0, "g"},   // d has the same error for less
        {1.0, 12.0, "h"},  // a has the same cost and less error
        {std::nan(""), 0.0, "broken"},
    };
    EXPECT_EQ(paretoFront(points), (std::vector<std::size_t>{5, 0, 1, 4, 3}));
    EXPECT_TRUE(paretoFront({}).empty());
    EXPECT_EQ(paretoFront({{3.0, 3.0, "only"}}), (std::vector<std::size_t>{0}));
}

TEST(Metrics, BreakPointScansInTheGivenOrder) {
    std::vector<double> xs{256, 512, 1024, 2048};
    EXPECT_EQ(breakPoint(xs, {0.5, 1.0, 2.5, 9.0}, 2.0), 1024.0);
    EXPECT_EQ(breakPoint(xs, {0.5, 2.0, 2.5, 9.0}, 2.0), 1024.0);  // equal is not above
    EXPECT_TRUE(std::isnan(breakPoint(xs, {0.1, 0.2, 0.3, 0.4}, 2.0)));
    // Descending: map sizes from large to small, error growing as the map shrinks.
    std::vector<double> down{2048, 1024, 512, 256};
    EXPECT_EQ(breakPoint(down, {0.1, 0.4, 3.0, 8.0}, 1.0), 512.0);
    // The first in the given order wins, even if a later one is also above.
    EXPECT_EQ(breakPoint(down, {5.0, 0.4, 3.0, 8.0}, 1.0), 2048.0);
    EXPECT_TRUE(std::isnan(breakPoint({}, {}, 1.0)));
    EXPECT_THROW(breakPoint(xs, {1.0}, 1.0), std::invalid_argument);
}

TEST(Metrics, WorkingRangeOfAMarginSweepHasABreakOnEachSide) {
    // Made-up margin sweep: acne below 0.004, leaking shadows above 0.02.
    std::vector<double> margin{0, 0.002, 0.004, 0.01, 0.02, 0.03, 0.05};
    std::vector<double> error{40, 12, 3, 0.5, 2, 7, 20};
    WorkingRange r = workingRange(margin, error, 5.0);
    EXPECT_TRUE(r.works);
    EXPECT_EQ(r.best, 0.01);
    EXPECT_EQ(r.bestError, 0.5);
    EXPECT_EQ(r.from, 0.004);
    EXPECT_EQ(r.to, 0.02);
    EXPECT_EQ(r.breaksBefore, 0.002);
    EXPECT_EQ(r.breaksAfter, 0.03);
}

TEST(Metrics, WorkingRangeWithoutABreakOrWithoutAWorkingPoint) {
    // Elevation listed from high to low; a method that holds all the way down breaks nowhere.
    std::vector<double> elevation{85, 45, 15, 5, 1};
    WorkingRange holds = workingRange(elevation, {0.2, 0.3, 0.9, 1.5, 2.0}, 5.0);
    EXPECT_TRUE(holds.works);
    EXPECT_EQ(holds.from, 85.0);
    EXPECT_EQ(holds.to, 1.0);
    EXPECT_TRUE(std::isnan(holds.breaksBefore));
    EXPECT_TRUE(std::isnan(holds.breaksAfter));
    // One that fails at grazing light: the break is the first value past the working range.
    WorkingRange grazes = workingRange(elevation, {0.2, 0.3, 6.0, 1.0, 9.0}, 5.0);
    EXPECT_EQ(grazes.to, 45.0);
    EXPECT_EQ(grazes.breaksAfter,
              15.0);  // 5 degrees works again, but the range ends at the first break
    // Never under the threshold: not working, best point still reported.
    WorkingRange never = workingRange(elevation, {9, 8, 7, 8, 9}, 5.0);
    EXPECT_FALSE(never.works);
    EXPECT_EQ(never.best, 15.0);
    EXPECT_TRUE(std::isnan(never.from));
    // A NaN error counts as broken, and lengths must match.
    WorkingRange gap = workingRange({1, 2, 3}, {1, NAN, 1}, 5.0);
    EXPECT_EQ(gap.breaksAfter, 2.0);
    EXPECT_THROW(workingRange({1, 2}, {1}, 5.0), std::invalid_argument);
}

// ---- the mirror's id picture -----------------------------------------------------------------

TEST(IdPicture, ColoursAreDistinctAndBackgroundIsBlack) {
    EXPECT_EQ(idColour(0), glm::vec3(0.0f));
    for (int a = 1; a <= 24; ++a)
        for (int b = a + 1; b <= 24; ++b)
            EXPECT_GT(glm::length(idColour(a) - idColour(b)), 0.05f) << a << " vs " << b;
}

TEST(IdPicture, DecodesScaledColoursToTheirIds) {
    const int maxId = 6;
    Image image(maxId + 1, 1);
    for (int id = 0; id <= maxId; ++id) {
        glm::vec3 c = idColour(id) * kMirrorReflectance * 255.0f;
        for (int k = 0; k < 3; ++k) image.at(id, 0)[k] = std::uint8_t(c[k] + 0.5f);
    }
    std::vector<int> ids = decodeIdImage(image, maxId, kMirrorReflectance);
    for (int id = 0; id <= maxId; ++id) EXPECT_EQ(ids[std::size_t(id)], id);
}

TEST(IdPicture, SceneIsFlatIdColours) {
    Scene scene;
    scene.objects.resize(3);
    Scene painted = idColouredScene(scene);
    EXPECT_EQ(painted.background, glm::vec3(0.0f));
    EXPECT_EQ(painted.material.ambient, 1.0f);
    EXPECT_EQ(painted.material.diffuse, 0.0f);
    EXPECT_EQ(painted.material.specular, 0.0f);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(painted.objects[i].color, idColour(objectId(i)));
}

TEST(Metrics, ShadowEdgeOnASilhouetteIsAnEdge) {
    // The floor ends at x = 20 (background beyond); the truth is shadowed up to that silhouette
    // and the reference marks the boundary as running along it. A render whose shadow stops two
    // pixels short is two pixels off, not a free false-lit strip far from any edge.
    ReferenceImage ref = evaluatedEverywhere(30, 10);
    for (int j = 0; j < 10; ++j)
        for (int i = 20; i < 30; ++i) pixel(ref, i, j).objectId = 0;
    blockRect(ref, 10, 0, 20, 10);
    for (int j = 0; j < 10; ++j) pixel(ref, 19, j).shadowEdgeAtSilhouette = true;
    ShadowFigures f = shadowFigures(ref, maskRect(30, 10, 10, 0, 18, 10));
    EXPECT_EQ(f.trueBoundary, 20);  // column 10 (lit neighbour) and column 19 (silhouette)
    EXPECT_NEAR(f.edgeP95Px, 2.0, 1e-9);
    // Columns 10 and 19 are in the band; column 18 is not: 10 of the 80 shadow pixels outside.
    EXPECT_NEAR(f.falseLitPct, 100.0 * 10 / 80, 1e-9);
    // The same render with the shadow reaching the silhouette agrees everywhere.
    ShadowFigures right = shadowFigures(ref, maskRect(30, 10, 10, 0, 20, 10));
    EXPECT_EQ(right.falseLitPct, 0.0);
    EXPECT_NEAR(right.edgeP95Px, 0.0, 1e-9);
}

TEST(Metrics, PixelsTheRenderGivesToAnotherObjectAreNotEvaluated) {
    // The render shows the background in column 29 where the reference sees the floor: that
    // column is a silhouette difference, neither false lit nor a shadow edge.
    ReferenceImage ref = evaluatedEverywhere(30, 10);
    blockRect(ref, 0, 0, 30, 10);
    ShadowFigureInputs inputs;
    inputs.renderedIds.assign(300, 1);
    for (int j = 0; j < 10; ++j) inputs.renderedIds[std::size_t(j) * 30 + 29] = 0;
    ShadowFigures f = shadowFigures(ref, maskRect(30, 10, 0, 0, 29, 10), inputs);
    EXPECT_EQ(f.evaluated, 290);
    EXPECT_EQ(f.falseLitPct, 0.0);
    EXPECT_EQ(f.renderedBoundary, 0);
    // Without the coverage the column counts as lit.
    EXPECT_GT(shadowFigures(ref, maskRect(30, 10, 0, 0, 29, 10)).falseLitPct, 3.0);
}

TEST(Metrics, ShadowsThatCannotBeSeenAreNotEvaluated) {
    // Columns 20-29 are near a terminator: a shadow there would not show, so the render's "lit"
    // there is neither right nor wrong, and the diff image paints it white.
    ReferenceImage ref = evaluatedEverywhere(30, 10);
    blockRect(ref, 10, 0, 30, 10);
    ShadowFigureInputs inputs;
    inputs.shadowVisible = maskRect(30, 10, 0, 0, 20, 10);
    std::vector<std::uint8_t> render = maskRect(30, 10, 10, 0, 20, 10);
    ShadowFigures f = shadowFigures(ref, render, inputs);
    EXPECT_EQ(f.evaluated, 200);
    EXPECT_EQ(f.falseLitPct, 0.0);
    EXPECT_GT(shadowFigures(ref, render).falseLitPct, 40.0);  // counted without the mask
    Image shown(30, 10);
    Image diff = diffImage(ref, render, shown, f.evaluatedMask, f.band);
    expectColor(diff, 25, 5, 255, 255, 255);
}

TEST(Metrics, DarkWithoutACasterAndSpeckle) {
    ReferenceImage ref = evaluatedEverywhere(20, 20);
    // A checkerboard of false shadow (acne-like specks) over the lit scene ...
    std::vector<std::uint8_t> specks(400, 0);
    for (int j = 0; j < 20; ++j)
        for (int i = 0; i < 20; ++i) specks[std::size_t(j) * 20 + i] = (i + j) % 2;
    ShadowFigureInputs none;
    ShadowFigures acne = shadowFigures(ref, specks, none);
    EXPECT_NEAR(acne.falseShadowPct, 50.0, 1e-9);
    EXPECT_NEAR(acne.falseShadowSpecklePct, 100.0, 1e-9);
    // ... against a solid dark region, dark even with the map forced lit.
    ShadowFigureInputs dark;
    dark.darkWithoutCaster = maskRect(20, 20, 0, 0, 20, 10);
    ShadowFigures solid = shadowFigures(ref, maskRect(20, 20, 0, 0, 20, 10), dark);
    EXPECT_NEAR(solid.falseShadowPct, 50.0, 1e-9);
    EXPECT_NEAR(solid.darkWithoutCasterPct, 50.0, 1e-9);
    EXPECT_NEAR(solid.falseShadowSpecklePct, 100.0 * 20 / 200, 1e-9);  // only its last row
}

TEST(Metrics, BandWidensToOneMapTexelOnScreen) {
    // Truth shadowed left of x = 10; the render stops at x = 7: three pixels short. With one
    // map texel spanning 4 pixels there, that slip is within the map's resolution.
    ReferenceImage ref = evaluatedEverywhere(30, 10);
    blockRect(ref, 0, 0, 10, 10);
    std::vector<std::uint8_t> render = maskRect(30, 10, 0, 0, 7, 10);
    ShadowFigures strict = shadowFigures(ref, render);
    EXPECT_GT(strict.falseLitPct, 0.0);
    EXPECT_NEAR(strict.edgeP95Px, 3.0, 1e-9);
    ShadowFigureInputs texel;
    texel.bandPx.assign(300, 4.0f);
    ShadowFigures tolerant = shadowFigures(ref, render, texel);
    EXPECT_EQ(tolerant.falseLitPct, 0.0);
    EXPECT_NEAR(tolerant.edgeP95Px, 0.0, 1e-9);
    // Five pixels short is still one pixel beyond the tolerance.
    EXPECT_NEAR(shadowFigures(ref, maskRect(30, 10, 0, 0, 5, 10), texel).edgeP95Px, 2.0, 1e-9);
}

namespace {

Image filledGrey(int w, int h, int level) {
    Image image(w, h);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) setGrey(image, i, j, level);
    return image;
}

}  // namespace

TEST(Metrics, ShadowLevelIsTheLecturesAmbientOnly) {
    // The reference keeps 40 of 120 levels in a hard shadow (ambient only): a third. A render
    // whose all-lit pixel is 150 should show its shadow at 50.
    ReferenceShades shades{filledGrey(4, 1, 120), filledGrey(4, 1, 40)};
    Image allLit = filledGrey(4, 1, 150);
    Image shown = filledGrey(4, 1, 150);
    setGrey(shown, 0, 0, 50);   // the lecture's shadow
    setGrey(shown, 1, 0, 0);    // black: the ambient dropped too
    setGrey(shown, 2, 0, 100);  // pale: half the diffuse kept
    setGrey(shown, 3, 0, 58);   // within 10 % of the lit luma (15 levels)
    std::vector<std::uint8_t> off = shadowLevelOff(shown, allLit, shades);
    EXPECT_EQ(off, (std::vector<std::uint8_t>{0, 1, 1, 0}));

    // The figure counts truly shadowed pixels outside the band that the render shows shadowed.
    ReferenceImage ref = evaluatedEverywhere(4, 1);
    blockRect(ref, 0, 0, 4, 1);
    ShadowFigureInputs inputs;
    inputs.shadowLevelOff = off;
    ShadowFigures f = shadowFigures(ref, maskRect(4, 1, 0, 0, 4, 1), inputs);
    EXPECT_NEAR(f.shadowLevelOffPct, 50.0, 1e-9);
    EXPECT_EQ(f.falseLitPct, 0.0);  // where the shadows are is a separate question
}

TEST(Metrics, LightLostSeesDimmingBelowTheClassifier) {
    // Lit 150, the lecture's shadow 50 there: the pixel's light is 100 levels. A render 10 %
    // darker (135) is not "shadowed" to the classifier, but loses 15 % of its light.
    ReferenceShades shades{filledGrey(3, 1, 120), filledGrey(3, 1, 40)};
    Image allLit = filledGrey(3, 1, 150);
    Image shown = filledGrey(3, 1, 150);
    setGrey(shown, 1, 0, 135);
    setGrey(shown, 2, 0, 50);
    std::vector<float> lost = lightLost(shown, allLit, shades);
    EXPECT_NEAR(lost[0], 0.0f, 1e-6f);
    EXPECT_NEAR(lost[1], 0.15f, 1e-3f);
    EXPECT_NEAR(lost[2], 1.0f, 1e-3f);
    EXPECT_EQ(classifyShadowed(shown, allLit)[1], 0);

    ReferenceImage ref = evaluatedEverywhere(3, 1);  // all truly lit
    ShadowFigureInputs inputs;
    inputs.lightLost = lost;
    ShadowFigures f = shadowFigures(ref, classifyShadowed(shown, allLit), inputs);
    EXPECT_NEAR(f.litLightLostPct, 100.0 * 1.15 / 3.0, 0.05);
    EXPECT_NEAR(f.falseShadowPct, 100.0 / 3.0, 1e-9);
}

// A figure over an empty set measured nothing: with no shadowed pixel outside the band (a light
// so low that no shadow can be seen) false lit and the balanced error are undefined, not a
// perfect 0; the figures that did measure something keep their values.
TEST(ShadowAccuracy, EmptySetsAreUndefinedNotPerfect) {
    ShadowFigures f;
    f.litOutside = 1000;
    f.falseShadowPct = 2.0;
    f.shadowOutside = 0;
    f.falseLitPct = 0.0;  // percent() of nothing
    Accuracy a = shadowAccuracy(f);
    EXPECT_DOUBLE_EQ(a.falseShadowPct, 2.0);
    EXPECT_TRUE(std::isnan(a.falseLitPct));
    EXPECT_TRUE(std::isnan(a.errorPct));

    f.shadowOutside = 500;
    f.falseLitPct = 4.0;
    a = shadowAccuracy(f);
    EXPECT_DOUBLE_EQ(a.errorPct, 3.0);

    f.litOutside = 0;
    EXPECT_TRUE(std::isnan(shadowAccuracy(f).falseShadowPct));
    EXPECT_TRUE(std::isnan(shadowAccuracy(f).errorPct));
}
