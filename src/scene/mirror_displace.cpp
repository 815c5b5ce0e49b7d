#include "scene/mirror_displace.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "scene/displace.h"

namespace sl {

namespace {

// [0, 1) from 53 bits of the generator, as displace.cpp draws (the same on every library).
double unit(std::mt19937_64& g) {
    return double(g() >> 11) * (1.0 / 9007199254740992.0);
}

double eitherWay(std::mt19937_64& g, double lo, double hi) {
    double v = lo + (hi - lo) * unit(g);
    return unit(g) < 0.5 ? -v : v;
}

// How far an object reaches along unit `n`: its centre's offset plus and minus this.
float reachAlong(const Object& o, const glm::vec3& n) {
    if (o.kind == PrimitiveKind::Sphere) return o.radius;
    if (o.kind == PrimitiveKind::Box) return glm::dot(0.5f * o.size, glm::abs(n));
    glm::vec3 up = glm::normalize(o.up), right = glm::normalize(glm::cross(up, o.normal));
    return 0.5f * (o.width * std::abs(glm::dot(right, n)) + o.height * std::abs(glm::dot(up, n)));
}

// The camera turned about `axis` through its target, raised or lowered within 15..60 degrees
// above the plane across `axis`, and moved nearer or farther.
Camera turnedCamera(const Camera& camera, const glm::vec3& axis, const MirrorDisplacement& d) {
    glm::vec3 offset = camera.eye - camera.at;
    float length = glm::length(offset);
    glm::vec3 across = offset - glm::dot(offset, axis) * axis;
    if (length < 1e-6f || glm::length(across) < 1e-6f) return camera;
    float a = glm::radians(d.cameraTurnDegrees), c = std::cos(a), s = std::sin(a);
    glm::vec3 side = glm::normalize(across);
    side = side * c + glm::cross(axis, side) * s;  // Rodrigues: side is perpendicular to axis
    float elevation = glm::degrees(std::atan2(glm::dot(offset, axis), glm::length(across)));
    elevation = std::clamp(elevation + d.cameraElevationDegrees, 15.0f, 60.0f);
    float e = glm::radians(elevation), r = length * d.cameraDistanceScale;
    Camera out = camera;
    out.eye = camera.at + r * (std::cos(e) * side + std::sin(e) * axis);
    return out;
}

}  // namespace

MirrorDisplacement mirrorDisplacementFor(std::uint64_t seed) {
    std::mt19937_64 g(seed);
    MirrorDisplacement d;
    d.cameraTurnDegrees = float(eitherWay(g, 15.0, 35.0));
    d.cameraElevationDegrees = float(20.0 * unit(g) - 10.0);
    d.cameraDistanceScale = float(0.85 + 0.3 * unit(g));
    d.mirrorSlide = float(eitherWay(g, 0.05, 0.10));
    d.mirrorAdvance = float(0.2 * unit(g));
    return d;
}

Scene displacedMirrorScene(const Scene& scene, const MirrorDisplacement& d) {
    if (!scene.mirror) return scene;
    Scene out = scene;
    Mirror& m = *out.mirror;
    const glm::vec3 n = glm::normalize(m.normal), up = glm::normalize(m.up);
    const glm::vec3 right = glm::normalize(glm::cross(up, n));
    // Behind the plane (its frame, what it hides) moves with it; wholly in front limits how far
    // it may come forward: 0.1 short of the nearest such object.
    std::vector<bool> behind(scene.objects.size(), false);
    float room = INFINITY;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        float offset = glm::dot(o.center - m.center, n), reach = reachAlong(o, n);
        if (offset + reach <= 1e-3f)
            behind[i] = true;
        else if (offset - reach > 0.0f)
            room = std::min(room, offset - reach - 0.1f);
    }
    float advance = std::clamp(d.mirrorAdvance * m.height, 0.0f, std::max(room, 0.0f));
    glm::vec3 move = d.mirrorSlide * m.width * right + advance * n;
    m.center += move;
    for (std::size_t i = 0; i < out.objects.size(); ++i)
        if (behind[i]) out.objects[i].center += move;
    out.camera = turnedCamera(scene.camera, up, d);
    return out;
}

Scene displacedViewOf(const Scene& scene, std::uint64_t seed) {
    return scene.mirror ? displacedMirrorScene(scene, mirrorDisplacementFor(seed))
                        : displacedScene(scene, displacementFor(seed));
}

}  // namespace sl
