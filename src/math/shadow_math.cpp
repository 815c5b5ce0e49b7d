#include "math/shadow_math.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>

#include "math/camera.h"

namespace sl {

namespace {

constexpr float kMaxFovyDegrees = 170.0f;
constexpr float kFovMargin = 1.02f;       // on the half-angle
constexpr float kNearShrink = 0.95f;      // tight near sits a little in front of the nearest corner
constexpr float kFarGrow = 1.01f;         // and far a little behind the farthest
constexpr float kMinNearOverFar = 1e-3f;  // never let near collapse to 0 (depth precision)
constexpr float kSphereTooClose = 1.05f;  // d < 1.05 r: sphere fit falls back to tight
constexpr float kSphereMinNear = 0.01f;   // sphere near >= 0.01 r

std::string format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
std::string format(const char* fmt, ...) {
    char buf[256];
    va_list args;
    va_start(args, fmt);
    std::vsnprintf(buf, sizeof buf, fmt, args);
    va_end(args);
    return buf;
}

// lookAt that survives target == eye (looks down -Y then) and a view direction along +-Y.
glm::mat4 lightView(const glm::vec3& eye, glm::vec3 at) {
    if (glm::length(at - eye) < 1e-6f) at = eye + glm::vec3(0, -1, 0);
    return glm::lookAt(eye, at, safeUp(eye, at));
}

template <class Visit>
void forEachCorner(const std::vector<Aabb>& boxes, const Visit& visit) {
    for (const Aabb& b : boxes)
        for (int i = 0; i < 8; ++i)
            visit(glm::vec3(i & 1 ? b.hi.x : b.lo.x, i & 2 ? b.hi.y : b.lo.y,
                            i & 4 ? b.hi.z : b.lo.z));
}

LightFrustum fixedFit(const glm::vec3& light, const glm::vec3& target, const std::string& why) {
    LightFrustum f;
    f.view = lightView(light, target);
    f.projection = glm::frustum(-1.0f, 1.0f, -1.0f, 1.0f, 1.0f, 100.0f);
    f.zNear = 1.0f;
    f.zFar = 100.0f;
    f.fovyDegrees = 90.0f;  // half-height 1 at distance 1
    f.used = LightFit::Fixed;
    f.note = "fixed: the lab's frustum(-1,1,-1,1,1,100), fovy 90" + why;
    return f;
}

LightFrustum tightFit(const glm::vec3& light, const glm::vec3& target,
                      const std::vector<Aabb>& boxes) {
    glm::mat4 view = lightView(light, target);
    float minDepth = INFINITY, maxDepth = -INFINITY, maxHalfAngle = 0.0f;
    int corners = 0, behind = 0;
    forEachCorner(boxes, [&](const glm::vec3& p) {
        glm::vec3 v = glm::vec3(view * glm::vec4(p, 1.0f));
        float depth = -v.z;
        ++corners;
        if (depth <= 0.0f) ++behind;
        minDepth = std::min(minDepth, depth);
        maxDepth = std::max(maxDepth, depth);
        // atan2 gives >= 90 degrees for corners beside or behind the light: the cap handles them.
        maxHalfAngle =
            std::max(maxHalfAngle, std::atan2(std::max(std::abs(v.x), std::abs(v.y)), depth));
    });
    if (corners == 0) return fixedFit(light, target, " (tight fit: no boxes)");
    if (!(maxDepth > 0.0f) || !std::isfinite(maxDepth))
        return fixedFit(light, target, " (tight fit: every corner is behind the light)");

    LightFrustum f;
    f.view = view;
    f.used = LightFit::Tight;
    f.zFar = maxDepth * kFarGrow;
    f.zNear = std::max(minDepth * kNearShrink, kMinNearOverFar * maxDepth);
    float fovy = std::min(2.0f * glm::degrees(maxHalfAngle) * kFovMargin, kMaxFovyDegrees);
    f.fovyDegrees = fovy;
    f.projection = glm::perspective(glm::radians(fovy), 1.0f, f.zNear, f.zFar);
    f.note = format(
        "tight: %d corners at depth %.3g..%.3g -> near %.3g far %.3g fovy %.1f (far/near %.3g)",
        corners, minDepth, maxDepth, f.zNear, f.zFar, fovy, f.zFar / f.zNear);
    if (behind > 0)
        f.note += format(
            "; %d corners behind or at the light: near clamped to 1e-3 far, they are not covered",
            behind);
    else if (fovy >= kMaxFovyDegrees)
        f.note += "; fovy capped at 170: corners beside the light are not covered";
    return f;
}

LightFrustum sphereFit(const glm::vec3& light, const glm::vec3& target,
                       const std::vector<Aabb>& boxes) {
    BoundingSphere s = boundingSphere(boxes);
    float d = glm::length(s.center - light);
    float r = s.radius;
    if (!(r > 0.0f) || d < kSphereTooClose * r) {
        LightFrustum f = tightFit(light, target, boxes);
        f.note =
            format(
                "sphere fit refused (light at d=%.3g from the centre, r=%.3g: needs d >= 1.05 r), ",
                d, r) +
            f.note;
        return f;
    }
    LightFrustum f;
    f.view = lightView(light, s.center);
    f.used = LightFit::Sphere;
    f.zNear = std::max(d - r, kSphereMinNear * r);
    f.zFar = d + r;
    // The cone from the light tangent to the sphere: sin(half-angle) = r / d.
    f.fovyDegrees = 2.0f * glm::degrees(std::asin(r / d));
    f.projection = glm::perspective(glm::radians(f.fovyDegrees), 1.0f, f.zNear, f.zFar);
    f.note =
        format("sphere: centre at d=%.3g, r=%.3g -> near %.3g far %.3g fovy %.1f (far/near %.3g)",
               d, r, f.zNear, f.zFar, f.fovyDegrees, f.zFar / f.zNear);
    return f;
}

}  // namespace

glm::mat4 biasMatrix(float zScale) {
    // GLM is column-major: m[column][row]. The translation 0.5 sits in the last column.
    glm::mat4 m(1.0f);
    m[0][0] = 0.5f;
    m[1][1] = 0.5f;
    m[2][2] = zScale;
    m[3][0] = 0.5f;
    m[3][1] = 0.5f;
    m[3][2] = 0.5f;
    return m;
}

glm::mat4 depthFlippedProjection(const glm::mat4& p) {
    glm::mat4 flip(1.0f);
    flip[2][2] = -1.0f;
    return flip * p;
}

BoundingSphere boundingSphere(const std::vector<Aabb>& boxes) {
    if (boxes.empty()) return {glm::vec3(0.0f), 0.0f};
    glm::vec3 lo = boxes.front().lo, hi = boxes.front().hi;
    for (const Aabb& b : boxes) {
        lo = glm::min(lo, glm::min(b.lo, b.hi));
        hi = glm::max(hi, glm::max(b.lo, b.hi));
    }
    glm::vec3 center = 0.5f * (lo + hi);
    return {center, glm::length(hi - center)};
}

LightFrustum fitLightFrustum(const glm::vec3& light, const glm::vec3& target,
                             const std::vector<Aabb>& boxes, LightFit fit) {
    switch (fit) {
        case LightFit::Tight:
            return tightFit(light, target, boxes);
        case LightFit::Sphere:
            return sphereFit(light, target, boxes);
        case LightFit::Fixed:
            break;
    }
    return fixedFit(light, target, "");
}

LightFrustum withFarOverNear(LightFrustum f, float ratio) {
    if (!(ratio > 1.0f) || !std::isfinite(ratio)) return f;
    f.zNear = f.zFar / ratio;
    f.projection = glm::perspective(glm::radians(f.fovyDegrees), 1.0f, f.zNear, f.zFar);
    f.note += format("; near moved to far/%.6g = %.3g (far-near)", ratio, f.zNear);
    return f;
}

float farOverNear(const LightFrustum& f) {
    return f.zFar / f.zNear;
}

const char* lightFitName(LightFit fit) {
    switch (fit) {
        case LightFit::Tight:
            return "tight";
        case LightFit::Sphere:
            return "sphere";
        case LightFit::Fixed:
            // not a stage id: the light fit "fixed"
            return "fixed";
    }
    return "?";
}

}  // namespace sl
