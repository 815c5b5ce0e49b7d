#include "metrics/shadow_metrics.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <stdexcept>

#include "metrics/pixel_figures.h"
#include "metrics/row_bands.h"
#include "metrics/shadow_truth.h"

namespace sl {

namespace {

void requireSize(const ReferenceImage& ref, std::size_t count, const char* what) {
    if (ref.pixels.size() != std::size_t(ref.width) * ref.height || count != ref.pixels.size())
        throw std::invalid_argument(std::string(what) + ": size does not match the reference");
}

bool isEvaluated(const ReferenceImage& ref, const ReferencePixel& p) {
    return p.objectId != 0 && p.objectId != ref.mirrorObjectId && p.facesLight;
}

void requireSameSize(const Image& image, std::initializer_list<const Image*> others,
                     const char* what) {
    for (const Image* other : others)
        if (other->width != image.width || other->height != image.height)
            throw std::invalid_argument(std::string(what) + ": the images differ in size");
}

}  // namespace

std::vector<std::uint8_t> classifyShadowed(const Image& withShadows, const Image& allLit,
                                           const ClassifyOptions& options) {
    if (withShadows.width != allLit.width || withShadows.height != allLit.height)
        throw std::invalid_argument("classifyShadowed: the two images differ in size");
    std::vector<std::uint8_t> shadowed(std::size_t(allLit.width) * allLit.height, 0);
    for (int j = 0; j < allLit.height; ++j)
        for (int i = 0; i < allLit.width; ++i)
            shadowed[std::size_t(j) * allLit.width + i] =
                pixel::shadowed(withShadows.luma(i, j), allLit.luma(i, j), options);
    return shadowed;
}

std::vector<float> mapTexelOnScreen(const ReferenceImage& ref, const Camera& camera,
                                    const glm::mat4& lightViewProjection, int mapSize) {
    const int w = ref.width, h = ref.height;
    std::vector<float> band(ref.pixels.size(), 1.0f);
    if (mapSize <= 0) return band;
    auto texel = [&](const glm::vec3& p) {  // map coordinates in texels
        glm::vec4 c = lightViewProjection * glm::vec4(p, 1.0f);
        return (glm::vec2(c) / c.w * 0.5f + 0.5f) * float(mapSize);
    };
    const PixelRays rays(camera, w, h);
    forRowBands(h, rowBandCount(h, w), [&](int, int first, int end) {
        for (int j = first; j < end; ++j)
            for (int i = 0; i < w; ++i) {
                const ReferencePixel& p = ref.at(i, j);
                if (!isEvaluated(ref, p)) continue;
                // The surface's tangent plane under the rays of the next pixel across and down.
                const glm::vec2 here = texel(p.position);
                glm::vec2 steps[2];
                bool ok = true;
                for (int axis = 0; axis < 2 && ok; ++axis) {
                    Ray ray = rays(i + (axis == 0), j + (axis == 1));
                    float facing = glm::dot(ray.direction, p.normal);
                    if (std::abs(facing) < 1e-6f) {
                        ok = false;
                        break;
                    }
                    float t = glm::dot(p.position - ray.origin, p.normal) / facing;
                    steps[axis] = texel(ray.origin + t * ray.direction) - here;
                }
                if (!ok) continue;
                // J maps a screen step to a map step; one texel covers 1 / (its smallest
                // singular value) pixels at most.
                double a = steps[0].x, b = steps[1].x, c = steps[0].y, d = steps[1].y;
                double sumSq = a * a + b * b + c * c + d * d, det = a * d - b * c;
                double disc = std::sqrt(std::max(0.0, sumSq * sumSq - 4.0 * det * det));
                double smallest = std::sqrt(std::max(0.0, 0.5 * (sumSq - disc)));
                if (smallest > 1e-9)
                    band[std::size_t(j) * w + i] = float(std::max(1.0, 1.0 / smallest));
            }
    });
    return band;
}

ReferenceShades referenceShades(const Scene& scene, const Camera& camera, const ReferenceImage& ref,
                                const glm::vec3& lightPosition) {
    return {shadeReference(scene, camera, ref, lightPosition, Occlusion::NoneBlocked),
            shadeReference(scene, camera, ref, lightPosition, Occlusion::AllBlocked)};
}

std::vector<std::uint8_t> shadowVisiblePixels(const ReferenceShades& shades, float margin,
                                              const ClassifyOptions& options) {
    ClassifyOptions stricter{options.relativeDrop * margin, options.absoluteDrop * margin};
    return classifyShadowed(shades.blocked, shades.reached, stricter);
}

std::vector<std::uint8_t> shadowLevelOff(const Image& withShadows, const Image& allLit,
                                         const ReferenceShades& shades,
                                         const ClassifyOptions& options) {
    requireSameSize(allLit, {&withShadows, &shades.reached, &shades.blocked}, "shadowLevelOff");
    const int w = allLit.width, h = allLit.height;
    std::vector<std::uint8_t> off(std::size_t(w) * h, 0);
    const ShadeShares shares = shadeShares(shades);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const std::size_t k = std::size_t(j) * w + i;
            if (!shares.reached[k]) continue;  // nothing lit to compare with
            off[k] =
                pixel::levelOff(withShadows.luma(i, j), allLit.luma(i, j), shares.kept[k], options);
        }
    return off;
}

std::vector<float> lightLost(const Image& withShadows, const Image& allLit,
                             const ReferenceShades& shades, float absoluteDrop) {
    requireSameSize(allLit, {&withShadows, &shades.reached, &shades.blocked}, "lightLost");
    const int w = allLit.width, h = allLit.height;
    std::vector<float> lost(std::size_t(w) * h, 0.0f);
    const ShadeShares shares = shadeShares(shades);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const std::size_t k = std::size_t(j) * w + i;
            lost[k] = pixel::lightLost(withShadows.luma(i, j), allLit.luma(i, j), shares.kept[k],
                                       absoluteDrop);
        }
    return lost;
}

std::vector<std::uint8_t> evaluatedPixels(const ReferenceImage& ref,
                                          const std::vector<int>& renderedIds,
                                          const std::vector<std::uint8_t>& shadowVisible) {
    if (!renderedIds.empty()) requireSize(ref, renderedIds.size(), "evaluatedPixels");
    if (!shadowVisible.empty()) requireSize(ref, shadowVisible.size(), "evaluatedPixels");
    std::vector<std::uint8_t> evaluated(ref.pixels.size());
    for (std::size_t k = 0; k < ref.pixels.size(); ++k)
        evaluated[k] = isEvaluated(ref, ref.pixels[k]) &&
                       (renderedIds.empty() || renderedIds[k] == ref.pixels[k].objectId) &&
                       (shadowVisible.empty() || shadowVisible[k]);
    return evaluated;
}

ShadowFigures shadowFigures(const ReferenceImage& ref, const std::vector<std::uint8_t>& shadowed,
                            const ShadowFigureInputs& inputs) {
    requireSize(ref, shadowed.size(), "shadowFigures");
    ShadowFigureInputs rendered = inputs;
    rendered.renderedIds.clear();
    rendered.shadowVisible.clear();
    return shadowFigures(ref, shadowTruth(ref, inputs.renderedIds, inputs.shadowVisible), shadowed,
                         rendered);
}

Image diffImage(const ReferenceImage& ref, const std::vector<std::uint8_t>& shadowed,
                const Image& withShadows, const std::vector<std::uint8_t>& evaluatedMask,
                const std::vector<std::uint8_t>& band) {
    requireSize(ref, shadowed.size(), "diffImage");
    if (!evaluatedMask.empty()) requireSize(ref, evaluatedMask.size(), "diffImage");
    const std::vector<std::uint8_t> evaluated =
        evaluatedMask.empty() ? evaluatedPixels(ref, {}) : evaluatedMask;
    if (!band.empty()) requireSize(ref, band.size(), "diffImage");
    if (withShadows.width != ref.width || withShadows.height != ref.height)
        throw std::invalid_argument("diffImage: the render does not match the reference size");
    Image diff(ref.width, ref.height);
    for (int j = 0; j < ref.height; ++j)
        for (int i = 0; i < ref.width; ++i) {
            std::size_t k = std::size_t(j) * ref.width + i;
            const ReferencePixel& p = ref.pixels[k];
            std::uint8_t* out = diff.at(i, j);
            auto paint = [out](int r, int g, int b) {
                out[0] = std::uint8_t(r);
                out[1] = std::uint8_t(g);
                out[2] = std::uint8_t(b);
                out[3] = 255;
            };
            bool renderedShadow = shadowed[k] != 0;
            if (!evaluated[k]) {
                paint(255, 255, 255);
            } else if (renderedShadow != p.blocked) {
                const bool forgiven = !band.empty() && band[k];
                if (renderedShadow)
                    forgiven ? paint(240, 170, 170) : paint(220, 40, 40);  // false shadow
                else
                    forgiven ? paint(170, 190, 240) : paint(40, 80, 230);  // false lit
            } else {
                int grey = int(std::lround(60.0 + withShadows.luma(i, j) / 255.0 * 140.0));
                grey = std::clamp(grey, 60, 200);
                paint(grey, grey, grey);
            }
        }
    return diff;
}

}  // namespace sl
