// How well the GL mirror matches the reference: does each mirror pixel show the right object,
// and how close are the colours inside the mirror.
#pragma once

#include <cstdint>
#include <vector>

#include "metrics/image.h"
#include "reference/raytracer.h"
#include "scene/scene.h"

namespace sl {

// Percentage of front-facing mirror pixels (objectId == ref.mirrorObjectId with a bounce) whose
// rendered id equals the reference's bounceObjectId. `renderedIds` is the GL id image: same size,
// row 0 at the top, -1 where nothing was drawn. 0 when the reference shows no mirror front.
// Throws std::invalid_argument when the sizes differ.
double mirrorIdAgreementPct(const ReferenceImage& ref, const std::vector<int>& renderedIds);

// Peak signal-to-noise ratio in dB over the RGB channels of the pixels where mask != 0:
// 10 log10(255^2 / MSE). Identical pixels would give +infinity; we return 99.0 instead so the
// number stays printable and sortable. 0 when the mask is empty. Throws std::invalid_argument
// when the sizes differ.
constexpr double kPsnrIdentical = 99.0;
double psnrInMask(const Image& a, const Image& b, const std::vector<std::uint8_t>& mask);

// 1 where the reference sees the front of the mirror (objectId == mirrorId(scene) and a bounce
// was traced), 0 elsewhere, including the mirror's back.
std::vector<std::uint8_t> mirrorMask(const ReferenceImage& ref, const Scene& scene);

}  // namespace sl
