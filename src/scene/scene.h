// The scene as data: exact primitives, camera, light and an optional planar mirror.
// The GL path tessellates these; the CPU reference ray-traces them exactly.
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

namespace sl {

enum class PrimitiveKind { Box, Sphere, Quad };

// One exact primitive. Which fields matter depends on `kind`:
//   Box:    center, size (full extents along world x, y, z; axis-aligned)
//   Sphere: center, radius
//   Quad:   center, normal, up, width (along cross(up, normal)), height (along up); one-sided
//           for lighting but opaque from both sides for shadows and visibility.
struct Object {
    std::string name;
    PrimitiveKind kind = PrimitiveKind::Box;
    glm::vec3 center{0.0f};
    glm::vec3 size{1.0f};
    float radius = 0.5f;
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    glm::vec3 up{0.0f, 0.0f, -1.0f};
    float width = 1.0f;
    float height = 1.0f;
    glm::vec3 color{0.8f};
    bool castsShadow = true;
};

// A planar mirror: a rectangle with the reflecting side facing `normal`.
struct Mirror {
    glm::vec3 center{0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float width = 1.0f;   // along right = cross(up, normal)
    float height = 1.0f;  // along up
};

// A real mirror returns a little less than all light: the GL stage and the CPU reference both
// scale what the mirror shows by this.
constexpr float kMirrorReflectance = 0.9f;

struct Camera {
    glm::vec3 eye{0.0f, 2.0f, 4.0f};
    glm::vec3 at{0.0f};
    float fovyDegrees = 45.0f;
    float zNear = 0.1f;
    float zFar = 20.0f;
};

// A point light. `target` is where the light's shadow camera looks.
struct Light {
    glm::vec3 position{2.0f, 1.0f, 0.0f};
    glm::vec3 target{0.0f};
};

// Phong coefficients shared by every object (the lecture uses one material).
struct Material {
    float ambient = 0.2f;
    float diffuse = 0.8f;
    float specular = 0.5f;
    float shininess = 32.0f;
};

struct Scene {
    std::string name;
    glm::vec3 background{0.1f, 0.1f, 0.15f};
    Camera camera;
    Light light;
    Material material;
    std::vector<Object> objects;
    std::optional<Mirror> mirror;
};

// Object ids used by the reference and the GL id pass: 0 = background, 1..N = objects[i-1],
// N+1 = the mirror.
inline int objectId(std::size_t objectIndex) {
    return static_cast<int>(objectIndex) + 1;
}
inline int mirrorId(const Scene& s) {
    return static_cast<int>(s.objects.size()) + 1;
}

// Corners of a mirror: bottom-left, bottom-right, top-right, top-left as seen from its front.
struct MirrorCorners {
    glm::vec3 corner[4];
};
MirrorCorners mirrorCorners(const Mirror& m);
glm::vec3 mirrorRight(const Mirror& m);  // cross(up, normal), unit

// Whether p is strictly inside a box or sphere (quads have no inside).
bool pointInside(const Object& o, const glm::vec3& p);

}  // namespace sl
