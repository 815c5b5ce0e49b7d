// The displaced view of a scene with a mirror (GUIDE section 4, issue 37). The mirror stage was
// graded from its scene's own camera alone, so a mapping fitted to that one picture (the mirror
// texture looked up from the pixel's screen position through the lecture view's numbers, or from
// the world position through the lecture mirror's) passed. A seed moves the camera to another
// side, height and distance, still in front of the mirror, and slides the mirror, with whatever
// stands behind it (its frame, the box it hides), along its plane and towards the scene. The
// casters and the light stay: what the stage teaches is the reflection, and the shadow stages'
// displacement (displace.h) assumes a floor that casts nothing, which the mirror scene's does.
#pragma once

#include <cstdint>

#include "scene/scene.h"

namespace sl {

struct MirrorDisplacement {
    // The camera, about the mirror's up axis through the camera's target.
    float cameraTurnDegrees = 0;       // 15..35 degrees either way from where it was
    float cameraElevationDegrees = 0;  // added to its angle above the mirror's base, -10..+10,
                                       // kept within 15..60 degrees
    float cameraDistanceScale = 1;     // times its distance to its target, 0.85..1.15
    // The mirror, with what stands behind it.
    float mirrorSlide = 0;  // along the mirror's right, a share of its width: 0.05..0.10 either way
    float mirrorAdvance = 0;  // along its normal, a share of its height: 0..0.20 (less where an
                              // object in front would come within 0.1 of it)
};

// The mirror displacement of one seed, the same on every platform (mt19937_64 and our own
// distributions, as displacementFor).
MirrorDisplacement mirrorDisplacementFor(std::uint64_t seed);

// `scene` with its camera and mirror moved by `d` (a scene without a mirror is returned as it
// is). Objects wholly behind the mirror's plane move with it; every other object and the light
// stay.
Scene displacedMirrorScene(const Scene& scene, const MirrorDisplacement& d);

// Grading's displaced view of `seed`: the mirror's for a scene with a mirror, else the casters',
// light's and camera's (displacedScene).
Scene displacedViewOf(const Scene& scene, std::uint64_t seed);

}  // namespace sl
