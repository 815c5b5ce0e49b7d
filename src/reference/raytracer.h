// The CPU reference: one exact ray per pixel centre, against the scene's exact primitives (no
// tessellation, no shadow map). The GL renders are judged against what this produces.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "io/image.h"
#include "math/camera.h"
#include "scene/scene.h"

namespace sl {

// Everything the metrics need to know about one pixel, as exact geometric facts.
struct ReferencePixel {
    // 0 = background, objectId(i) for scene.objects[i], mirrorId(scene) for the mirror.
    int objectId = 0;
    // Hit point and unit outward normal. For a Quad the normal is its declared `normal` even when
    // seen from behind (lighting treats quads as one-sided). For the back of the mirror it is
    // -mirror.normal.
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f};
    bool facesLight = false;  // dot(normal, light - position) > 0
    bool blocked = false;     // the segment position -> light hits a shadow-casting object
    // The true shadow boundary runs along this pixel's silhouette: a 4-neighbour shows something
    // else (background, another object, a face turned away), and the same surface continued
    // under that neighbour's ray (its tangent plane) has the other shadow state. Such a boundary
    // is a shadow edge though no evaluated pixel lies on its other side.
    bool shadowEdgeAtSilhouette = false;

    // Mirror pixels seen from the front only; otherwise bounceObjectId stays -1.
    int bounceObjectId = -1;  // object seen in the mirror (0 = background)
    bool bounceBlocked = false;
    bool bounceFacesLight = false;
    glm::vec3 bouncePosition{0.0f};  // hit point of the reflected ray (needed to shade it)
    glm::vec3 bounceNormal{0.0f};
};

struct ReferenceImage {
    int width = 0;
    int height = 0;
    // The id mirror pixels carry (mirrorId(scene)), so the metrics can tell them apart without
    // the scene; -1 when unknown (then no pixel counts as the mirror).
    int mirrorObjectId = -1;
    std::vector<ReferencePixel> pixels;  // row-major, row 0 at the top, like Image

    const ReferencePixel& at(int i, int j) const { return pixels[std::size_t(j) * width + i]; }
};

// How far a ray must travel before a hit counts, and how far a shadow ray starts off the
// surface along its normal. Both avoid a surface finding itself through rounding.
constexpr float kRayEpsilon = 1e-4f;
constexpr float kShadowOffset = 1e-4f;

// What a ray hit: the index into scene.objects (-1 for nothing), or the mirror.
struct RayHit {
    float t = 0.0f;
    int objectIndex = -1;
    bool mirror = false;
    bool mirrorFront = false;
    glm::vec3 normal{0.0f};
};

// The shadow test for a surface point: a ray starts at position + normal * kShadowOffset and
// heads for the light; the point is blocked when an object with castsShadow is hit with t in
// (kRayEpsilon, distance to the light). The offset keeps the ray from finding its own surface;
// the mirror never blocks light (a choice of the lab: the mirror is not a shadow caster).
bool shadowRayBlocked(const Scene& scene, const glm::vec3& position, const glm::vec3& normal,
                      const glm::vec3& lightPosition);

// Traces one ray per pixel centre (pixelRay, the same conventions as the GL path), then marks
// the silhouette pixels a shadow boundary runs along (shadowEdgeAtSilhouette). Rows are split
// across `threads` std::threads (0 = hardware concurrency); the result does not depend on the
// thread count.
ReferenceImage traceReference(const Scene& scene, const Camera& camera,
                              const glm::vec3& lightPosition, int width, int height,
                              int threads = 0);

// A Phong picture of the reference: ambient + diffuse + specular with scene.material and white
// light; diffuse and specular are dropped where the point is blocked or faces away. Mirror
// pixels show the shaded bounce times 0.9. Alpha is 255. `occlusion` shades each pixel's own
// point as traced, or as if the light reached every point or none (the metrics' two shadings:
// no copy of the reference with its flags rewritten, which cost two 20 MB copies a row).
enum class Occlusion { AsTraced, NoneBlocked, AllBlocked };
Image shadeReference(const Scene& scene, const Camera& camera, const ReferenceImage& reference,
                     const glm::vec3& lightPosition, Occlusion occlusion = Occlusion::AsTraced);

}  // namespace sl
