#include "reference/object_bvh.h"

#include <algorithm>
#include <cmath>

namespace sl {

namespace {

constexpr int kLeafSize = 4;  // depth stays under 12 for 4,096 objects: the stack of 64 is ample

ObjectBounds merged(const ObjectBounds& a, const ObjectBounds& b) {
    return {glm::min(a.lo, b.lo), glm::max(a.hi, b.hi)};
}

ObjectBounds padded(glm::vec3 lo, glm::vec3 hi) {
    const glm::vec3 pad = 1e-4f * (glm::abs(lo) + glm::abs(hi) + glm::vec3(1.0f));
    return {lo - pad, hi + pad};
}

}  // namespace

ObjectBounds objectBounds(const Object& object) {
    switch (object.kind) {
        case PrimitiveKind::Box: {
            const glm::vec3 half = 0.5f * glm::abs(object.size);
            return padded(object.center - half, object.center + half);
        }
        case PrimitiveKind::Sphere:
            return padded(object.center - glm::vec3(std::abs(object.radius)),
                          object.center + glm::vec3(std::abs(object.radius)));
        case PrimitiveKind::Quad: {  // the same axes as the exact test (intersectRectangle)
            const glm::vec3 n = glm::normalize(object.normal);
            const glm::vec3 right = glm::normalize(glm::cross(object.up, n));
            const glm::vec3 up = glm::cross(n, right);
            const glm::vec3 half = glm::abs(right) * (0.5f * std::abs(object.width)) +
                                   glm::abs(up) * (0.5f * std::abs(object.height));
            return padded(object.center - half, object.center + half);
        }
    }
    return {};
}

bool rayMeetsBounds(const ObjectBounds& b, const Ray& ray, const glm::vec3& inverseDirection,
                    float tMin, float tMax) {
    for (int axis = 0; axis < 3; ++axis) {
        const float d = ray.direction[axis];
        if (d == 0.0f) {  // parallel to this pair of planes: inside them or never
            if (ray.origin[axis] < b.lo[axis] || ray.origin[axis] > b.hi[axis]) return false;
            continue;
        }
        float t0 = (b.lo[axis] - ray.origin[axis]) * inverseDirection[axis];
        float t1 = (b.hi[axis] - ray.origin[axis]) * inverseDirection[axis];
        if (t0 > t1) std::swap(t0, t1);
        tMin = std::max(tMin, t0);
        tMax = std::min(tMax, t1);
        if (tMin > tMax) return false;
    }
    return true;
}

// Splits items [begin, end) at the median of their centres along the widest axis of those
// centres. Returns the node's index.
int ObjectBvh::build(int begin, int end) {
    const int index = int(nodes_.size());
    nodes_.emplace_back();
    ObjectBounds bounds = items_[std::size_t(begin)].bounds;
    ObjectBounds centres{0.5f * (bounds.lo + bounds.hi), 0.5f * (bounds.lo + bounds.hi)};
    for (int k = begin; k < end; ++k) {
        const ObjectBounds& b = items_[std::size_t(k)].bounds;
        bounds = merged(bounds, b);
        const glm::vec3 c = 0.5f * (b.lo + b.hi);
        centres = merged(centres, {c, c});
    }
    nodes_[std::size_t(index)].bounds = bounds;
    if (end - begin <= kLeafSize) {
        nodes_[std::size_t(index)].first = begin;
        nodes_[std::size_t(index)].count = end - begin;
        return index;
    }
    const glm::vec3 extent = centres.hi - centres.lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                     : extent.y >= extent.z                       ? 1
                                                                  : 2;
    const int middle = begin + (end - begin) / 2;
    std::nth_element(items_.begin() + begin, items_.begin() + middle, items_.begin() + end,
                     [axis](const Item& a, const Item& b) {
                         return a.bounds.lo[axis] + a.bounds.hi[axis] <
                                b.bounds.lo[axis] + b.bounds.hi[axis];
                     });
    const int left = build(begin, middle);
    const int right = build(middle, end);
    nodes_[std::size_t(index)].left = left;
    nodes_[std::size_t(index)].right = right;
    return index;
}

}  // namespace sl
