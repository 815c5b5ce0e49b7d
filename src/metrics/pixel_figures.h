// One pixel's share of the per-pixel figures (shadow_metrics.h has their definitions), written
// once for both the image-at-a-time functions and the one-pass classifyRender.
#pragma once

#include <algorithm>
#include <cmath>

#include "metrics/shadow_metrics.h"

namespace sl::pixel {

// classifyShadowed: clearly darker than the all-lit luma by both thresholds.
inline bool shadowed(float rendered, float lit, const ClassifyOptions& o) {
    bool darker = rendered < lit * (1.0f - o.relativeDrop);
    bool clearly = lit - rendered > o.absoluteDrop;
    return darker && clearly;
}

// keptShare: blocked / reached of the reference's shading, 1 where the light adds nothing.
inline float kept(float reachedLuma, float blockedLuma) {
    return reachedLuma > 0.0f ? std::min(1.0f, blockedLuma / reachedLuma) : 1.0f;
}

// shadowLevelOff: the shadow's luma off the lecture's (lit * kept) by both thresholds.
inline bool levelOff(float rendered, float lit, float kept, const ClassifyOptions& o) {
    float difference = std::abs(rendered - lit * kept);
    return difference > o.relativeDrop * lit && difference > o.absoluteDrop;
}

// lightLost: the fraction of the light a hard shadow would take that the render loses.
inline float lightLost(float rendered, float lit, float kept, float absoluteDrop) {
    float light = std::max(lit * (1.0f - kept), absoluteDrop);
    return std::clamp((lit - rendered) / light, 0.0f, 1.0f);
}

}  // namespace sl::pixel
