// The shadow figures in two halves: what comes from the truth alone (the reference, our id
// render, where a shadow can be seen), the same for every render of one view and kept by the
// evaluator, and the pass over one render, each pixel's luma read once. Together they compute
// exactly what classifyShadowed, shadowLevelOff, lightLost and shadowFigures do
// (shadow_metrics.h has the definitions); tests/render/test_fast_figures.cpp checks it bit for
// bit against the straightforward code on real renders.
#pragma once

#include <cstdint>
#include <vector>

#include "metrics/distance.h"
#include "metrics/shadow_metrics.h"

namespace sl {

// The truth's half of shadowFigures for one reference, id render and shadowVisible.
struct ShadowTruth {
    int width = 0, height = 0;
    std::vector<std::uint8_t> evaluated;  // evaluatedPixels
    std::vector<std::uint8_t> blocked;    // the truth: the reference's `blocked`
    std::vector<int> objectIds;           // the reference's object ids
    // Per evaluated pixel, bit d set when its 4-neighbour d (+i, -i, +j, -j) is evaluated and
    // shows the same object: the neighbours whose state can make an edge with it.
    std::vector<std::uint8_t> neighbours;
    std::vector<std::uint8_t>
        atSilhouette;  // a marked silhouette shadow edge as the render covers it
    std::vector<std::uint8_t> trueEdge;
    std::vector<float>
        toStraddling;   // distance to the nearest pixel on either side of the true edge
    ObjectBoxes boxes;  // of the evaluated pixels
    long evaluatedCount = 0, truthLit = 0, truthShadow = 0, trueBoundary = 0;
};
ShadowTruth shadowTruth(const ReferenceImage& ref, const std::vector<int>& renderedIds,
                        const std::vector<std::uint8_t>& shadowVisible = {});

// shadowFigures(ref, shadowed, inputs) with the truth's half done: `truth` must come from `ref`,
// and inputs.renderedIds and inputs.shadowVisible stay empty (they are in `truth`).
ShadowFigures shadowFigures(const ReferenceImage& ref, const ShadowTruth& truth,
                            const std::vector<std::uint8_t>& shadowed,
                            const ShadowFigureInputs& inputs);

// The reference's shading as the per-pixel figures use it: the share of its lit luma a hard
// shadow keeps (blocked / reached, at most 1; 1 where the light adds nothing) and whether the
// lit luma is above 0.
struct ShadeShares {
    std::vector<float> kept;
    std::vector<std::uint8_t> reached;
};
ShadeShares shadeShares(const ReferenceShades& shades);

// Every pixel's luma (Image::luma), row-major.
std::vector<float> lumaOf(const Image& image);

// The per-pixel figures of one render in one pass: `shadowed` is classifyShadowed(withShadows,
// allLit) or dark without a caster, and `inputs` gets darkWithoutCaster =
// classifyShadowed(allLit, baseline), litTooBright = classifyShadowed(ours, allLit),
// shadowLevelOff(withShadows, allLit, shades) and lightLost(withShadows, allLit, shades), with
// their default options. `baselineLuma` and `oursLuma` are lumaOf our renders (baseline empty:
// the all-lit render is its own baseline); `shares` is shadeShares of the view's shades.
struct RenderClassification {
    std::vector<std::uint8_t> shadowed;
    ShadowFigureInputs inputs;
};
RenderClassification classifyRender(const Image& withShadows, const Image& allLit,
                                    const std::vector<float>& baselineLuma,
                                    const std::vector<float>& oursLuma, const ShadeShares& shares);

}  // namespace sl
