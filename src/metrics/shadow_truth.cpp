#include "metrics/shadow_truth.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "metrics/pixel_figures.h"
#include "metrics/row_bands.h"

namespace sl {

namespace {

double percent(long part, long whole) {
    return whole > 0 ? 100.0 * part / whole : 0.0;
}

void requireCount(std::size_t expected, std::size_t count, const char* what) {
    if (count != expected)
        throw std::invalid_argument(std::string(what) + ": size does not match the reference");
}

// Nearest-rank percentile of an ascending list.
double percentile(const std::vector<double>& ascending, double fraction) {
    std::size_t rank = std::size_t(std::ceil(fraction * ascending.size()));
    return ascending[std::max<std::size_t>(rank, 1) - 1];
}

// The 4-neighbours in the order of ShadowTruth::neighbours' bits.
constexpr int kOffsets[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};

}  // namespace

ShadowTruth shadowTruth(const ReferenceImage& ref, const std::vector<int>& renderedIds,
                        const std::vector<std::uint8_t>& shadowVisible) {
    const int w = ref.width, h = ref.height;
    requireCount(std::size_t(w) * h, ref.pixels.size(), "shadowTruth");
    ShadowTruth t;
    t.width = w, t.height = h;
    t.evaluated = evaluatedPixels(ref, renderedIds, shadowVisible);
    const std::size_t count = ref.pixels.size();
    t.blocked.resize(count);
    t.objectIds.resize(count);
    for (std::size_t k = 0; k < count; ++k) {
        t.blocked[k] = ref.pixels[k].blocked;
        t.objectIds[k] = ref.pixels[k].objectId;
    }
    t.neighbours.assign(count, 0);
    t.atSilhouette.assign(count, 0);
    t.trueEdge.assign(count, 0);
    std::vector<std::uint8_t> straddling(count, 0);  // both sides of the true edge
    const int bands = rowBandCount(h, w);
    struct Counts {
        long evaluated = 0, lit = 0, shadow = 0, trueEdge = 0;
    };
    std::vector<Counts> counts(bands);
    forRowBands(h, bands, [&](int band, int first, int end) {
        Counts& c = counts[band];
        for (int j = first; j < end; ++j)
            for (int i = 0; i < w; ++i) {
                const std::size_t k = std::size_t(j) * w + i;
                if (!t.evaluated[k]) continue;
                const ReferencePixel& p = ref.pixels[k];
                bool silhouette = p.shadowEdgeAtSilhouette, acrossTruth = false;
                std::uint8_t bits = 0;
                for (int d = 0; d < 4; ++d) {
                    int ni = i + kOffsets[d][0], nj = j + kOffsets[d][1];
                    if (ni < 0 || nj < 0 || ni >= w || nj >= h) continue;
                    const std::size_t n = std::size_t(nj) * w + ni;
                    const ReferencePixel& q = ref.pixels[n];
                    if (q.objectId != p.objectId) continue;
                    if (t.evaluated[n]) {
                        bits |= std::uint8_t(1u << d);
                        acrossTruth = acrossTruth || q.blocked != p.blocked;
                    } else {
                        // The rasterizer left this neighbour out: its silhouette mark is ours.
                        silhouette = silhouette || q.shadowEdgeAtSilhouette;
                    }
                }
                t.neighbours[k] = bits;
                t.atSilhouette[k] = silhouette;
                t.trueEdge[k] = silhouette || (p.blocked && acrossTruth);
                straddling[k] = silhouette || acrossTruth;
                ++c.evaluated;
                ++(p.blocked ? c.shadow : c.lit);
                c.trueEdge += t.trueEdge[k];
            }
    });
    for (const Counts& c : counts) {
        t.evaluatedCount += c.evaluated;
        t.truthLit += c.lit;
        t.truthShadow += c.shadow;
        t.trueBoundary += c.trueEdge;
    }
    t.boxes = objectBoxes(ref, t.evaluated);
    t.toStraddling = distanceWithinObjects(t.objectIds, w, t.boxes, straddling, t.evaluated);
    return t;
}

ShadowFigures shadowFigures(const ReferenceImage& ref, const ShadowTruth& truth,
                            const std::vector<std::uint8_t>& shadowed,
                            const ShadowFigureInputs& inputs) {
    const int w = ref.width, h = ref.height;
    const std::size_t count = ref.pixels.size();
    requireCount(std::size_t(w) * h, count, "shadowFigures");
    if (truth.width != w || truth.height != h || truth.evaluated.size() != count)
        throw std::invalid_argument("shadowFigures: the truth is of another reference");
    if (!inputs.renderedIds.empty() || !inputs.shadowVisible.empty())
        throw std::invalid_argument("shadowFigures: ids and visibility belong to the truth");
    requireCount(count, shadowed.size(), "shadowFigures");
    for (std::size_t n :
         {inputs.darkWithoutCaster.size(), inputs.litTooBright.size(), inputs.bandPx.size(),
          inputs.shadowLevelOff.size(), inputs.lightLost.size()})
        if (n != 0) requireCount(count, n, "shadowFigures");
    // Raw pointers: a byte stored through a vector's element may alias the vector itself, which
    // would reload every vector's data pointer after each store.
    const std::uint8_t *evaluated = truth.evaluated.data(), *neighbours = truth.neighbours.data(),
                       *silhouette = truth.atSilhouette.data(), *blocked = truth.blocked.data(),
                       *trueEdge = truth.trueEdge.data(), *shown = shadowed.data();
    const float* toStraddling = truth.toStraddling.data();
    auto optional = [](const auto& v) { return v.empty() ? nullptr : v.data(); };
    const std::uint8_t *levelOff = optional(inputs.shadowLevelOff),
                       *dark = optional(inputs.darkWithoutCaster),
                       *bright = optional(inputs.litTooBright);
    const float *lightLost = optional(inputs.lightLost), *bandPx = optional(inputs.bandPx);
    const std::ptrdiff_t step[4] = {1, -1, w, -w};  // ShadowTruth::neighbours' bits

    // The rendered edge: a rendered-shadowed pixel with a rendered-lit neighbour, plus a marked
    // silhouette pixel the render gets right (it cannot show the other side).
    std::vector<std::uint8_t> renderedEdge(count, 0), renderedAcross(count, 0);
    std::uint8_t *edge = renderedEdge.data(), *across = renderedAcross.data();
    const int bands = rowBandCount(h, w);
    std::vector<long> renderedBoundary(bands, 0);
    forRowBands(h, bands, [&](int b, int first, int end) {
        long boundary = 0;
        for (std::size_t k = std::size_t(first) * w; k < std::size_t(end) * w; ++k) {
            if (!evaluated[k]) continue;
            const bool rendered = shown[k] != 0;
            bool other = false;
            for (int d = 0; d < 4; ++d)
                other = other || ((neighbours[k] >> d & 1) &&
                                  (shown[std::ptrdiff_t(k) + step[d]] != 0) != rendered);
            across[k] = other;
            edge[k] = (rendered && other) || (silhouette[k] && rendered == (blocked[k] != 0));
            boundary += edge[k];
        }
        renderedBoundary[b] = boundary;
    });
    const std::vector<float> toRenderedEdge =
        distanceWithinObjects(truth.objectIds, w, truth.boxes, renderedEdge, truth.trueEdge);

    ShadowFigures figures;
    figures.evaluatedMask = truth.evaluated;
    figures.evaluated = truth.evaluatedCount;
    figures.truthLit = truth.truthLit;
    figures.truthShadow = truth.truthShadow;
    figures.trueBoundary = truth.trueBoundary;
    for (long n : renderedBoundary) figures.renderedBoundary += n;
    figures.band.assign(count, 0);
    std::uint8_t* inBandOut = figures.band.data();

    // Counted per band; the sums of fractions kept as lists, so they add up in pixel order
    // whatever the bands (a double sum depends on its order).
    struct Counts {
        long litOut = 0, litOutWrong = 0, litIn = 0, litInWrong = 0, litWrongSpeckled = 0;
        long shadowOut = 0, shadowOutWrong = 0, shadowIn = 0, shadowInWrong = 0;
        long darkUnlit = 0, tooBright = 0, shadowShown = 0, shadowShownOff = 0;
        std::vector<float> lost;        // lightLost of each litOut pixel
        std::vector<double> distances;  // of each true edge pixel
        std::vector<ShadowFigures::ObjectCounts> byObject;
    };
    const std::vector<int>& ids = truth.objectIds;
    const std::size_t idCount = truth.boxes.byId.size();
    std::vector<Counts> counts(bands);
    const double diagonal = std::hypot(double(w), double(h));
    forRowBands(h, bands, [&](int b, int first, int end) {
        Counts c;
        c.byObject.resize(idCount);
        for (std::size_t k = std::size_t(first) * w; k < std::size_t(end) * w; ++k) {
            if (!evaluated[k]) continue;
            const float tolerance = bandPx ? bandPx[k] : 1.0f;
            const bool inBand = toStraddling[k] < tolerance;
            inBandOut[k] = inBand;
            const bool wrong = (shown[k] != 0) != (blocked[k] != 0);
            if (!inBand && std::size_t(ids[k]) < idCount) {
                ShadowFigures::ObjectCounts& o = c.byObject[std::size_t(ids[k])];
                if (blocked[k])
                    ++o.shadow, o.falseLit += wrong;
                else
                    ++o.lit, o.falseShadow += wrong;
            }
            if (blocked[k]) {
                (inBand ? c.shadowIn : c.shadowOut)++;
                if (wrong) (inBand ? c.shadowInWrong : c.shadowOutWrong)++;
                if (!inBand && !wrong) {
                    ++c.shadowShown;
                    if (levelOff && levelOff[k]) ++c.shadowShownOff;
                }
            } else {
                (inBand ? c.litIn : c.litOut)++;
                if (!inBand && lightLost) c.lost.push_back(lightLost[k]);
                if (wrong) (inBand ? c.litInWrong : c.litOutWrong)++;
                if (wrong && !inBand && across[k]) ++c.litWrongSpeckled;
            }
            // The "everything lit" frame has no caster in the light's way: a pixel dark there is
            // wrong whatever the truth of the real frame.
            if (dark && dark[k]) ++c.darkUnlit;
            if (bright && bright[k]) ++c.tooBright;
            if (trueEdge[k]) {
                // How far the render puts this piece of the true edge, beyond the tolerance.
                double d = std::min(double(toRenderedEdge[k]), diagonal);
                c.distances.push_back(std::max(0.0, d - std::max(0.0, double(tolerance) - 1.0)));
            }
        }
        counts[b] = std::move(c);
    });
    Counts all;
    double litLost = 0.0, sum = 0.0;
    std::vector<double> distances;
    distances.reserve(std::size_t(figures.trueBoundary));
    figures.byObject.resize(idCount);
    for (const Counts& c : counts) {
        for (std::size_t id = 0; id < idCount; ++id) {
            ShadowFigures::ObjectCounts& o = figures.byObject[id];
            o.lit += c.byObject[id].lit, o.falseShadow += c.byObject[id].falseShadow;
            o.shadow += c.byObject[id].shadow, o.falseLit += c.byObject[id].falseLit;
        }
        all.litOut += c.litOut, all.litOutWrong += c.litOutWrong;
        all.litIn += c.litIn, all.litInWrong += c.litInWrong;
        all.litWrongSpeckled += c.litWrongSpeckled;
        all.shadowOut += c.shadowOut, all.shadowOutWrong += c.shadowOutWrong;
        all.shadowIn += c.shadowIn, all.shadowInWrong += c.shadowInWrong;
        all.darkUnlit += c.darkUnlit, all.tooBright += c.tooBright;
        all.shadowShown += c.shadowShown, all.shadowShownOff += c.shadowShownOff;
        for (float v : c.lost) litLost += v;
        for (double d : c.distances) sum += d, distances.push_back(d);
    }
    figures.litOutside = all.litOut;
    figures.shadowOutside = all.shadowOut;
    figures.falseShadowPct = percent(all.litOutWrong, all.litOut);
    figures.falseLitPct = percent(all.shadowOutWrong, all.shadowOut);
    figures.falseShadowBandPct = percent(all.litInWrong, all.litIn);
    figures.falseLitBandPct = percent(all.shadowInWrong, all.shadowIn);
    figures.darkWithoutCasterPct = percent(all.darkUnlit, figures.evaluated);
    figures.litTooBrightPct = percent(all.tooBright, figures.evaluated);
    figures.falseShadowSpecklePct = percent(all.litWrongSpeckled, all.litOutWrong);
    figures.shadowLevelOffPct = percent(all.shadowShownOff, all.shadowShown);
    figures.litLightLostPct = all.litOut > 0 ? 100.0 * litLost / double(all.litOut) : 0.0;

    if (figures.trueBoundary == 0 || figures.renderedBoundary == 0) return figures;
    std::sort(distances.begin(), distances.end());
    figures.edgeMeanPx = sum / double(distances.size());
    figures.edgeP95Px = percentile(distances, 0.95);
    figures.edgeDefined = true;
    return figures;
}

ShadeShares shadeShares(const ReferenceShades& shades) {
    const Image& reached = shades.reached;
    if (shades.blocked.width != reached.width || shades.blocked.height != reached.height)
        throw std::invalid_argument("shadeShares: the images differ in size");
    ShadeShares s;
    s.kept.resize(std::size_t(reached.width) * reached.height);
    s.reached.resize(s.kept.size());
    for (int j = 0; j < reached.height; ++j)
        for (int i = 0; i < reached.width; ++i) {
            const std::size_t k = std::size_t(j) * reached.width + i;
            const float lit = reached.luma(i, j);
            s.kept[k] = pixel::kept(lit, shades.blocked.luma(i, j));
            s.reached[k] = lit > 0.0f;
        }
    return s;
}

std::vector<float> lumaOf(const Image& image) {
    std::vector<float> luma(std::size_t(image.width) * image.height);
    for (int j = 0; j < image.height; ++j)
        for (int i = 0; i < image.width; ++i)
            luma[std::size_t(j) * image.width + i] = image.luma(i, j);
    return luma;
}

RenderClassification classifyRender(const Image& withShadows, const Image& allLit,
                                    const std::vector<float>& baselineLuma,
                                    const std::vector<float>& oursLuma, const ShadeShares& shares) {
    const int w = allLit.width, h = allLit.height;
    const std::size_t count = std::size_t(w) * h;
    if (withShadows.width != w || withShadows.height != h)
        throw std::invalid_argument("classifyRender: the images differ in size");
    if (!baselineLuma.empty()) requireCount(count, baselineLuma.size(), "classifyRender");
    requireCount(count, oursLuma.size(), "classifyRender");
    requireCount(count, shares.kept.size(), "classifyRender");
    requireCount(count, shares.reached.size(), "classifyRender");
    RenderClassification out;
    ShadowFigureInputs& in = out.inputs;
    out.shadowed.resize(count);
    in.darkWithoutCaster.resize(count);
    in.litTooBright.resize(count);
    in.shadowLevelOff.resize(count);
    in.lightLost.resize(count);
    const ClassifyOptions classify{}, level = kShadowLevelOptions;
    // Raw pointers: a byte stored through a vector's element may alias the vector itself, which
    // would reload every vector's data pointer after each store.
    std::uint8_t *shadowed = out.shadowed.data(), *dark = in.darkWithoutCaster.data(),
                 *bright = in.litTooBright.data(), *off = in.shadowLevelOff.data();
    float* lost = in.lightLost.data();
    const float *baselines = baselineLuma.empty() ? nullptr : baselineLuma.data(),
                *ours = oursLuma.data(), *keptShares = shares.kept.data();
    const std::uint8_t* reached = shares.reached.data();
    const std::uint8_t *renders = withShadows.rgba.data(), *allLits = allLit.rgba.data();
    forRowBands(h, rowBandCount(h, w), [&](int, int first, int end) {
        for (std::size_t k = std::size_t(first) * w; k < std::size_t(end) * w; ++k) {
            const float rendered = rec601Luma(renders + 4 * k), lit = rec601Luma(allLits + 4 * k);
            const bool darkHere = pixel::shadowed(lit, baselines ? baselines[k] : lit, classify);
            dark[k] = darkHere;
            bright[k] = pixel::shadowed(ours[k], lit, classify);
            shadowed[k] = pixel::shadowed(rendered, lit, classify) || darkHere;
            const float kept = keptShares[k];
            off[k] = reached[k] && pixel::levelOff(rendered, lit, kept, level);
            lost[k] = pixel::lightLost(rendered, lit, kept, kLightLostAbsoluteDrop);
        }
    });
    return out;
}

}  // namespace sl
