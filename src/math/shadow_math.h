// Shadow-map math without GL: the texture-coordinate (bias) matrix, the flipped-depth variant
// the slides assume, and fitting the light's frustum to the shadow casters.
//
// Conventions (OpenGL, as glm::perspective / glm::frustum build them): light view space looks
// down -Z, "depth" of a point is -z_view (> 0 in front of the light), and the standard projection
// maps the near plane to NDC z = -1 and the far plane to NDC z = +1.
#pragma once

#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace sl {

// The matrix that takes light NDC to shadow-map texture space:
//   | 0.5  0    0       0.5 |
//   | 0    0.5  0       0.5 |
//   | 0    0    zScale  0.5 |
//   | 0    0    0       1   |
// Use zScale = +0.5 with the standard projection (near -> NDC -1 -> depth 0). The slides' -0.5
// is only right together with depthFlippedProjection() and glDepthRange(1, 0).
glm::mat4 biasMatrix(float zScale);

// diag(1, 1, -1, 1) * p: the same frustum, but near maps to NDC z = +1 and far to -1. Paired with
// glDepthRange(1, 0) the window depth is again 0 at near and 1 at far, and the matching texture
// matrix is biasMatrix(-0.5).
glm::mat4 depthFlippedProjection(const glm::mat4& p);

struct Aabb {
    glm::vec3 lo, hi;
};

struct BoundingSphere {
    glm::vec3 center;
    float radius;
};

// A simple (not minimal) bounding sphere: centred on the union box of `boxes`, with the radius
// reaching its farthest corner (half the diagonal). Empty input gives centre 0 and radius 0.
BoundingSphere boundingSphere(const std::vector<Aabb>& boxes);

// How to choose the light's frustum:
//   Tight:  fit near, far and fovy to the box corners as seen from the light (best depth use).
//   Sphere: the SuperBible's fit to the bounding sphere of the casters (rotation invariant).
//   Fixed:  the lab's glm::frustum(-1, 1, -1, 1, 1, 100).
enum class LightFit { Tight, Sphere, Fixed };

struct LightFrustum {
    glm::mat4 view, projection;  // lookAt + perspective/frustum
    float zNear = 0.0f, zFar = 0.0f, fovyDegrees = 0.0f;
    LightFit used = LightFit::Fixed;  // what was actually used after any fallback
    std::string note;                 // one line: what was fitted and why
};

// Fit the light's view and projection to `boxes` (the shadow casters and receivers).
//  - Tight looks at `target`; near = 0.95 * nearest corner depth (never below 1e-3 * farthest),
//    far = 1.01 * farthest, square fovy covering every corner with a 2% margin, capped at 170.
//    Corners behind or at the light cannot be covered by a perspective frustum: the near plane is
//    clamped and the note says so.
//  - Sphere looks at the sphere centre: near = d - r (>= 0.01 r), far = d + r, and the fovy of
//    the cone tangent to the sphere, 2 asin(r / d). (The SuperBible's 2 atan(r / d) only covers
//    the sphere's central cross-section: the half of the sphere nearer the light pokes out of the
//    sides.) When the light is inside or too close to the sphere (d < 1.05 r) the fit falls back
//    to Tight, since d - r would put the near plane at or behind the light.
//  - Fixed looks at `target` with glm::frustum(-1, 1, -1, 1, 1, 100) (fovy 90).
// With no boxes, or nothing in front of the light, Tight and Sphere fall back to Fixed.
LightFrustum fitLightFrustum(const glm::vec3& light, const glm::vec3& target,
                             const std::vector<Aabb>& boxes, LightFit fit);

// The same frustum with its near plane moved to far / ratio (the field of view kept): the knob
// of the near-far precision sweep. A ratio of 0 (or anything not above 1) returns `f` unchanged.
LightFrustum withFarOverNear(LightFrustum f, float ratio);

// far / near: how much of the depth buffer's precision the fit wastes (bigger is worse).
float farOverNear(const LightFrustum& f);

// The name of a fit, for notes and the HUD ("tight", "sphere", "fixed").
const char* lightFitName(LightFit fit);

}  // namespace sl
