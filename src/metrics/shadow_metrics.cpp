#include "metrics/shadow_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace sl {

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

}  // namespace

std::vector<std::uint8_t> classifyShadowed(const Image& withShadows, const Image& allLit,
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

std::vector<float> distanceToFeatures(const std::vector<std::uint8_t>& feature, int width,
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

ShadowFigures shadowFigures(const ReferenceImage& ref, const std::vector<std::uint8_t>& shadowed) {
    requireSize(ref, shadowed.size(), "shadowFigures");
    const int w = ref.width, h = ref.height;
    auto index = [w](int i, int j) { return std::size_t(j) * w + i; };

    std::vector<std::uint8_t> evaluated(ref.pixels.size()), truth(ref.pixels.size());
    for (std::size_t k = 0; k < ref.pixels.size(); ++k) {
        evaluated[k] = isEvaluated(ref, ref.pixels[k]);
        truth[k] = ref.pixels[k].blocked;
    }
    auto rendered = [&](std::size_t k) -> std::uint8_t { return shadowed[k] ? 1 : 0; };

    // Does evaluated pixel (i, j) have an evaluated neighbour whose state differs? `diagonal`
    // chooses the 8-neighbourhood (edge band) or the 4-neighbourhood (boundary).
    auto hasOtherNeighbour = [&](int i, int j, bool diagonal, auto state) {
        for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di) {
                if ((di == 0 && dj == 0) || (!diagonal && di != 0 && dj != 0)) continue;
                int ni = i + di, nj = j + dj;
                if (ni < 0 || nj < 0 || ni >= w || nj >= h) continue;
                std::size_t n = index(ni, nj);
                if (evaluated[n] && state(n) != state(index(i, j))) return true;
            }
        return false;
    };
    auto truthState = [&](std::size_t k) { return truth[k]; };

    ShadowFigures figures;
    long litOut = 0, litOutWrong = 0, litIn = 0, litInWrong = 0;
    long shadowOut = 0, shadowOutWrong = 0, shadowIn = 0, shadowInWrong = 0;
    std::vector<std::uint8_t> trueBoundary(ref.pixels.size(), 0);
    std::vector<std::size_t> renderedBoundary;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            std::size_t k = index(i, j);
            if (!evaluated[k]) continue;
            ++figures.evaluated;
            bool inBand = hasOtherNeighbour(i, j, true, truthState);
            bool wrong = rendered(k) != truth[k];
            if (truth[k]) {
                ++figures.truthShadow;
                (inBand ? shadowIn : shadowOut)++;
                if (wrong) (inBand ? shadowInWrong : shadowOutWrong)++;
                if (hasOtherNeighbour(i, j, false, truthState)) {
                    trueBoundary[k] = 1;
                    ++figures.trueBoundary;
                }
            } else {
                ++figures.truthLit;
                (inBand ? litIn : litOut)++;
                if (wrong) (inBand ? litInWrong : litOutWrong)++;
            }
            if (rendered(k) && hasOtherNeighbour(i, j, false, rendered))
                renderedBoundary.push_back(k);
        }
    figures.falseShadowPct = percent(litOutWrong, litOut);
    figures.falseLitPct = percent(shadowOutWrong, shadowOut);
    figures.falseShadowBandPct = percent(litInWrong, litIn);
    figures.falseLitBandPct = percent(shadowInWrong, shadowIn);
    figures.renderedBoundary = long(renderedBoundary.size());

    if (figures.trueBoundary == 0 || figures.renderedBoundary == 0) return figures;
    std::vector<float> distance = distanceToFeatures(trueBoundary, w, h);
    std::vector<double> distances;
    distances.reserve(renderedBoundary.size());
    double sum = 0.0;
    for (std::size_t k : renderedBoundary) {
        distances.push_back(distance[k]);
        sum += distance[k];
    }
    std::sort(distances.begin(), distances.end());
    figures.edgeMeanPx = sum / double(distances.size());
    figures.edgeP95Px = percentile(distances, 0.95);
    figures.edgeDefined = true;
    return figures;
}

Image diffImage(const ReferenceImage& ref, const std::vector<std::uint8_t>& shadowed,
                const Image& withShadows) {
    requireSize(ref, shadowed.size(), "diffImage");
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
            if (!isEvaluated(ref, p)) {
                paint(255, 255, 255);
            } else if (renderedShadow && !p.blocked) {
                paint(220, 40, 40);  // false shadow
            } else if (!renderedShadow && p.blocked) {
                paint(40, 80, 230);  // false lit
            } else {
                int grey = int(std::lround(60.0 + withShadows.luma(i, j) / 255.0 * 140.0));
                grey = std::clamp(grey, 60, 200);
                paint(grey, grey, grey);
            }
        }
    return diff;
}

}  // namespace sl
