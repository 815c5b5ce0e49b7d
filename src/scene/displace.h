// A scene moved by an amount drawn at grading time (GUIDE section 4): its casters turned about
// the receiver's normal and shifted, its light turned about its target, its camera moved to
// another side, height and distance. A shader that hard-codes the lecture's boxes and sphere (no
// shadow map at all) draws its shadows in the wrong places in such a view, and one that
// recognises the graded cameras by eyePosition does not recognise this one, however well either
// matches the fixed views; a correct method cannot tell it from any other scene.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace sl {

struct Displacement {
    float casterTurnDegrees = 0;  // about the receiver's normal through the casters' centre
    glm::vec2 casterShift{0};     // in the receiver's plane, as a share of the casters' extent
    float lightTurnDegrees = 0;   // about the receiver's normal through the light's target
    // The camera, about the receiver's normal through its (moved) target: set to a side away from
    // the light's, raised or lowered, nearer or farther.
    float cameraTurnDegrees = 0;       // from the light's side, about the normal
    float cameraElevationDegrees = 0;  // added to its angle above the receiver's plane
    float cameraDistanceScale = 1;     // times its distance to its target
};

// The displacement of one seed: the same on every platform (mt19937_64's output is fixed by the
// standard; the distributions are ours). The casters turn by 40..320 degrees (never close to
// where they were), shift by up to 15 % of their extent per axis; the light turns 10..20 degrees
// either way (its elevation kept, so the lessons' grazing and acne stay what they teach; at 35
// degrees a shadow could stretch across the floor at a grazing angle our own shaders fail). The
// camera looks from 50..310 degrees away from the light's side (never from behind the light,
// where the casters hide their own shadows), its elevation changes by -10..+10 degrees (kept
// within 15..75 degrees above the receiver) and its distance by a factor 0.85..1.15: it still
// looks at the casters from above the receiver with the shadows in frame, from a place no fixed
// view has.
// The camera's draws come after the others', so a seed moves casters and light as it did before
// the camera moved.
Displacement displacementFor(std::uint64_t seed);

// The axis a scene's casters turn about: the normal of its first object that casts no shadow (the
// floor a quad's normal, a box's thinnest side), else +Y.
glm::vec3 receiverNormal(const Scene& scene);

// `scene` with its casters (objects that cast a shadow), light and camera moved by `d`; receivers
// and the mirror stay. Boxes stay axis-aligned: their centres move. Casters that would overlap
// after the turn turn on in 23-degree steps until apart. The camera's target moves with the
// casters (it looks at them as before); its eye moves about that target as `d` says.
Scene displacedScene(const Scene& scene, const Displacement& d);

}  // namespace sl
