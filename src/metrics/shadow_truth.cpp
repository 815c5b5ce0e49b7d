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
    t.toStraddling = distanceWithinObjects(ref, t.boxes, straddling, t.evaluated);
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
    auto truthAt = [&](std::size_t k) { return ref.pixels[k].blocked; };
    auto band = [&](std::size_t k) { return inputs.bandPx.empty() ? 1.0f : inputs.bandPx[k]; };

    // The rendered edge: a rendered-shadowed pixel with a rendered-lit neighbour, plus a marked
    // silhouette pixel the render gets right (it cannot show the other side).
    std::vector<std::uint8_t> renderedEdge(count, 0), renderedAcross(count, 0);
    const int bands = rowBandCount(h, w);
    std::vector<long> renderedBoundary(bands, 0);
    forRowBands(h, bands, [&](int b, int first, int end) {
        for (std::size_t k = std::size_t(first) * w; k < std::size_t(end) * w; ++k) {
            if (!truth.evaluated[k]) continue;
            const bool rendered = shadowed[k] != 0;
            const int i = int(k % w), j = int(k / w);
            bool across = false;
            for (int d = 0; d < 4 && !across; ++d)
                if (truth.neighbours[k] & (1u << d))
                    across =
                        (shadowed[std::size_t(j + kOffsets[d][1]) * w + (i + kOffsets[d][0])] !=
                         0) != rendered;
            renderedAcross[k] = across;
            renderedEdge[k] =
                (rendered && across) || (truth.atSilhouette[k] && rendered == truthAt(k));
            renderedBoundary[b] += renderedEdge[k];
        }
    });
    const std::vector<float> toRenderedEdge =
        distanceWithinObjects(ref, truth.boxes, renderedEdge, truth.trueEdge);

    ShadowFigures figures;
    figures.evaluatedMask = truth.evaluated;
    figures.evaluated = truth.evaluatedCount;
    figures.truthLit = truth.truthLit;
    figures.truthShadow = truth.truthShadow;
    figures.trueBoundary = truth.trueBoundary;
    for (long n : renderedBoundary) figures.renderedBoundary += n;
    figures.band.assign(count, 0);

    // Counted per band; the sums of fractions kept as lists, so they add up in pixel order
    // whatever the bands (a double sum depends on its order).
    struct Counts {
        long litOut = 0, litOutWrong = 0, litIn = 0, litInWrong = 0, litWrongSpeckled = 0;
        long shadowOut = 0, shadowOutWrong = 0, shadowIn = 0, shadowInWrong = 0;
        long darkUnlit = 0, tooBright = 0, shadowShown = 0, shadowShownOff = 0;
        std::vector<float> lost;        // lightLost of each litOut pixel
        std::vector<double> distances;  // of each true edge pixel
    };
    std::vector<Counts> counts(bands);
    const double diagonal = std::hypot(double(w), double(h));
    forRowBands(h, bands, [&](int b, int first, int end) {
        Counts& c = counts[b];
        for (std::size_t k = std::size_t(first) * w; k < std::size_t(end) * w; ++k) {
            if (!truth.evaluated[k]) continue;
            const bool inBand = truth.toStraddling[k] < band(k);
            figures.band[k] = inBand;
            const bool wrong = (shadowed[k] != 0) != truthAt(k);
            if (truthAt(k)) {
                (inBand ? c.shadowIn : c.shadowOut)++;
                if (wrong) (inBand ? c.shadowInWrong : c.shadowOutWrong)++;
                if (!inBand && !wrong) {
                    ++c.shadowShown;
                    if (!inputs.shadowLevelOff.empty() && inputs.shadowLevelOff[k])
                        ++c.shadowShownOff;
                }
            } else {
                (inBand ? c.litIn : c.litOut)++;
                if (!inBand && !inputs.lightLost.empty()) c.lost.push_back(inputs.lightLost[k]);
                if (wrong) (inBand ? c.litInWrong : c.litOutWrong)++;
                if (wrong && !inBand && renderedAcross[k]) ++c.litWrongSpeckled;
            }
            // The "everything lit" frame has no caster in the light's way: a pixel dark there is
            // wrong whatever the truth of the real frame.
            if (!inputs.darkWithoutCaster.empty() && inputs.darkWithoutCaster[k]) ++c.darkUnlit;
            if (!inputs.litTooBright.empty() && inputs.litTooBright[k]) ++c.tooBright;
            if (truth.trueEdge[k]) {
                // How far the render puts this piece of the true edge, beyond the tolerance.
                double d = std::min(double(toRenderedEdge[k]), diagonal);
                c.distances.push_back(std::max(0.0, d - std::max(0.0, double(band(k)) - 1.0)));
            }
        }
    });
    Counts all;
    double litLost = 0.0, sum = 0.0;
    std::vector<double> distances;
    distances.reserve(std::size_t(figures.trueBoundary));
    for (const Counts& c : counts) {
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
    forRowBands(h, rowBandCount(h, w), [&](int, int first, int end) {
        for (int j = first; j < end; ++j)
            for (int i = 0; i < w; ++i) {
                const std::size_t k = std::size_t(j) * w + i;
                const float rendered = withShadows.luma(i, j), lit = allLit.luma(i, j);
                const float baseline = baselineLuma.empty() ? lit : baselineLuma[k];
                const bool dark = pixel::shadowed(lit, baseline, classify);
                in.darkWithoutCaster[k] = dark;
                in.litTooBright[k] = pixel::shadowed(oursLuma[k], lit, classify);
                out.shadowed[k] = pixel::shadowed(rendered, lit, classify) || dark;
                const float kept = shares.kept[k];
                in.shadowLevelOff[k] =
                    shares.reached[k] && pixel::levelOff(rendered, lit, kept, level);
                in.lightLost[k] = pixel::lightLost(rendered, lit, kept, kLightLostAbsoluteDrop);
            }
    });
    return out;
}

}  // namespace sl
