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

// The box a caster occupies (a sphere's, a quad's whole square: a bound is enough).
void bounds(const Object& o, const glm::vec3& centre, glm::vec3& lo, glm::vec3& hi) {
    glm::vec3 half = o.kind == PrimitiveKind::Box ? 0.5f * o.size
                     : o.kind == PrimitiveKind::Sphere
                         ? glm::vec3(o.radius)
                         : glm::vec3(0.5f * std::max(o.width, o.height));
    lo = centre - half;
    hi = centre + half;
}

// Whether two casters, turned by `turn`, come closer than a small gap.
bool castersOverlap(const Scene& scene, const glm::vec3& centre, const glm::vec3& axis,
                    float turn) {
    const float gap = 0.02f;
    for (std::size_t a = 0; a < scene.objects.size(); ++a)
        for (std::size_t b = a + 1; b < scene.objects.size(); ++b) {
            const Object &p = scene.objects[a], &q = scene.objects[b];
            if (!p.castsShadow || !q.castsShadow) continue;
            glm::vec3 plo, phi, qlo, qhi;
            bounds(p, turned(p.center, centre, axis, turn), plo, phi);
            bounds(q, turned(q.center, centre, axis, turn), qlo, qhi);
            if (glm::all(glm::lessThan(plo - gap, qhi)) && glm::all(glm::lessThan(qlo - gap, phi)))
                return true;
        }
    return false;
}

// The camera moved by `d` about its target `at` (already moved with the casters): the eye's
// offset split into its height along `axis` and its direction in the receiver's plane; that
// direction set `d.cameraTurnDegrees` away from the light's (seen from the light's own side the
// casters hide their shadows; a light straight above the receiver leaves the camera's own
// direction to turn from), its elevation changed within 15..75 degrees, its length scaled.
Camera movedCamera(const Camera& camera, const glm::vec3& at, const Light& light,
                   const glm::vec3& axis, const Displacement& d) {
    auto across = [&](const glm::vec3& w) { return w - glm::dot(w, axis) * axis; };
    glm::vec3 offset = camera.eye - camera.at;
    float length = glm::length(offset);
    if (length < 1e-6f) return camera;
    glm::vec3 u, v;
    planeBasis(axis, u, v);
    glm::vec3 fromLight = across(light.position - light.target);
    glm::vec3 own = across(offset);
    glm::vec3 side = glm::length(fromLight) > 1e-3f * glm::length(light.position - light.target)
                         ? fromLight
                     : glm::length(own) > 1e-6f ? own
                                                : u;
    side = glm::normalize(turned(glm::normalize(side), glm::vec3(0), axis, d.cameraTurnDegrees));
    float elevation = glm::degrees(std::atan2(glm::dot(offset, axis), glm::length(own)));
    elevation = std::clamp(elevation + d.cameraElevationDegrees, 15.0f, 75.0f);
    float e = glm::radians(elevation), r = length * d.cameraDistanceScale;
    Camera out = camera;
    out.at = at;
    out.eye = at + r * (std::cos(e) * side + std::sin(e) * axis);
    return out;
}

}  // namespace

Displacement displacementFor(std::uint64_t seed) {
    std::mt19937_64 g(seed);
    Displacement d;
    d.casterTurnDegrees = float(40.0 + 280.0 * unit(g));
    d.casterShift = {float(0.3 * unit(g) - 0.15), float(0.3 * unit(g) - 0.15)};
    double light = 10.0 + 10.0 * unit(g);
    d.lightTurnDegrees = float(unit(g) < 0.5 ? -light : light);
    d.cameraTurnDegrees = float(50.0 + 260.0 * unit(g));
    d.cameraElevationDegrees = float(20.0 * unit(g) - 10.0);
    d.cameraDistanceScale = float(0.85 + 0.3 * unit(g));
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
    // Casters that would run into each other (intersecting solids leave slivers no method can
    // resolve, which our shaders would fail on too) turn on by 23 degrees steps until apart.
    float turn = d.casterTurnDegrees;
    for (int tries = 0; tries < 16 && castersOverlap(scene, centre, axis, turn); ++tries)
        turn += 23.0f;
    for (Object& o : out.objects)
        if (o.castsShadow) {
            o.center = turned(o.center, centre, axis, turn) + shift;
            o.normal = turned(o.normal, glm::vec3(0), axis, turn);  // quads turn
            o.up = turned(o.up, glm::vec3(0), axis, turn);
        }
    out.light.position = turned(scene.light.position, scene.light.target, axis, d.lightTurnDegrees);
    out.camera = movedCamera(scene.camera, turned(scene.camera.at, centre, axis, turn) + shift,
                             out.light, axis, d);
    return out;
}

}  // namespace sl
