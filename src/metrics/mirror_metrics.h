// How well the GL mirror matches the reference: does each mirror pixel show the right object,
// and how close are the colours inside the mirror.
#pragma once

#include <cstdint>
#include <vector>

#include "io/image.h"
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

// What differs inside the mirror, as a picture for a student: inside `mask`, black where `shown`
// equals `exact` and red as strong as the largest channel difference (times 4, so a few levels
// show); outside it, `shown` dimmed to grey. Throws std::invalid_argument when the sizes differ.
Image mirrorDifferencePicture(const Image& shown, const Image& exact,
                              const std::vector<std::uint8_t>& mask);

// The object-id picture, made with the real shaders: the scene with every object painted its own
// flat colour (ambient 1, no diffuse or specular, so any Phong shader returns objectColor
// unchanged, shadowed or not) on a black background. Rendering it through a stage and decoding
// the pixels gives which object each pixel shows.
Scene idColouredScene(const Scene& scene);
// The flat colour of object id `id` (0 = background, black): hues spread by the golden ratio so
// that neighbouring ids differ strongly.
glm::vec3 idColour(int id);
// Each pixel's id: the nearest of idColour(0..maxId) * `scale` (the mirror's reflectance scales
// what it shows). Row 0 at the top, like Image.
std::vector<int> decodeIdImage(const Image& image, int maxId, float scale);

// 1 where the reference sees the front of the mirror (objectId == mirrorId(scene) and a bounce
// was traced), 0 elsewhere, including the mirror's back.
std::vector<std::uint8_t> mirrorMask(const ReferenceImage& ref, const Scene& scene);

}  // namespace sl
