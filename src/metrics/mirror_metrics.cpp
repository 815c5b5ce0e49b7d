#include "metrics/mirror_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
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

Scene idColouredScene(const Scene& scene) {
    Scene painted = scene;
    painted.background = idColour(0);
    painted.material = Material{1.0f, 0.0f, 0.0f, scene.material.shininess};
    for (std::size_t i = 0; i < painted.objects.size(); ++i)
        painted.objects[i].color = idColour(objectId(i));
    return painted;
}

glm::vec3 idColour(int id) {
    if (id <= 0) return glm::vec3(0.0f);
    // Fully saturated hue h in [0, 1): the colour wheel's six sectors.
    float h = std::fmod(0.61803398875f * float(id), 1.0f) * 6.0f;
    float x = 1.0f - std::fabs(std::fmod(h, 2.0f) - 1.0f);
    switch (int(h)) {
        case 0:
            return {1, x, 0};
        case 1:
            return {x, 1, 0};
        case 2:
            return {0, 1, x};
        case 3:
            return {0, x, 1};
        case 4:
            return {x, 0, 1};
        default:
            return {1, 0, x};
    }
}

std::vector<int> decodeIdImage(const Image& image, int maxId, float scale) {
    std::vector<glm::vec3> palette;
    for (int id = 0; id <= maxId; ++id) palette.push_back(idColour(id) * scale * 255.0f);
    std::vector<int> ids(std::size_t(image.width) * image.height, 0);
    for (std::size_t k = 0; k < ids.size(); ++k) {
        glm::vec3 c(image.rgba[4 * k], image.rgba[4 * k + 1], image.rgba[4 * k + 2]);
        float best = INFINITY;
        for (int id = 0; id <= maxId; ++id) {
            glm::vec3 d = c - palette[std::size_t(id)];
            float distance = glm::dot(d, d);
            if (distance < best) {
                best = distance;
                ids[k] = id;
            }
        }
    }
    return ids;
}

std::vector<std::uint8_t> mirrorMask(const ReferenceImage& ref, const Scene& scene) {
    std::vector<std::uint8_t> mask(ref.pixels.size(), 0);
    const int mirror = mirrorId(scene);
    for (std::size_t k = 0; k < ref.pixels.size(); ++k)
        mask[k] = seesMirrorFront(ref.pixels[k], mirror) ? 1 : 0;
    return mask;
}

Image mirrorDifferencePicture(const Image& shown, const Image& exact,
                              const std::vector<std::uint8_t>& mask) {
    if (shown.width != exact.width || shown.height != exact.height ||
        mask.size() != std::size_t(shown.width) * std::size_t(shown.height))
        throw std::invalid_argument("mirrorDifferencePicture: sizes differ");
    Image out(shown.width, shown.height);
    for (int j = 0; j < shown.height; ++j)
        for (int i = 0; i < shown.width; ++i) {
            std::uint8_t* o = out.at(i, j);
            o[3] = 255;
            if (!mask[std::size_t(j) * std::size_t(shown.width) + std::size_t(i)]) {
                auto grey = std::uint8_t(64 + shown.luma(i, j) * 0.25f);
                o[0] = o[1] = o[2] = grey;
                continue;
            }
            int most = 0;
            for (int c = 0; c < 3; ++c)
                most = std::max(most, std::abs(int(shown.at(i, j)[c]) - int(exact.at(i, j)[c])));
            o[0] = std::uint8_t(std::min(255, most * 4));
            o[1] = o[2] = 0;
        }
    return out;
}

}  // namespace sl
