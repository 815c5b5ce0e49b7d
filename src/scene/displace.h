// A scene moved by an amount drawn at grading time (GUIDE section 4): its casters turned about
// the receiver's normal and shifted, its light turned about its target. A shader that hard-codes
// the lecture's boxes and sphere (no shadow map at all) draws its shadows in the wrong places in
// such a view, however well it matches the fixed ones; a correct method cannot tell it from any
// other scene.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace sl {

struct Displacement {
    float casterTurnDegrees = 0;  // about the receiver's normal through the casters' centre
    glm::vec2 casterShift{0};     // in the receiver's plane, as a share of the casters' extent
    float lightTurnDegrees = 0;   // about the receiver's normal through the light's target
};

// The displacement of one seed: the same on every platform (mt19937_64's output is fixed by the
// standard; the distributions are ours). The casters turn by 40..320 degrees (never close to
// where they were), shift by up to 15 % of their extent per axis; the light turns 10..20 degrees
// either way (its elevation kept, so the lessons' grazing and acne stay what they teach; at 35
// degrees a shadow could stretch across the floor at a grazing angle our own shaders fail).
Displacement displacementFor(std::uint64_t seed);

// The axis a scene's casters turn about: the normal of its first object that casts no shadow (the
// floor a quad's normal, a box's thinnest side), else +Y.
glm::vec3 receiverNormal(const Scene& scene);

// `scene` with its casters (objects that cast a shadow) and light moved by `d`; receivers, the
// mirror and the camera stay. Boxes stay axis-aligned: their centres move. Casters that would
// overlap after the turn turn on in 23-degree steps until apart.
Scene displacedScene(const Scene& scene, const Displacement& d);

}  // namespace sl
