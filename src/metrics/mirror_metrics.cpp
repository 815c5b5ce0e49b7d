#include "metrics/mirror_metrics.h"

#include <cmath>
#include <stdexcept>

namespace sl {

namespace {

bool seesMirrorFront(const ReferencePixel& p, int mirror) {
    // Only front hits are given a bounce (bounceObjectId >= 0); the back keeps -1.
    return p.objectId == mirror && p.bounceObjectId >= 0;
}

}  // namespace

double mirrorIdAgreementPct(const ReferenceImage& ref, const std::vector<int>& renderedIds) {
    if (renderedIds.size() != ref.pixels.size())
        throw std::invalid_argument("mirrorIdAgreementPct: size does not match the reference");
    long mirrorPixels = 0, agreeing = 0;
    for (std::size_t k = 0; k < ref.pixels.size(); ++k) {
        const ReferencePixel& p = ref.pixels[k];
        if (!seesMirrorFront(p, ref.mirrorObjectId)) continue;
        ++mirrorPixels;
        if (renderedIds[k] == p.bounceObjectId) ++agreeing;
    }
    return mirrorPixels > 0 ? 100.0 * agreeing / mirrorPixels : 0.0;
}

double psnrInMask(const Image& a, const Image& b, const std::vector<std::uint8_t>& mask) {
    if (a.width != b.width || a.height != b.height ||
        mask.size() != std::size_t(a.width) * a.height)
        throw std::invalid_argument("psnrInMask: the images and the mask differ in size");
    double squaredErrorSum = 0.0;
    long samples = 0;
    for (std::size_t k = 0; k < mask.size(); ++k) {
        if (!mask[k]) continue;
        for (int c = 0; c < 3; ++c) {  // RGB; alpha is not part of the picture
            double e = double(a.rgba[4 * k + c]) - double(b.rgba[4 * k + c]);
            squaredErrorSum += e * e;
        }
        samples += 3;
    }
    if (samples == 0) return 0.0;
    if (squaredErrorSum == 0.0) return kPsnrIdentical;
    double mse = squaredErrorSum / double(samples);
    return 10.0 * std::log10(255.0 * 255.0 / mse);
}

std::vector<std::uint8_t> mirrorMask(const ReferenceImage& ref, const Scene& scene) {
    std::vector<std::uint8_t> mask(ref.pixels.size(), 0);
    const int mirror = mirrorId(scene);
    for (std::size_t k = 0; k < ref.pixels.size(); ++k)
        mask[k] = seesMirrorFront(ref.pixels[k], mirror) ? 1 : 0;
    return mask;
}

}  // namespace sl
