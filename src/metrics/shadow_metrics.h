// How well a shadow-mapped render matches the reference: which pixels the render shows in
// shadow, how many disagree with the exact answer, and how far its shadow edges are displaced.
#pragma once

#include <cstdint>
#include <vector>

#include "metrics/image.h"
#include "reference/raytracer.h"

namespace sl {

struct ClassifyOptions {
    float relativeDrop = 0.15f;  // fraction of the all-lit luma that must be lost
    float absoluteDrop = 6.0f;   // luma levels (0..255) that must be lost
};

// A pixel is rendered "shadowed" (1) when its luma with shadows is darker than the all-lit
// render by more than BOTH thresholds: luma(withShadows) < luma(allLit) * (1 - relativeDrop)
// and luma(allLit) - luma(withShadows) > absoluteDrop. The absolute threshold keeps dark
// surfaces, where a small change is a large fraction, from flickering in and out.
// Both images must have the same size (std::invalid_argument otherwise). Row-major, row 0 top.
std::vector<std::uint8_t> classifyShadowed(const Image& withShadows, const Image& allLit,
                                           const ClassifyOptions& options = {});

// Definitions (all on the reference image grid):
//   evaluated   a pixel on an object (objectId != 0), not the mirror, facing the light.
//   truth       shadowed when the reference says `blocked`.
//   edge band   evaluated pixels with an evaluated 8-neighbour of the other truth: one pixel on
//               each side of the true shadow edge, where a one-pixel slip is forgivable.
//   boundary    an evaluated pixel in shadow with an evaluated 4-neighbour that is lit. Only
//               the shadow side counts, so a shadow shifted by d pixels gives distances of d.
struct ShadowFigures {
    long evaluated = 0;  // pixels facing the light on a non-mirror object
    long truthLit = 0, truthShadow = 0;
    // Of the truth-lit evaluated pixels outside the band: % rendered shadowed.
    double falseShadowPct = 0;
    // Of the truth-shadowed evaluated pixels outside the band: % rendered lit.
    double falseLitPct = 0;
    // The same two inside the band.
    double falseShadowBandPct = 0, falseLitBandPct = 0;
    // Euclidean distance in pixels from each rendered boundary pixel to the nearest true boundary
    // pixel: the mean and the 95th percentile (nearest rank). When either boundary set is empty
    // the distance is undefined: both are -1 and edgeDefined is false.
    double edgeMeanPx = -1, edgeP95Px = -1;
    bool edgeDefined = false;
    long renderedBoundary = 0, trueBoundary = 0;
};

// `shadowed` comes from classifyShadowed (one byte per pixel, non-zero = shadowed) and must match
// the reference size (std::invalid_argument otherwise). Percentages are 0 when nothing is counted.
ShadowFigures shadowFigures(const ReferenceImage& ref, const std::vector<std::uint8_t>& shadowed);

// A picture of the disagreement: red (220,40,40) false shadow, blue (40,80,230) false lit, grey
// where render and reference agree (the luma of withShadows squeezed into 60..200 so it never
// reads as red or blue), white where the pixel is not evaluated.
Image diffImage(const ReferenceImage& ref, const std::vector<std::uint8_t>& shadowed,
                const Image& withShadows);

// Exact Euclidean distance transform: for every pixel of a width x height grid, the distance in
// pixels to the nearest pixel with feature[k] != 0 (+infinity when there is none).
std::vector<float> distanceToFeatures(const std::vector<std::uint8_t>& feature, int width,
                                      int height);

}  // namespace sl
