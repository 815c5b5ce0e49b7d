#include "math/mirror_math.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "math/camera.h"

namespace sl {

namespace {

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The mirror with a unit normal, a unit up perpendicular to it and right = cross(up, normal).
struct MirrorFrame {
    bool valid = false;
    std::string reason;
    glm::vec3 normal{0.0f}, up{0.0f}, right{0.0f};
    glm::vec3 corner[4];  // bottom-left, bottom-right, top-right, top-left seen from the front
};

MirrorFrame mirrorFrame(const Mirror& m) {
    MirrorFrame f;
    if (!finite(m.center) || !finite(m.normal) || !finite(m.up) || !std::isfinite(m.width) ||
        !std::isfinite(m.height)) {
        f.reason = "the mirror has a non-finite centre, normal, up or size";
        return f;
    }
    if (!(m.width > 0.0f) || !(m.height > 0.0f)) {
        f.reason = "the mirror has zero width or height";
        return f;
    }
    float nLength = glm::length(m.normal);
    if (!(nLength > 1e-12f)) {
        f.reason = "the mirror's normal is zero";
        return f;
    }
    f.normal = m.normal / nLength;
    // Gram-Schmidt: keep only the part of up that lies in the mirror's plane.
    glm::vec3 up = m.up - glm::dot(m.up, f.normal) * f.normal;
    float upLength = glm::length(up);
    if (!(upLength > 1e-6f * glm::length(m.up))) {
        f.reason = "the mirror's up is zero or parallel to its normal";
        return f;
    }
    f.up = up / upLength;
    f.right = glm::cross(f.up, f.normal);
    glm::vec3 r = f.right * (0.5f * m.width), u = f.up * (0.5f * m.height);
    f.corner[0] = m.center - r - u;
    f.corner[1] = m.center + r - u;
    f.corner[2] = m.center + r + u;
    f.corner[3] = m.center - r + u;
    f.valid = true;
    return f;
}

// Signed distance of `eye` in front of the mirror, and whether that is clearly in front: a
// relative tolerance so "on the plane" means the same at every scale.
bool eyeInFront(const Mirror& m, const MirrorFrame& f, const glm::vec3& eye, float& distance,
                std::string& reason) {
    if (!finite(eye)) {
        reason = "the eye is not finite";
        return false;
    }
    distance = glm::dot(eye - m.center, f.normal);
    float tolerance = 1e-5f * std::max({1.0f, glm::length(eye - m.center), m.width, m.height});
    if (distance < -tolerance) {
        reason = "the eye is behind the mirror";
        return false;
    }
    if (distance <= tolerance) {
        reason = "the eye is on the mirror's plane";
        return false;
    }
    return true;
}

float sgn(float x) {
    return x > 0.0f ? 1.0f : (x < 0.0f ? -1.0f : 0.0f);
}

}  // namespace

glm::vec3 reflectPoint(const glm::vec3& point, const glm::vec3& planePoint,
                       const glm::vec3& planeNormal) {
    glm::vec3 n = glm::normalize(planeNormal);
    return point - 2.0f * glm::dot(point - planePoint, n) * n;
}

glm::mat4 reflectionMatrix(const glm::vec3& planePoint, const glm::vec3& planeNormal) {
    glm::vec3 n = glm::normalize(planeNormal);
    float d = glm::dot(planePoint, n);
    // x' = x - 2 (x.n - d) n = (I - 2 n n^T) x + 2 d n. GLM is column-major: m[column][row].
    glm::mat4 m(1.0f);
    for (int col = 0; col < 3; ++col)
        for (int row = 0; row < 3; ++row) m[col][row] -= 2.0f * n[row] * n[col];
    m[3] = glm::vec4(2.0f * d * n, 1.0f);
    return m;
}

glm::vec3 reflectedEyeSlides(const glm::vec3& eye, const glm::vec3& p, const glm::vec3& n) {
    glm::vec3 unitN = glm::normalize(n);
    float distance = glm::length(eye - p);
    if (!(distance > 0.0f)) return p;    // the eye on the mirror point is its own image
    glm::vec3 l = (eye - p) / distance;  // towards the eye
    glm::vec3 r = 2.0f * glm::dot(l, unitN) * unitN - l;  // l mirrored about the normal
    return p + distance * (-r / glm::length(r));
}

MirrorCamera mirrorCamera(const Mirror& mirror, const glm::vec3& eye, float sceneRadiusFromMirror) {
    MirrorCamera c;
    MirrorFrame f = mirrorFrame(mirror);
    if (!f.valid) {
        c.reason = f.reason;
        return c;
    }
    float distance = 0.0f;
    if (!eyeInFront(mirror, f, eye, distance, c.reason)) return c;
    if (!std::isfinite(sceneRadiusFromMirror) || !(sceneRadiusFromMirror > 0.0f)) {
        c.reason = "the scene radius (sceneRadiusFromMirror) must be positive";
        return c;
    }

    c.eye = reflectPoint(eye, mirror.center, f.normal);
    // Look along the normal, perpendicular to the mirror: then the mirror's plane is parallel to
    // the near plane and the frustum through the mirror's rectangle is a plain off-axis frustum.
    c.at = c.eye + f.normal;
    c.up = f.up;
    c.view = glm::lookAt(c.eye, c.at, c.up);

    // Every corner is at depth `distance` in this camera; its x and y bound the near window.
    c.left = c.bottom = INFINITY;
    c.right = c.top = -INFINITY;
    for (const glm::vec3& corner : f.corner) {
        glm::vec3 v = glm::vec3(c.view * glm::vec4(corner, 1.0f));
        c.left = std::min(c.left, v.x);
        c.right = std::max(c.right, v.x);
        c.bottom = std::min(c.bottom, v.y);
        c.top = std::max(c.top, v.y);
    }
    c.zNear = distance;
    c.zFar = distance + sceneRadiusFromMirror;
    c.projection = glm::frustum(c.left, c.right, c.bottom, c.top, c.zNear, c.zFar);

    for (int i = 0; i < 4; ++i) {
        glm::vec4 clip = c.projection * c.view * glm::vec4(f.corner[i], 1.0f);
        c.cornerUv[i] = 0.5f * (glm::vec2(clip) / clip.w + 1.0f);
    }
    c.valid = true;
    return c;
}

glm::mat4 obliqueNearPlane(const glm::mat4& projection, const glm::vec4& viewSpacePlane) {
    glm::vec4 plane = viewSpacePlane;
    if (!finite(glm::vec3(plane)) || !std::isfinite(plane.w)) return projection;
    if (plane.w > 0.0f) plane = -plane;  // the camera (the origin) must be on the negative side
    float normalLength = glm::length(glm::vec3(plane));
    if (!(-plane.w > 1e-6f * normalLength)) return projection;  // through the camera

    // Row 4 of the projection gives clip w. In clip space the near plane is z + w >= 0, so making
    // row 3 = a * plane - row4 turns it into a * (plane . v) >= 0: the new near plane.
    glm::vec4 row4(projection[0][3], projection[1][3], projection[2][3], projection[3][3]);
    // The far plane becomes (2 row4 - a plane) . v >= 0. Choose a so it passes through the far
    // corner of the frustum on the plane's side, q = P^-1 (sgn a, sgn b, 1, 1): nothing of the
    // original frustum in front of the plane is lost, and depth precision is spoilt the least.
    glm::vec4 q = glm::inverse(projection) * glm::vec4(sgn(plane.x), sgn(plane.y), 1.0f, 1.0f);
    float planeDotQ = glm::dot(plane, q);
    if (!(planeDotQ * q.w > 0.0f)) return projection;  // the far corner is not on the kept side
    float a = 2.0f * glm::dot(row4, q) / planeDotQ;
    glm::mat4 oblique = projection;
    for (int col = 0; col < 4; ++col) oblique[col][2] = a * plane[col] - row4[col];
    return oblique;
}

glm::ivec2 mirrorFootprintPixels(const Mirror& mirror, const Camera& camera, int width,
                                 int height) {
    if (width <= 0 || height <= 0) return {0, 0};
    MirrorFrame f = mirrorFrame(mirror);
    if (!f.valid) return {0, 0};
    float distance = 0.0f;
    std::string reason;
    if (!eyeInFront(mirror, f, camera.eye, distance, reason)) return {0, 0};
    if (!finite(camera.at)) return {0, 0};

    glm::mat4 viewProjection =
        projectionMatrix(camera, float(width) / float(height)) * viewMatrix(camera);
    std::vector<glm::vec4> polygon;
    for (const glm::vec3& corner : f.corner)
        polygon.push_back(viewProjection * glm::vec4(corner, 1.0f));

    // Clip the quad against the six frustum planes in clip space (w +- x, w +- y, w +- z >= 0)
    // so corners behind the camera cannot produce a bogus box (Sutherland-Hodgman).
    for (int axis = 0; axis < 3; ++axis)
        for (float side : {1.0f, -1.0f}) {
            std::vector<glm::vec4> kept;
            for (std::size_t i = 0; i < polygon.size(); ++i) {
                const glm::vec4& a = polygon[i];
                const glm::vec4& b = polygon[(i + 1) % polygon.size()];
                float da = a.w + side * a[axis], db = b.w + side * b[axis];
                if (da >= 0.0f) kept.push_back(a);
                if ((da >= 0.0f) != (db >= 0.0f)) kept.push_back(a + (da / (da - db)) * (b - a));
            }
            polygon = std::move(kept);
            if (polygon.empty()) return {0, 0};
        }

    glm::vec2 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec4& clip : polygon) {
        if (!(clip.w > 0.0f)) continue;
        glm::vec2 ndc = glm::vec2(clip) / clip.w;
        glm::vec2 pixel((ndc.x + 1.0f) * 0.5f * width, (1.0f - ndc.y) * 0.5f * height);
        lo = glm::min(lo, pixel);
        hi = glm::max(hi, pixel);
    }
    if (!(lo.x <= hi.x) || !(lo.y <= hi.y)) return {0, 0};
    int x0 = std::clamp(int(std::floor(lo.x)), 0, width),
        x1 = std::clamp(int(std::ceil(hi.x)), 0, width);
    int y0 = std::clamp(int(std::floor(lo.y)), 0, height),
        y1 = std::clamp(int(std::ceil(hi.y)), 0, height);
    return {x1 - x0, y1 - y0};
}

}  // namespace sl
