#include "math/orbit.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sl {

float sceneFloorHeight(const Scene& scene) {
    float lowest = std::numeric_limits<float>::infinity();
    for (const Object& o : scene.objects) {
        float y = o.center.y;
        if (o.kind == PrimitiveKind::Box) y -= 0.5f * o.size.y;
        if (o.kind == PrimitiveKind::Sphere) y -= o.radius;
        if (o.kind == PrimitiveKind::Quad) {  // half its extent along the world's y
            glm::vec3 right = glm::normalize(glm::cross(o.up, o.normal));
            y -= 0.5f * (std::abs(o.up.y) * o.height + std::abs(right.y) * o.width);
        }
        lowest = std::min(lowest, y);
    }
    return std::isfinite(lowest) ? lowest : 0.0f;
}

float sceneReceiverHeight(const Scene& scene) {
    const Object* lowest = nullptr;
    float bottom = std::numeric_limits<float>::infinity();
    for (const Object& o : scene.objects) {
        Scene one;
        one.objects = {o};
        const float b = sceneFloorHeight(one);
        if (b < bottom) bottom = b, lowest = &o;
    }
    if (!lowest) return 0.0f;
    const Object& o = *lowest;
    if (o.kind == PrimitiveKind::Box && o.size.y * 4 <= std::min(o.size.x, o.size.z))
        return o.center.y + 0.5f * o.size.y;  // a slab: its top
    if (o.kind == PrimitiveKind::Quad && std::abs(glm::normalize(o.normal).y) > 0.99f)
        return o.center.y;  // a horizontal quad
    return bottom;
}

Camera orbitCamera(const Camera& c, float yaw, float pitch, float floorY, float clearance) {
    glm::vec3 d = c.eye - c.at;
    float radius = glm::length(d);
    if (radius < 1e-6f) return c;
    float currentYaw = std::atan2(d.x, d.z) + yaw;
    float currentPitch = std::asin(glm::clamp(d.y / radius, -1.0f, 1.0f)) + pitch;
    // eye.y = at.y + radius * sin(pitch) must stay above the floor plus the clearance.
    float lowestSin = (floorY + clearance - c.at.y) / radius;
    float lowest = lowestSin >= 1.0f ? 1.5f : lowestSin <= -1.0f ? -1.5f : std::asin(lowestSin);
    currentPitch = glm::clamp(currentPitch, std::min(lowest, 1.5f), 1.5f);
    Camera out = c;
    out.eye = c.at + radius * glm::vec3(std::cos(currentPitch) * std::sin(currentYaw),
                                        std::sin(currentPitch),
                                        std::cos(currentPitch) * std::cos(currentYaw));
    return out;
}

glm::vec3 circlingLight(const glm::vec3& start, float radiansPerSecond, double seconds) {
    float radius = std::hypot(start.x, start.z);
    double angle = std::atan2(start.z, start.x) + radiansPerSecond * seconds;
    return {radius * static_cast<float>(std::cos(angle)), start.y,
            radius * static_cast<float>(std::sin(angle))};
}

}  // namespace sl

namespace sl {

Camera zoomCamera(const Camera& c, float factor) {
    const glm::vec3 offset = c.eye - c.at;
    const float distance = glm::length(offset);
    if (!(distance > 0) || !(factor > 0)) return c;
    const float wanted = std::clamp(distance * factor, 2 * c.zNear, 0.5f * c.zFar);
    Camera out = c;
    out.eye = c.at + offset * (wanted / distance);
    return out;
}

float fovyFittingWidth(float fovyDegrees, float aspect) {
    if (!(aspect < kFramedAspect)) return fovyDegrees;
    const float half = glm::radians(fovyDegrees) / 2;
    return std::min(150.0f, glm::degrees(2 * std::atan(std::tan(half) * kFramedAspect / aspect)));
}

}  // namespace sl
