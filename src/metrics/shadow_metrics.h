// How well a shadow-mapped render matches the reference: which pixels the render shows in
// shadow, how many disagree with the exact answer, and how far its shadow edges are displaced.
#pragma once

#include <cstdint>
#include <vector>

#include "io/image.h"
#include "math/camera.h"
#include "metrics/distance.h"
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

// Definitions (all on the reference image grid; GUIDE section 4, pictures in docs/check.md):
//   evaluated   the reference sees a light-facing, non-mirror object there, the render shows
//               the same object (`renderedIds`, when given: a pixel the rasterizer gives to the
//               background or a neighbour is a silhouette difference, not a shadow), and a
//               shadow there could be seen at all (`shadowVisible`, when given: near a
//               terminator the light adds too little for any render to show its loss).
//   neighbours  only evaluated pixels of the same object are neighbours: a boundary against the
//               background, another object or a face turned away is no shadow edge.
//   truth       shadowed when the reference says `blocked`.
//   true edge   a truth-shadowed pixel with a truth-lit neighbour, plus every pixel the shadow
//               boundary runs along at a silhouette (ReferencePixel::shadowEdgeAtSilhouette).
//   edge band   the pixels on both sides of the true edge (a neighbour of the other truth, or a
//               marked silhouette pixel), widened to those closer than `bandPx` (per pixel; at
//               least 1): where the map's finite resolution may put the rendered edge. The
//               tolerance is one shadow-map texel as it lands on screen (mapTexelOnScreen), so a
//               correct method's one-texel slip at a grazing receiver is forgiven and a larger
//               slip is not.
//   rendered    a rendered-shadowed pixel with a rendered-lit neighbour, plus a marked
//   edge        silhouette pixel the render gets right (it cannot show the other side).
//   edge error  for each true edge pixel, the distance to the nearest rendered edge pixel of the
//               same object: how far the render puts each piece of the true edge. Acne specks
//               far from any true edge are false shadow, not edge error.
struct ShadowFigures {
    long evaluated = 0;  // pixels counted (see above)
    long truthLit = 0, truthShadow = 0;
    // Of those, the ones outside the band: the denominators of falseShadowPct and falseLitPct.
    // Zero means that figure measured nothing (a light so low that no shadow can be seen).
    long litOutside = 0, shadowOutside = 0;
    // Of the truth-lit evaluated pixels outside the band: % rendered shadowed.
    double falseShadowPct = 0;
    // Of the truth-shadowed evaluated pixels outside the band: % rendered lit.
    double falseLitPct = 0;
    // The same two inside the band.
    double falseShadowBandPct = 0, falseLitBandPct = 0;
    // Of the evaluated pixels, truth lit or shadowed: % dark even in the "everything lit" frame
    // (darkWithoutCaster; where the truth is lit, counted in falseShadow too).
    double darkWithoutCasterPct = 0;
    // Of the truth-lit evaluated pixels rendered shadowed outside the band: % that touch a
    // rendered-lit neighbour. Acne is specks and stripes (high); a map that darkens whole
    // surfaces leaves solid regions (low). NaN-free: 0 when nothing is falsely shadowed.
    double falseShadowSpecklePct = 0;
    // Of the truth-shadowed evaluated pixels outside the band that render shadowed: % whose
    // luma is not the lecture's shadow (shadowLevelOff): shadows that drop the ambient term
    // too (black) or keep part of the diffuse light (pale). 0 when nothing is counted.
    double shadowLevelOffPct = 0;
    // Of the truth-lit evaluated pixels outside the band: the mean % of each pixel's light (its
    // all-lit luma less the lecture's shadow there) that the render loses (lightLost). Close to
    // false shadow for a hard test; it also sees a surface dimmed by less than the classifier's
    // 15 % (a filter whose far taps shadow their own surface). 0 when nothing is counted.
    double litLightLostPct = 0;
    // Of the evaluated pixels: % clearly brighter in the "everything lit" frame than our own
    // lighting with its highlight (litTooBright): flat white, a flat colour, infinities.
    double litTooBrightPct = 0;
    // Outside the band, per object id (index: ReferencePixel::objectId): where the errors lie, so
    // a lesson's words ("specks on the floor", "most of the lit floor stays bright") can be held
    // to its picture. Sums over the ids are litOutside, shadowOutside and their wrong pixels.
    struct ObjectCounts {
        long lit = 0, falseShadow = 0;  // truth lit; of those rendered shadowed
        long shadow = 0, falseLit = 0;  // truth shadowed; of those rendered lit
    };
    std::vector<ObjectCounts> byObject;
    // Distance in pixels from each true edge pixel to the nearest rendered edge pixel of the same
    // object (the image's diagonal when there is none), less that pixel's tolerance beyond one
    // pixel (bandPx - 1, never below 0): the mean and the 95th percentile (nearest rank). When
    // either set is empty the distance is undefined: both are -1 and edgeDefined is false.
    double edgeMeanPx = -1, edgeP95Px = -1;
    bool edgeDefined = false;
    long renderedBoundary = 0, trueBoundary = 0;
    std::vector<std::uint8_t> band;  // per pixel, 1 inside the edge band (for the diff image)
    std::vector<std::uint8_t> evaluatedMask;  // per pixel, 1 where counted (for the diff image)
};

// The inputs beyond the reference and the classification. Every vector is per pixel, row-major,
// and empty when not known.
struct ShadowFigureInputs {
    std::vector<int> renderedIds;                 // the object the render shows (0 background)
    std::vector<std::uint8_t> darkWithoutCaster;  // dark with the map forced "everything lit"
    std::vector<std::uint8_t> litTooBright;       // brighter there than our lighting
    std::vector<float> bandPx;                    // edge tolerance in pixels (>= 1)
    std::vector<std::uint8_t> shadowVisible;      // shadowVisiblePixels
    std::vector<std::uint8_t> shadowLevelOff;     // shadowLevelOff
    std::vector<float> lightLost;                 // lightLost
};

// `shadowed` comes from classifyShadowed (one byte per pixel, non-zero = shadowed) and must match
// the reference size (std::invalid_argument otherwise), as must every non-empty input.
// Percentages are 0 when nothing is counted. (The evaluator keeps the truth's half of this per
// view: shadow_truth.h.)
ShadowFigures shadowFigures(const ReferenceImage& ref, const std::vector<std::uint8_t>& shadowed,
                            const ShadowFigureInputs& inputs = {});

// How many screen pixels one texel of a shadow map (size x size texels over the clip square of
// `lightViewProjection`) spans on each evaluated surface, at least 1: the largest on-screen step
// a one-texel move in the map makes, found from the surface's tangent plane under the
// neighbouring pixels' rays. 1 where not evaluated or mapSize <= 0.
std::vector<float> mapTexelOnScreen(const ReferenceImage& ref, const Camera& camera,
                                    const glm::mat4& lightViewProjection, int mapSize);

// The reference's own shading (shadeReference) of every pixel with the light reaching it and
// with the light blocked: what a lit and a shadowed pixel should look like, per the lecture
// (ambient always; diffuse and specular only where the light arrives).
struct ReferenceShades {
    Image reached, blocked;
};
ReferenceShades referenceShades(const Scene& scene, const Camera& camera, const ReferenceImage& ref,
                                const glm::vec3& lightPosition);
// Where a shadow can be seen at all: the reference's own shading (`shades`, the scene's
// material) with the light reaching the point and without it differ by more than `margin` times
// the classifier's thresholds. Not so within a few degrees of a terminator, where the light adds
// too little: there a correct shadow and a missing one render alike, so such a pixel is neither
// false lit nor false shadow (it would otherwise count against every method). The margin keeps
// pixels whose drop is only just over the threshold (a Gouraud pass, a student's Blinn) out too.
std::vector<std::uint8_t> shadowVisiblePixels(const ReferenceShades& shades, float margin = 1.5f,
                                              const ClassifyOptions& options = {});

// Where a rendered shadow is not as dark as the lecture's: a pixel in a hard shadow keeps the
// ambient term only, i.e. the fraction blocked / reached of its lit luma that the reference's
// shading keeps. Measured against the render's own all-lit luma (so a student's lighting model
// or the fixed-function pass is judged by its own light), 1 where luma(withShadows) differs from
// luma(allLit) * kept by more than both thresholds (`relativeDrop` of the all-lit luma and
// `absoluteDrop` levels). A black shadow (ambient dropped too) is off by the whole ambient, at
// least 20 % of the lit luma; a shadow keeping half the diffuse light by 14-33 %.
inline constexpr ClassifyOptions kShadowLevelOptions{0.10f, 6.0f};
std::vector<std::uint8_t> shadowLevelOff(const Image& withShadows, const Image& allLit,
                                         const ReferenceShades& shades,
                                         const ClassifyOptions& options = kShadowLevelOptions);

// Per pixel, the fraction (0..1) of its light the render loses: (allLit - withShadows) over
// allLit * (1 - kept), the drop a hard shadow would make there (at least `absoluteDrop` levels,
// so a pixel the light barely reaches does not divide by nothing).
inline constexpr float kLightLostAbsoluteDrop = 6.0f;
std::vector<float> lightLost(const Image& withShadows, const Image& allLit,
                             const ReferenceShades& shades,
                             float absoluteDrop = kLightLostAbsoluteDrop);

// Which pixels the figures count (the `evaluated` definition above).
std::vector<std::uint8_t> evaluatedPixels(const ReferenceImage& ref,
                                          const std::vector<int>& renderedIds,
                                          const std::vector<std::uint8_t>& shadowVisible = {});

// A picture of the disagreement: red (220,40,40) false shadow, blue (40,80,230) false lit, their
// pale versions (240,170,170) and (170,190,240) for a disagreement inside the edge band `band`
// (forgiven: within a map texel of the true edge), grey where render and reference agree (the
// luma of withShadows squeezed into 60..200 so it never reads as a colour), white where the
// pixel is not evaluated (`evaluated`, ShadowFigures::evaluatedMask; empty = evaluatedPixels(ref)).
Image diffImage(const ReferenceImage& ref, const std::vector<std::uint8_t>& shadowed,
                const Image& withShadows, const std::vector<std::uint8_t>& evaluated = {},
                const std::vector<std::uint8_t>& band = {});

}  // namespace sl
