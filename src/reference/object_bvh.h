// A bounding volume hierarchy over a scene's objects, so that a ray tests the few objects near
// its path instead of all of them: a 4,096-object scene (the scene parser's limit) traces in
// seconds instead of minutes. It only picks candidates; the exact tests stay in raytracer.cpp.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "math/camera.h"
#include "scene/scene.h"

namespace sl {

struct ObjectBounds {
    glm::vec3 lo{0.0f}, hi{0.0f};
};

// The box around an object: a box's own, a sphere's cube, a quad's four corners; padded by a
// little so that rounding in the slab test never drops a grazing hit.
ObjectBounds objectBounds(const Object& object);

// Whether the ray meets `b` somewhere with t in [tMin, tMax] (the slab method).
bool rayMeetsBounds(const ObjectBounds& b, const Ray& ray, const glm::vec3& inverseDirection,
                    float tMin, float tMax);

class ObjectBvh {
  public:
    // Over the objects `keep` accepts (all, or the shadow casters), by their index in `objects`.
    template <class Keep>
    ObjectBvh(const std::vector<Object>& objects, Keep keep) {
        for (std::size_t k = 0; k < objects.size(); ++k)
            if (keep(objects[k])) items_.push_back({objectBounds(objects[k]), int(k)});
        if (!items_.empty()) build(0, int(items_.size()));
    }

    // Calls visit(objectIndex, tMax&) for every object whose bounds the ray meets within
    // [tMin, tMax]; visit may lower tMax (nearest hit so far) or return true to stop.
    template <class Visit>
    void forEachCandidate(const Ray& ray, float tMin, float tMax, Visit visit) const {
        if (nodes_.empty()) return;
        const glm::vec3 inverse = 1.0f / ray.direction;
        int stack[64];
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const Node& node = nodes_[std::size_t(stack[--top])];
            if (!rayMeetsBounds(node.bounds, ray, inverse, tMin, tMax)) continue;
            if (node.count > 0) {
                for (int k = node.first; k < node.first + node.count; ++k) {
                    const Item& item = items_[std::size_t(k)];
                    if (rayMeetsBounds(item.bounds, ray, inverse, tMin, tMax) &&
                        visit(item.object, tMax))
                        return;
                }
            } else {
                stack[top++] = node.right;  // popped after the left one
                stack[top++] = node.left;
            }
        }
    }

    std::size_t nodeCount() const { return nodes_.size(); }

  private:
    struct Item {
        ObjectBounds bounds;
        int object;
    };
    struct Node {
        ObjectBounds bounds;
        int first = 0, count = 0;   // a leaf's items; count 0 inside
        int left = -1, right = -1;  // an inner node's children
    };
    int build(int begin, int end);
    std::vector<Item> items_;
    std::vector<Node> nodes_;
};

}  // namespace sl
