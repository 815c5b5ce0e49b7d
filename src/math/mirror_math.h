// Planar-mirror math without GL: reflecting points and matrices, the reflected camera with its
// off-axis frustum through the mirror, Lengyel's oblique near plane and the mirror's size on
// screen.
//
// The mirror's normal and up need not be unit length or exactly perpendicular: everything here
// normalises the normal and makes up perpendicular to it (Gram-Schmidt), then uses
// right = cross(up, normal) as scene.h does.
#pragma once

#include <glm/glm.hpp>
#include <string>

#include "scene/scene.h"

namespace sl {

// The mirror image of `point` in the plane through `planePoint` with normal `planeNormal`
// (any length): point - 2 ((point - planePoint) . n) n.
glm::vec3 reflectPoint(const glm::vec3& point, const glm::vec3& planePoint,
                       const glm::vec3& planeNormal);

// The same reflection as a 4x4 matrix (for drawing the reflected scene directly). It is its own
// inverse (M * M = I) and has determinant -1, so it flips triangle winding: swap glFrontFace.
glm::mat4 reflectionMatrix(const glm::vec3& planePoint, const glm::vec3& planeNormal);

// The slides' construction, step by step, for a point p on the mirror with normal n:
//   l = (eye - p) / |eye - p|,  r = 2 (l.n) n - l,  eye' = p + |eye - p| * (-r / |r|).
// r is the direction the ray eye -> p leaves the mirror in; going back along it from p by the
// same distance lands on eye', whatever point p of the mirror is used. n is normalised here.
// Equal to reflectPoint(eye, p, n); eye == p returns p.
glm::vec3 reflectedEyeSlides(const glm::vec3& eye, const glm::vec3& p, const glm::vec3& n);

// The camera that renders the mirror's image: it sits at eye' behind the mirror and looks
// through it along the normal (at' = eye' + n), its up along the mirror's vertical edge. Its
// frustum is off-axis: its near plane is the mirror's plane and the mirror's rectangle is exactly
// the near window, so nothing behind the mirror is drawn and the image maps onto the mirror.
// Seen from behind, the mirror's right is the camera's left: the image is flipped left-right,
// which cornerUv accounts for.
struct MirrorCamera {
    bool valid = false;
    std::string reason;                                          // why not valid (empty when valid)
    glm::vec3 eye{0.0f}, at{0.0f}, up{0.0f, 1.0f, 0.0f};         // eye', at' = eye' + n, mirror up
    float left = 0.0f, right = 0.0f, bottom = 0.0f, top = 0.0f;  // off-axis window at near
    float zNear = 0.0f, zFar = 0.0f;  // near = distance eye' -> mirror plane; far = near + radius
    glm::mat4 view{1.0f}, projection{1.0f};  // lookAt(eye', at', up), glm::frustum(...)
    // Texture coordinate of each mirror corner (mirrorCorners order: bottom-left, bottom-right,
    // top-right, top-left as seen from the front) in the image this camera renders.
    glm::vec2 cornerUv[4] = {glm::vec2(0.0f), glm::vec2(0.0f), glm::vec2(0.0f), glm::vec2(0.0f)};
};

// The reflected camera for a viewer at `eye`. `sceneRadiusFromMirror` is how far in front of the
// mirror the scene reaches: far' = near' + sceneRadiusFromMirror. Invalid (with a reason, and
// only finite zeros/identity in the other fields) when the eye is behind or on the mirror plane,
// the mirror has no area, its up is parallel to its normal, the radius is not positive, or some
// input is not finite.
MirrorCamera mirrorCamera(const Mirror& mirror, const glm::vec3& eye, float sceneRadiusFromMirror);

// Lengyel's oblique near plane: `projection` (any OpenGL perspective, also off-axis) with its
// near plane replaced by the view-space plane (a, b, c, d): a x + b y + c z + d = 0. Points with
// a x + b y + c z + d >= 0 are kept; the camera must be on the other side (d < 0), so the normal
// (a, b, c) points away from the camera into the visible scene. A plane given the other way round
// is flipped. The far plane is tilted to pass through the original far corner, so the original
// frustum on the kept side stays inside. Returns `projection` unchanged when the plane passes
// through the camera, lies beyond the frustum, or is not finite.
glm::mat4 obliqueNearPlane(const glm::mat4& projection, const glm::vec4& viewSpacePlane);

// The size in pixels of the screen-space bounding box of the mirror seen by `camera` in a
// width x height image (the part inside the view frustum, clamped to the image). {0, 0} when the
// mirror is not visible: outside the frustum, behind the camera, seen from its back (it reflects
// nothing then), or degenerate.
glm::ivec2 mirrorFootprintPixels(const Mirror& mirror, const Camera& camera, int width, int height);

}  // namespace sl
