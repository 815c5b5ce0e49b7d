#include "scene/displace.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace sl {

namespace {

// [0, 1) from 53 bits of the generator (std::uniform_real_distribution is not the same on every
// standard library, and a seed in the report must repeat the same view anywhere).
double unit(std::mt19937_64& g) {
    return double(g() >> 11) * (1.0 / 9007199254740992.0);
}

glm::vec3 turned(const glm::vec3& p, const glm::vec3& centre, const glm::vec3& axis, float deg) {
    float a = glm::radians(deg), c = std::cos(a), s = std::sin(a);
    glm::vec3 v = p - centre;
    // Rodrigues' rotation about a unit axis.
    return centre + v * c + glm::cross(axis, v) * s + axis * glm::dot(axis, v) * (1.0f - c);
}

// Two unit vectors spanning the plane perpendicular to `n`.
void planeBasis(const glm::vec3& n, glm::vec3& u, glm::vec3& v) {
    glm::vec3 other = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    u = glm::normalize(glm::cross(n, other));
    v = glm::cross(n, u);
}

}  // namespace

Displacement displacementFor(std::uint64_t seed) {
    std::mt19937_64 g(seed);
    Displacement d;
    d.casterTurnDegrees = float(40.0 + 280.0 * unit(g));
    d.casterShift = {float(0.3 * unit(g) - 0.15), float(0.3 * unit(g) - 0.15)};
    double light = 15.0 + 20.0 * unit(g);
    d.lightTurnDegrees = float(unit(g) < 0.5 ? -light : light);
    return d;
}

glm::vec3 receiverNormal(const Scene& scene) {
    for (const Object& o : scene.objects) {
        if (o.castsShadow) continue;
        if (o.kind == PrimitiveKind::Quad) return glm::normalize(o.normal);
        if (o.kind == PrimitiveKind::Box) {
            int thin = 0;
            for (int k = 1; k < 3; ++k)
                if (o.size[k] < o.size[thin]) thin = k;
            glm::vec3 n(0);
            n[thin] = 1;
            return n;
        }
    }
    return {0, 1, 0};
}

Scene displacedScene(const Scene& scene, const Displacement& d) {
    Scene out = scene;
    glm::vec3 axis = receiverNormal(scene);
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const Object& o : scene.objects)
        if (o.castsShadow) {
            lo = glm::min(lo, o.center);
            hi = glm::max(hi, o.center);
        }
    if (lo.x > hi.x) return out;  // nothing casts: nothing to move
    glm::vec3 centre = 0.5f * (lo + hi);
    glm::vec3 u, v;
    planeBasis(axis, u, v);
    float extent = std::max(glm::length(hi - lo), 1.0f);
    glm::vec3 shift = extent * (d.casterShift.x * u + d.casterShift.y * v);
    for (Object& o : out.objects)
        if (o.castsShadow) {
            o.center = turned(o.center, centre, axis, d.casterTurnDegrees) + shift;
            o.normal = turned(o.normal, glm::vec3(0), axis, d.casterTurnDegrees);  // quads turn
            o.up = turned(o.up, glm::vec3(0), axis, d.casterTurnDegrees);
        }
    out.light.position = turned(scene.light.position, scene.light.target, axis, d.lightTurnDegrees);
    return out;
}

}  // namespace sl
