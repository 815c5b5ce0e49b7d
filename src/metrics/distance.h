// Exact Euclidean distance transforms for the shadow figures (Felzenszwalb and Huttenlocher's
// separable one): over a whole grid, and within the objects of a reference image.
#pragma once

#include <cstdint>
#include <vector>

#include "reference/raytracer.h"

namespace sl {

// Exact Euclidean distance transform: for every pixel of a width x height grid, the distance in
// pixels to the nearest pixel with feature[k] != 0 (+infinity when there is none).
std::vector<float> distanceToFeatures(const std::vector<std::uint8_t>& feature, int width,
                                      int height);

// Per object id, the box of its pixels in `within` (the only pixels that may be features or
// queries below), found once per view.
struct ObjectBoxes {
    struct Box {
        int i0 = 0, j0 = 0, i1 = -1, j1 = -1;  // inclusive; empty when i1 < i0
    };
    std::vector<Box> byId;  // index: object id
};
ObjectBoxes objectBoxes(const ReferenceImage& ref, const std::vector<std::uint8_t>& within);

// For each pixel with query[k], the distance to the nearest pixel with feature[k] showing the
// same object (+infinity when that object has none); +infinity where nothing is asked. Features
// and queries lie in the pixels `boxes` were found over. The same numbers as distanceToFeatures
// over each object's own pixels, found with less work: the column pass is a nearest-feature
// scan (for a 0-or-infinity input it is one), the row pass runs only on rows with a query, and
// large objects are split over threads.
// `objectIds` is per pixel, row-major, `width` pixels a row (a reference's object ids).
std::vector<float> distanceWithinObjects(const std::vector<int>& objectIds, int width,
                                         const ObjectBoxes& boxes,
                                         const std::vector<std::uint8_t>& feature,
                                         const std::vector<std::uint8_t>& query);

}  // namespace sl
