// The mirror construction seen from above (the x-z plane), as the lecture's practice draws it:
// the mirror as a segment p1-p2, the viewer's eye and at, the reflected eye' and at', and the
// reflected camera's off-axis frustum. Plain geometry for the figure `render --figure` draws.
#pragma once

#include <glm/glm.hpp>
#include <string>

#include "math/mirror_math.h"

namespace sl {

// Every point is (x, z). "Depth" below means distance along the mirror's normal from eye'.
struct MirrorTopView {
    bool valid = false;
    std::string reason;               // why not valid (empty when valid)
    glm::vec2 p1{0.0f}, p2{0.0f};     // the mirror's ends
    glm::vec2 normal{0.0f};           // unit, the reflecting side (towards the eye)
    glm::vec2 eye{0.0f}, at{0.0f};    // the viewer
    glm::vec2 eyePrime{0.0f};         // eye reflected through the mirror's line
    glm::vec2 atPrime{0.0f};          // eye' + normal: at' - eye' is perpendicular to p1 - p2
    float left = 0.0f, right = 0.0f;  // the reflected camera's window at near' (its own x)
    float zNear = 0.0f, zFar = 0.0f;  // near' = depth of the mirror, far' = near' + reach
    // The frustum's side lines: from eye' through p1 (and p2) on to the far plane. The far
    // plane's ends are where those lines reach depth far'.
    glm::vec2 far1{0.0f}, far2{0.0f};
};

// The top view of a scene's mirror for a viewer at eye looking at `at`, with the reflected
// camera `camera` already computed (mirrorCamera). p1 and p2 are the ends of the mirror's
// horizontal centre line (p1 on the mirror's left seen from the front); y is dropped, so the
// picture is exact for an upright mirror (normal in the x-z plane). Invalid with the camera's
// reason when the camera is invalid.
MirrorTopView mirrorTopView(const Mirror& mirror, const glm::vec3& eye, const glm::vec3& at,
                            const MirrorCamera& camera);

// The lecture's practice set-up, given straight in the x-z plane: an upright mirror from p1 to
// p2, facing the side the eye is on. `reach` is how far the reflected camera sees beyond the
// mirror (far' = near' + reach); 0 picks the farther of eye and at from the mirror's middle.
// Invalid (with a reason) when p1 == p2, the eye is on the mirror's line, or a value is not
// finite.
MirrorTopView practiceTopView(const glm::vec2& p1, const glm::vec2& p2, const glm::vec2& eye,
                              const glm::vec2& at, float reach = 0.0f);

}  // namespace sl
