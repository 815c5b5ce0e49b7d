#include "metrics/distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "metrics/row_bands.h"

namespace sl {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

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

// The squared distance, along each column of box `b`, to the nearest feature of object `id` in
// that column (infinity when none), for columns [first, end) of the box. The same numbers as
// squaredDistanceLine over 0-or-infinity input, whose envelope is the nearest root.
template <typename IsFeature>
void nearestInColumns(const ObjectBoxes::Box& b, int first, int end, IsFeature isFeature,
                      std::vector<double>& squared) {
    const int bw = b.i1 - b.i0 + 1, bh = b.j1 - b.j0 + 1;
    std::vector<int> above(bh);  // the nearest feature row at or above, -1 when none
    for (int c = first; c < end; ++c) {
        int last = -1;
        for (int r = 0; r < bh; ++r) {
            if (isFeature(b.i0 + c, b.j0 + r)) last = r;
            above[r] = last;
        }
        int next = -1;  // the nearest feature row at or below
        for (int r = bh - 1; r >= 0; --r) {
            if (above[r] == r) next = r;
            double best = kInfinity;
            if (above[r] >= 0) best = double(r - above[r]) * double(r - above[r]);
            if (next >= 0) best = std::min(best, double(next - r) * double(next - r));
            squared[std::size_t(r) * bw + c] = best;
        }
    }
}

}  // namespace

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

ObjectBoxes objectBoxes(const ReferenceImage& ref, const std::vector<std::uint8_t>& within) {
    if (within.size() != ref.pixels.size())
        throw std::invalid_argument("objectBoxes: size does not match the reference");
    ObjectBoxes boxes;
    for (int j = 0; j < ref.height; ++j)
        for (int i = 0; i < ref.width; ++i) {
            const std::size_t k = std::size_t(j) * ref.width + i;
            const int id = ref.pixels[k].objectId;
            if (!within[k] || id < 0) continue;
            if (std::size_t(id) >= boxes.byId.size()) boxes.byId.resize(std::size_t(id) + 1);
            ObjectBoxes::Box& b = boxes.byId[id];
            if (b.i1 < b.i0) {
                b = {i, j, i, j};
                continue;
            }
            b.i0 = std::min(b.i0, i), b.i1 = std::max(b.i1, i);
            b.j0 = std::min(b.j0, j), b.j1 = std::max(b.j1, j);
        }
    return boxes;
}

std::vector<float> distanceWithinObjects(const std::vector<int>& objectIds, int width,
                                         const ObjectBoxes& boxes,
                                         const std::vector<std::uint8_t>& feature,
                                         const std::vector<std::uint8_t>& query) {
    if (feature.size() != objectIds.size() || query.size() != objectIds.size() || width <= 0 ||
        objectIds.size() % std::size_t(width) != 0)
        throw std::invalid_argument("distanceWithinObjects: sizes do not match");
    const int w = width;
    auto index = [w](int i, int j) { return std::size_t(j) * w + i; };
    std::vector<float> distance(objectIds.size(), std::numeric_limits<float>::infinity());
    const int* ids = objectIds.data();
    const std::uint8_t *features = feature.data(), *queries = query.data();
    float* out = distance.data();
    for (int id = 0; id < int(boxes.byId.size()); ++id) {
        const ObjectBoxes::Box& b = boxes.byId[id];
        if (b.i1 < b.i0) continue;
        const int bw = b.i1 - b.i0 + 1, bh = b.j1 - b.j0 + 1;
        auto isFeature = [&](int i, int j) {
            const std::size_t k = index(i, j);
            return features[k] && ids[k] == id;
        };
        auto isQuery = [&](int i, int j) {
            const std::size_t k = index(i, j);
            return queries[k] && ids[k] == id;
        };
        bool anyFeature = false, anyQuery = false;
        for (int j = b.j0; j <= b.j1 && !(anyFeature && anyQuery); ++j)
            for (int i = b.i0; i <= b.i1; ++i) {
                anyFeature = anyFeature || isFeature(i, j);
                anyQuery = anyQuery || isQuery(i, j);
            }
        if (!anyFeature || !anyQuery) continue;  // infinity, or nothing asked

        std::vector<double> squared(std::size_t(bw) * bh);
        forRowBands(bw, rowBandCount(bw, bh), [&](int, int first, int end) {
            nearestInColumns(b, first, end, isFeature, squared);
        });
        forRowBands(bh, rowBandCount(bh, bw), [&](int, int first, int end) {
            std::vector<double> f(bw), d(bw), from(bw + 1);
            std::vector<int> root(bw);
            for (int r = first; r < end; ++r) {
                const int j = b.j0 + r;
                bool asked = false;
                for (int i = b.i0; i <= b.i1 && !asked; ++i) asked = isQuery(i, j);
                if (!asked) continue;
                std::copy_n(&squared[std::size_t(r) * bw], bw, f.begin());
                squaredDistanceLine(f, d, root, from);
                for (int i = b.i0; i <= b.i1; ++i)
                    if (isQuery(i, j)) out[index(i, j)] = float(std::sqrt(d[i - b.i0]));
            }
        });
    }
    return distance;
}

}  // namespace sl
