// The hierarchy the reference tracer walks: it must offer every object whose bounds a ray
// meets (a dropped candidate would be a missed hit or a missed shadow), and the bounds must hold
// each primitive.
#include <gtest/gtest.h>

#include <random>
#include <set>

#include "reference/object_bvh.h"

using namespace sl;

namespace {

std::vector<Object> randomObjects(int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> pos(-5.0f, 5.0f), size(0.01f, 1.5f), unit(-1.0f, 1.0f);
    std::vector<Object> objects;
    for (int k = 0; k < count; ++k) {
        Object o;
        o.kind = PrimitiveKind(k % 3);
        o.center = {pos(rng), pos(rng), pos(rng)};
        o.size = {size(rng), size(rng), size(rng)};
        o.radius = size(rng);
        o.normal =
            glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)) + glm::vec3(0, 1e-3f, 0));
        o.up = glm::vec3(0, 0, 1);
        o.width = size(rng);
        o.height = size(rng);
        o.castsShadow = k % 4 != 0;
        objects.push_back(o);
    }
    return objects;
}

}  // namespace

TEST(ObjectBvh, OffersEveryObjectWhoseBoundsTheRayMeets) {
    const std::vector<Object> objects = randomObjects(1000, 7);
    std::vector<ObjectBounds> bounds;
    for (const Object& o : objects) bounds.push_back(objectBounds(o));
    ObjectBvh bvh(objects, [](const Object&) { return true; });
    EXPECT_GT(bvh.nodeCount(), 250u);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> pos(-7.0f, 7.0f), unit(-1.0f, 1.0f);
    long offered = 0;
    for (int r = 0; r < 2000; ++r) {
        glm::vec3 d(unit(rng), unit(rng), unit(rng));
        if (r % 10 == 0) d.y = 0.0f;  // parallel to a pair of planes
        if (glm::length(d) < 1e-3f) continue;
        Ray ray{{pos(rng), pos(rng), pos(rng)}, glm::normalize(d)};
        const float tMax = r % 2 ? 1e30f : 4.0f;
        const glm::vec3 inverse = 1.0f / ray.direction;
        std::set<int> expected, got;
        for (std::size_t k = 0; k < objects.size(); ++k)
            if (rayMeetsBounds(bounds[k], ray, inverse, 1e-4f, tMax)) expected.insert(int(k));
        bvh.forEachCandidate(ray, 1e-4f, tMax, [&](int k, float&) {
            EXPECT_TRUE(got.insert(k).second) << "object " << k << " offered twice";
            return false;
        });
        EXPECT_EQ(got, expected) << "ray " << r;
        offered += long(got.size());
    }
    // It prunes: a ray meets a few dozen of the thousand boxes, not all of them.
    EXPECT_LT(offered, 2000L * 100);
}

TEST(ObjectBvh, OnlyTheObjectsKeptAndNoneWhenEmpty) {
    const std::vector<Object> objects = randomObjects(200, 3);
    ObjectBvh casters(objects, [](const Object& o) { return o.castsShadow; });
    Ray ray{{0, -100, 0}, {0, 1, 0}};
    casters.forEachCandidate(ray, 0.0f, 1e30f, [&](int k, float&) {
        EXPECT_TRUE(objects[std::size_t(k)].castsShadow) << k;
        return false;
    });
    ObjectBvh none(std::vector<Object>{}, [](const Object&) { return true; });
    int calls = 0;
    none.forEachCandidate(ray, 0.0f, 1e30f, [&](int, float&) { return ++calls, false; });
    EXPECT_EQ(calls, 0);
}

TEST(ObjectBvh, BoundsHoldEachPrimitive) {
    Object sphere;
    sphere.kind = PrimitiveKind::Sphere;
    sphere.center = {1, 2, 3};
    sphere.radius = 0.5f;
    ObjectBounds b = objectBounds(sphere);
    EXPECT_LE(b.lo.x, 0.5f);
    EXPECT_GE(b.hi.z, 3.5f);
    Object quad;  // the lecture's floor quad: 3 x 3 in y = 0
    quad.kind = PrimitiveKind::Quad;
    quad.normal = {0, 1, 0};
    quad.up = {0, 0, -1};
    quad.width = quad.height = 3;
    b = objectBounds(quad);
    EXPECT_NEAR(b.lo.x, -1.5f, 1e-3f);
    EXPECT_NEAR(b.hi.z, 1.5f, 1e-3f);
    EXPECT_LT(b.hi.y - b.lo.y, 1e-2f);  // flat, padded a little
}
