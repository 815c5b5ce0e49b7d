#include "math/mirror_topview.h"

#include <algorithm>
#include <cmath>

namespace sl {

namespace {

glm::vec2 xz(const glm::vec3& v) {
    return {v.x, v.z};
}

bool finite(const glm::vec2& v) {
    return std::isfinite(v.x) && std::isfinite(v.y);
}

}  // namespace

MirrorTopView mirrorTopView(const Mirror& mirror, const glm::vec3& eye, const glm::vec3& at,
                            const MirrorCamera& camera) {
    MirrorTopView v;
    v.eye = xz(eye);
    v.at = xz(at);
    if (!camera.valid) {
        v.reason = camera.reason;
        return v;
    }
    glm::vec3 right = mirrorRight(mirror) * (0.5f * mirror.width);
    v.p1 = xz(mirror.center - right);
    v.p2 = xz(mirror.center + right);
    glm::vec2 n = xz(mirror.normal);
    if (!(glm::length(n) > 1e-6f)) {
        v.reason = "the mirror lies flat: seen from above it has no line to reflect in";
        return v;
    }
    v.normal = glm::normalize(n);
    v.eyePrime = xz(camera.eye);
    v.atPrime = xz(camera.at);
    v.left = camera.left;
    v.right = camera.right;
    v.zNear = camera.zNear;
    v.zFar = camera.zFar;
    // p1 and p2 lie at depth near'; the side lines reach depth far' at far'/near' times as far.
    float stretch = camera.zFar / camera.zNear;
    v.far1 = v.eyePrime + stretch * (v.p1 - v.eyePrime);
    v.far2 = v.eyePrime + stretch * (v.p2 - v.eyePrime);
    v.valid = true;
    return v;
}

MirrorTopView practiceTopView(const glm::vec2& p1, const glm::vec2& p2, const glm::vec2& eye,
                              const glm::vec2& at, float reach) {
    MirrorTopView v;
    v.p1 = p1;
    v.p2 = p2;
    v.eye = eye;
    v.at = at;
    if (!finite(p1) || !finite(p2) || !finite(eye) || !finite(at) || !std::isfinite(reach)) {
        v.reason = "a point or the reach is not finite";
        return v;
    }
    glm::vec2 along = p2 - p1;
    float width = glm::length(along);
    if (!(width > 1e-6f)) {
        v.reason = "p1 and p2 are the same point: the mirror has no width";
        return v;
    }
    // The mirror faces the eye: of the two normals of the segment, the one on the eye's side.
    glm::vec2 normal = glm::vec2(-along.y, along.x) / width;
    glm::vec2 middle = 0.5f * (p1 + p2);
    if (glm::dot(eye - middle, normal) < 0.0f) normal = -normal;

    Mirror m;  // upright, as tall as it is wide (the top view does not see the height)
    m.center = glm::vec3(middle.x, 0.0f, middle.y);
    m.normal = glm::vec3(normal.x, 0.0f, normal.y);
    m.up = glm::vec3(0.0f, 1.0f, 0.0f);
    m.width = m.height = width;
    if (!(reach > 0.0f))
        reach = std::max({glm::length(eye - middle), glm::length(at - middle), width});
    glm::vec3 eye3(eye.x, 0.0f, eye.y), at3(at.x, 0.0f, at.y);
    MirrorTopView view = mirrorTopView(m, eye3, at3, mirrorCamera(m, eye3, reach));
    // Keep the ends as given: mirrorTopView orders them left to right seen from the front.
    view.p1 = p1;
    view.p2 = p2;
    if (view.valid) {
        float stretch = view.zFar / view.zNear;
        view.far1 = view.eyePrime + stretch * (p1 - view.eyePrime);
        view.far2 = view.eyePrime + stretch * (p2 - view.eyePrime);
    }
    return view;
}

}  // namespace sl
