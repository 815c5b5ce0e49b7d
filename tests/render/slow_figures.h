// The shadow figures as they were computed before they were made fast (src/metrics at
// b11b40d, verbatim but for this namespace and the old pixelRay): the reference the fast path
// is checked against bit for bit (test_fast_figures.cpp). Included by that test only.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <initializer_list>
#include <limits>
#include <map>
#include <stdexcept>

#include "metrics/shadow_metrics.h"

namespace sl::slow {

// pixelRay as it was: the view matrix built and inverted for every pixel.
inline Ray pixelRay(const Camera& c, int i, int j, int width, int height) {
    glm::vec2 ndc = pixelCenterNdc(i, j, width, height);
    glm::mat4 invView = glm::inverse(viewMatrix(c));
    float t = std::tan(glm::radians(c.fovyDegrees) * 0.5f);
    float aspect = static_cast<float>(width) / static_cast<float>(height);
    glm::vec3 dirCam(ndc.x * t * aspect, ndc.y * t, -1.0f);
    glm::vec3 dir = glm::normalize(glm::vec3(invView * glm::vec4(dirCam, 0.0f)));
    return {c.eye, dir};
}

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

double percent(long part, long whole) {
    return whole > 0 ? 100.0 * part / whole : 0.0;
}

void requireSize(const ReferenceImage& ref, std::size_t count, const char* what) {
    if (ref.pixels.size() != std::size_t(ref.width) * ref.height || count != ref.pixels.size())
        throw std::invalid_argument(std::string(what) + ": size does not match the reference");
}

bool isEvaluated(const ReferenceImage& ref, const ReferencePixel& p) {
    return p.objectId != 0 && p.objectId != ref.mirrorObjectId && p.facesLight;
}

// One line of the distance transform (Felzenszwalb and Huttenlocher): the squared distance
// d(q) = min over p of (q - p)^2 + f(p) is the lower envelope of parabolas rooted at each p.
// We sweep once to find which parabolas form the envelope and where they take over from each
// other, then once more to read it off. Entries with f = infinity add no parabola.
void squaredDistanceLine(const std::vector<double>& f, std::vector<double>& d,
                         std::vector<int>& root, std::vector<double>& from) {
    const int n = int(f.size());
    auto crossing = [&](int q, int p) {  // where the parabolas of q and p (p < q) meet
        return ((f[q] + double(q) * q) - (f[p] + double(p) * p)) / (2.0 * (q - p));
    };
    int k = -1;  // index of the last parabola in the envelope
    for (int q = 0; q < n; ++q) {
        if (f[q] == kInfinity) continue;
        if (k < 0) {
            k = 0;
            root[0] = q;
            from[0] = -kInfinity;  // the first parabola is never dropped
            from[1] = kInfinity;
            continue;
        }
        double s = crossing(q, root[k]);
        while (s <= from[k]) s = crossing(q, root[--k]);  // q hides the last one entirely
        ++k;
        root[k] = q;
        from[k] = s;
        from[k + 1] = kInfinity;
    }
    if (k < 0) {
        std::fill(d.begin(), d.end(), kInfinity);
        return;
    }
    int j = 0;
    for (int q = 0; q < n; ++q) {
        while (from[j + 1] < q) ++j;
        double dq = q - root[j];
        d[q] = dq * dq + f[root[j]];
    }
}

// Nearest-rank percentile of an ascending list.
double percentile(const std::vector<double>& ascending, double fraction) {
    std::size_t rank = std::size_t(std::ceil(fraction * ascending.size()));
    return ascending[std::max<std::size_t>(rank, 1) - 1];
}

void requireSameSize(const Image& image, std::initializer_list<const Image*> others,
                     const char* what) {
    for (const Image* other : others)
        if (other->width != image.width || other->height != image.height)
            throw std::invalid_argument(std::string(what) + ": the images differ in size");
}

// The share of a pixel's lit luma the reference keeps in a hard shadow (blocked / reached: the
// ambient term's part), 1 where the light adds nothing.
float keptShare(const ReferenceShades& shades, int i, int j) {
    float reached = shades.reached.luma(i, j);
    return reached > 0.0f ? std::min(1.0f, shades.blocked.luma(i, j) / reached) : 1.0f;
}

}  // namespace

inline std::vector<std::uint8_t> classifyShadowed(const Image& withShadows, const Image& allLit,
                                                  const ClassifyOptions& options) {
    if (withShadows.width != allLit.width || withShadows.height != allLit.height)
        throw std::invalid_argument("classifyShadowed: the two images differ in size");
    std::vector<std::uint8_t> shadowed(std::size_t(allLit.width) * allLit.height, 0);
    for (int j = 0; j < allLit.height; ++j)
        for (int i = 0; i < allLit.width; ++i) {
            float lit = allLit.luma(i, j);
            float rendered = withShadows.luma(i, j);
            bool darker = rendered < lit * (1.0f - options.relativeDrop);
            bool clearly = lit - rendered > options.absoluteDrop;
            shadowed[std::size_t(j) * allLit.width + i] = darker && clearly ? 1 : 0;
        }
    return shadowed;
}

inline std::vector<float> distanceToFeatures(const std::vector<std::uint8_t>& feature, int width,
                                             int height) {
    if (width < 0 || height < 0 || feature.size() != std::size_t(width) * height)
        throw std::invalid_argument("distanceToFeatures: size does not match");
    const int longest = std::max(width, height);
    std::vector<double> f(longest), d(longest), from(longest + 1);
    std::vector<int> root(longest);
    std::vector<double> squared(feature.size());

    // Columns first: squared distance to the nearest feature in the same column ...
    f.resize(height), d.resize(height);
    for (int i = 0; i < width; ++i) {
        for (int j = 0; j < height; ++j)
            f[j] = feature[std::size_t(j) * width + i] ? 0.0 : kInfinity;
        squaredDistanceLine(f, d, root, from);
        for (int j = 0; j < height; ++j) squared[std::size_t(j) * width + i] = d[j];
    }
    // ... then rows, which combines it with the horizontal offset: exact in 2D.
    f.resize(width), d.resize(width);
    for (int j = 0; j < height; ++j) {
        for (int i = 0; i < width; ++i) f[i] = squared[std::size_t(j) * width + i];
        squaredDistanceLine(f, d, root, from);
        for (int i = 0; i < width; ++i) squared[std::size_t(j) * width + i] = d[i];
    }
    std::vector<float> distance(feature.size());
    for (std::size_t k = 0; k < distance.size(); ++k)
        distance[k] = float(std::sqrt(squared[k]));  // sqrt(inf) stays inf
    return distance;
}

inline std::vector<float> mapTexelOnScreen(const ReferenceImage& ref, const Camera& camera,
                                           const glm::mat4& lightViewProjection, int mapSize) {
    const int w = ref.width, h = ref.height;
    std::vector<float> band(ref.pixels.size(), 1.0f);
    if (mapSize <= 0) return band;
    auto texel = [&](const glm::vec3& p) {  // map coordinates in texels
        glm::vec4 c = lightViewProjection * glm::vec4(p, 1.0f);
        return (glm::vec2(c) / c.w * 0.5f + 0.5f) * float(mapSize);
    };
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const ReferencePixel& p = ref.at(i, j);
            if (!isEvaluated(ref, p)) continue;
            // The surface's tangent plane under the rays of the next pixel across and down.
            glm::vec2 steps[2];
            bool ok = true;
            for (int axis = 0; axis < 2 && ok; ++axis) {
                Ray ray = slow::pixelRay(camera, i + (axis == 0), j + (axis == 1), w, h);
                float facing = glm::dot(ray.direction, p.normal);
                if (std::abs(facing) < 1e-6f) {
                    ok = false;
                    break;
                }
                float t = glm::dot(p.position - ray.origin, p.normal) / facing;
                steps[axis] = texel(ray.origin + t * ray.direction) - texel(p.position);
            }
            if (!ok) continue;
            // J maps a screen step to a map step; one texel covers 1 / (its smallest singular
            // value) pixels at most.
            double a = steps[0].x, b = steps[1].x, c = steps[0].y, d = steps[1].y;
            double sumSq = a * a + b * b + c * c + d * d, det = a * d - b * c;
            double disc = std::sqrt(std::max(0.0, sumSq * sumSq - 4.0 * det * det));
            double smallest = std::sqrt(std::max(0.0, 0.5 * (sumSq - disc)));
            if (smallest > 1e-9)
                band[std::size_t(j) * w + i] = float(std::max(1.0, 1.0 / smallest));
        }
    return band;
}

inline ReferenceShades referenceShades(const Scene& scene, const Camera& camera,
                                       const ReferenceImage& ref, const glm::vec3& lightPosition) {
    ReferenceImage reached = ref, blocked = ref;
    for (auto& p : reached.pixels) p.blocked = false;
    for (auto& p : blocked.pixels) p.blocked = true;
    return {shadeReference(scene, camera, reached, lightPosition),
            shadeReference(scene, camera, blocked, lightPosition)};
}

inline std::vector<std::uint8_t> shadowVisiblePixels(const ReferenceShades& shades, float margin,
                                                     const ClassifyOptions& options) {
    ClassifyOptions stricter{options.relativeDrop * margin, options.absoluteDrop * margin};
    return slow::classifyShadowed(shades.blocked, shades.reached, stricter);
}

inline std::vector<std::uint8_t> shadowLevelOff(const Image& withShadows, const Image& allLit,
                                                const ReferenceShades& shades,
                                                const ClassifyOptions& options) {
    requireSameSize(allLit, {&withShadows, &shades.reached, &shades.blocked}, "shadowLevelOff");
    const int w = allLit.width, h = allLit.height;
    std::vector<std::uint8_t> off(std::size_t(w) * h, 0);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            if (shades.reached.luma(i, j) <= 0.0f) continue;  // nothing lit to compare with
            float kept = keptShare(shades, i, j);
            float lit = allLit.luma(i, j);
            float difference = std::abs(withShadows.luma(i, j) - lit * kept);
            off[std::size_t(j) * w + i] =
                difference > options.relativeDrop * lit && difference > options.absoluteDrop;
        }
    return off;
}

inline std::vector<float> lightLost(const Image& withShadows, const Image& allLit,
                                    const ReferenceShades& shades, float absoluteDrop) {
    requireSameSize(allLit, {&withShadows, &shades.reached, &shades.blocked}, "lightLost");
    const int w = allLit.width, h = allLit.height;
    std::vector<float> lost(std::size_t(w) * h, 0.0f);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            float kept = keptShare(shades, i, j);
            float lit = allLit.luma(i, j);
            float light = std::max(lit * (1.0f - kept), absoluteDrop);
            lost[std::size_t(j) * w + i] =
                std::clamp((lit - withShadows.luma(i, j)) / light, 0.0f, 1.0f);
        }
    return lost;
}

inline std::vector<std::uint8_t> evaluatedPixels(const ReferenceImage& ref,
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

inline ShadowFigures shadowFigures(const ReferenceImage& ref,
                                   const std::vector<std::uint8_t>& shadowed,
                                   const ShadowFigureInputs& inputs) {
    requireSize(ref, shadowed.size(), "shadowFigures");
    if (!inputs.darkWithoutCaster.empty())
        requireSize(ref, inputs.darkWithoutCaster.size(), "shadowFigures");
    if (!inputs.litTooBright.empty()) requireSize(ref, inputs.litTooBright.size(), "shadowFigures");
    if (!inputs.bandPx.empty()) requireSize(ref, inputs.bandPx.size(), "shadowFigures");
    if (!inputs.shadowLevelOff.empty())
        requireSize(ref, inputs.shadowLevelOff.size(), "shadowFigures");
    if (!inputs.lightLost.empty()) requireSize(ref, inputs.lightLost.size(), "shadowFigures");
    const int w = ref.width, h = ref.height;
    auto index = [w](int i, int j) { return std::size_t(j) * w + i; };

    const std::vector<std::uint8_t> evaluated =
        slow::evaluatedPixels(ref, inputs.renderedIds, inputs.shadowVisible);
    auto object = [&](std::size_t k) { return ref.pixels[k].objectId; };
    auto truth = [&](std::size_t k) -> std::uint8_t { return ref.pixels[k].blocked ? 1 : 0; };
    auto rendered = [&](std::size_t k) -> std::uint8_t { return shadowed[k] ? 1 : 0; };
    auto band = [&](std::size_t k) { return inputs.bandPx.empty() ? 1.0f : inputs.bandPx[k]; };

    // Does evaluated pixel (i, j) have a 4-neighbour of the same object, evaluated, whose state
    // differs?
    auto hasOtherNeighbour = [&](int i, int j, auto state) {
        const std::size_t k = index(i, j);
        const int offsets[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
        for (const auto& o : offsets) {
            int ni = i + o[0], nj = j + o[1];
            if (ni < 0 || nj < 0 || ni >= w || nj >= h) continue;
            std::size_t n = index(ni, nj);
            if (evaluated[n] && object(n) == object(k) && state(n) != state(k)) return true;
        }
        return false;
    };

    // Per object, the distance of each pixel to the nearest pixel of `mask` on that object, in
    // one image (each pixel shows one object). Each object's transform runs over the box of its
    // own pixels, which holds all its features and queries, so the distances are exact: one
    // float image per object over the whole picture took 1.2 MB an object (0.9 GB for a
    // 400-object scene) and as many whole-image transforms.
    auto distanceWithinObjects = [&](const std::vector<std::uint8_t>& mask) {
        std::vector<float> distance(mask.size(), std::numeric_limits<float>::infinity());
        struct Box {
            int i0 = std::numeric_limits<int>::max(), j0 = std::numeric_limits<int>::max();
            int i1 = -1, j1 = -1;
        };
        std::map<int, Box> boxes;  // the objects holding a feature, and their pixels' box
        for (std::size_t k = 0; k < mask.size(); ++k)
            if (mask[k]) boxes[object(k)];
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i) {
                auto found = boxes.find(object(index(i, j)));
                if (found == boxes.end()) continue;
                Box& b = found->second;
                b.i0 = std::min(b.i0, i), b.i1 = std::max(b.i1, i);
                b.j0 = std::min(b.j0, j), b.j1 = std::max(b.j1, j);
            }
        for (const auto& [id, b] : boxes) {
            const int bw = b.i1 - b.i0 + 1, bh = b.j1 - b.j0 + 1;
            std::vector<std::uint8_t> features(std::size_t(bw) * bh, 0);
            for (int j = b.j0; j <= b.j1; ++j)
                for (int i = b.i0; i <= b.i1; ++i)
                    features[std::size_t(j - b.j0) * bw + (i - b.i0)] =
                        mask[index(i, j)] && object(index(i, j)) == id;
            const std::vector<float> d = distanceToFeatures(features, bw, bh);
            for (int j = b.j0; j <= b.j1; ++j)
                for (int i = b.i0; i <= b.i1; ++i)
                    if (object(index(i, j)) == id)
                        distance[index(i, j)] = d[std::size_t(j - b.j0) * bw + (i - b.i0)];
        }
        return distance;
    };
    auto lookUp = [](const std::vector<float>& distance, std::size_t k) { return distance[k]; };

    // A silhouette shadow edge as the render covers it: the reference's mark, or the mark of a
    // neighbour of the same object the rasterizer left out (the render's silhouette one pixel
    // inside the reference's), so the edge is not lost with that pixel.
    auto marksSilhouetteEdge = [&](int i, int j) {
        const std::size_t k = index(i, j);
        if (ref.pixels[k].shadowEdgeAtSilhouette) return true;
        const int offsets[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
        for (const auto& o : offsets) {
            int ni = i + o[0], nj = j + o[1];
            if (ni < 0 || nj < 0 || ni >= w || nj >= h) continue;
            std::size_t n = index(ni, nj);
            if (!evaluated[n] && object(n) == object(k) && ref.pixels[n].shadowEdgeAtSilhouette)
                return true;
        }
        return false;
    };

    // The true edge and the rendered one. At a silhouette the render cannot show the other
    // side, so a marked silhouette pixel the render gets right counts as a rendered edge too.
    ShadowFigures figures;
    figures.evaluatedMask = evaluated;
    std::vector<std::uint8_t> trueEdge(ref.pixels.size(), 0), renderedEdge(ref.pixels.size(), 0);
    std::vector<std::uint8_t> straddling(ref.pixels.size(), 0);  // both sides of the true edge
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            std::size_t k = index(i, j);
            if (!evaluated[k]) continue;
            const bool atSilhouette = marksSilhouetteEdge(i, j);
            const bool acrossTruth = hasOtherNeighbour(i, j, truth);
            trueEdge[k] = atSilhouette || (truth(k) && acrossTruth);
            straddling[k] = atSilhouette || acrossTruth;
            renderedEdge[k] = (rendered(k) && hasOtherNeighbour(i, j, rendered)) ||
                              (atSilhouette && rendered(k) == truth(k));
            figures.trueBoundary += trueEdge[k];
            figures.renderedBoundary += renderedEdge[k];
        }
    const auto toStraddling = distanceWithinObjects(straddling);
    figures.band.assign(ref.pixels.size(), 0);
    const auto toRenderedEdge = distanceWithinObjects(renderedEdge);

    long litOut = 0, litOutWrong = 0, litIn = 0, litInWrong = 0, litWrongSpeckled = 0;
    long shadowOut = 0, shadowOutWrong = 0, shadowIn = 0, shadowInWrong = 0, darkUnlit = 0,
         tooBright = 0;
    long shadowShown = 0, shadowShownOff = 0;  // rendered shadowed outside the band; level off
    double litLost = 0.0;                      // lightLost summed over litOut
    std::vector<double> distances;
    double sum = 0.0;
    const double diagonal = std::hypot(double(w), double(h));
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            std::size_t k = index(i, j);
            if (!evaluated[k]) continue;
            ++figures.evaluated;
            const bool inBand = lookUp(toStraddling, k) < band(k);
            figures.band[k] = inBand;
            const bool wrong = rendered(k) != truth(k);
            if (truth(k)) {
                ++figures.truthShadow;
                (inBand ? shadowIn : shadowOut)++;
                if (wrong) (inBand ? shadowInWrong : shadowOutWrong)++;
                if (!inBand && !wrong) {
                    ++shadowShown;
                    if (!inputs.shadowLevelOff.empty() && inputs.shadowLevelOff[k])
                        ++shadowShownOff;
                }
            } else {
                ++figures.truthLit;
                (inBand ? litIn : litOut)++;
                if (!inBand && !inputs.lightLost.empty()) litLost += inputs.lightLost[k];
                if (wrong) (inBand ? litInWrong : litOutWrong)++;
                if (wrong && !inBand && hasOtherNeighbour(i, j, rendered)) ++litWrongSpeckled;
            }
            // The "everything lit" frame has no caster in the light's way: a pixel dark there is
            // wrong whatever the truth of the real frame (a shader that draws shadows the map
            // does not hold draws them there too).
            if (!inputs.darkWithoutCaster.empty() && inputs.darkWithoutCaster[k]) ++darkUnlit;
            if (!inputs.litTooBright.empty() && inputs.litTooBright[k]) ++tooBright;
            if (trueEdge[k]) {
                // How far the render puts this piece of the true edge, beyond the tolerance.
                double d = std::min(double(lookUp(toRenderedEdge, k)), diagonal);
                d = std::max(0.0, d - std::max(0.0, double(band(k)) - 1.0));
                distances.push_back(d);
                sum += d;
            }
        }
    figures.litOutside = litOut;
    figures.shadowOutside = shadowOut;
    figures.falseShadowPct = percent(litOutWrong, litOut);
    figures.falseLitPct = percent(shadowOutWrong, shadowOut);
    figures.falseShadowBandPct = percent(litInWrong, litIn);
    figures.falseLitBandPct = percent(shadowInWrong, shadowIn);
    figures.darkWithoutCasterPct = percent(darkUnlit, figures.evaluated);
    figures.litTooBrightPct = percent(tooBright, figures.evaluated);
    figures.falseShadowSpecklePct = percent(litWrongSpeckled, litOutWrong);
    figures.shadowLevelOffPct = percent(shadowShownOff, shadowShown);
    figures.litLightLostPct = litOut > 0 ? 100.0 * litLost / double(litOut) : 0.0;

    if (figures.trueBoundary == 0 || figures.renderedBoundary == 0) return figures;
    std::sort(distances.begin(), distances.end());
    figures.edgeMeanPx = sum / double(distances.size());
    figures.edgeP95Px = percentile(distances, 0.95);
    figures.edgeDefined = true;
    return figures;
}

inline Image diffImage(const ReferenceImage& ref, const std::vector<std::uint8_t>& shadowed,
                       const Image& withShadows, const std::vector<std::uint8_t>& evaluatedMask,
                       const std::vector<std::uint8_t>& band) {
    requireSize(ref, shadowed.size(), "diffImage");
    if (!evaluatedMask.empty()) requireSize(ref, evaluatedMask.size(), "diffImage");
    const std::vector<std::uint8_t> evaluated =
        evaluatedMask.empty() ? slow::evaluatedPixels(ref, {}, {}) : evaluatedMask;
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

}  // namespace sl::slow
