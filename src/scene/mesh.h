// Triangle meshes for the GL path. Each object is a unit primitive in object space placed by a
// model matrix, so the shaders see the lecture's `model` and the shadow matrix can carry it.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace sl {

struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
};

struct MeshPart {
    std::uint32_t firstIndex = 0;
    std::uint32_t indexCount = 0;
};

struct SceneMesh {
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    std::vector<MeshPart> objects;    // one per scene object, same order
    MeshPart unitQuad;                // [-0.5,0.5]^2 in z=0 facing +z: mirrors, full-screen quads
    std::vector<int> sphereSegments;  // per object, 0 for non-spheres (what tessellation chose)
};

// Object space -> world space for an object (unit cube, unit sphere or unit quad).
glm::mat4 modelMatrix(const Object& o);
// The mirror's unit quad placed in the world; corners as in mirrorCorners().
glm::mat4 mirrorModelMatrix(const Mirror& m);

// Segments around a sphere so that its silhouette, seen by `camera` in an image `imageHeight`
// pixels tall, stays within half a pixel of the true circle: a polygon of n sides inscribed in
// a circle of R pixels is off by R (1 - cos(pi / n)) at most.
int sphereSegmentsForHalfPixel(const Object& sphere, const Camera& camera, int imageHeight);

// Sphere vertices a scene may ask for in all (about 50 MB of vertices and indices).
constexpr std::size_t kSphereVertexBudget = 2'000'000;

// Tessellates every object; spheres as fine as sphereSegmentsForHalfPixel asks, coarser for all
// when that would exceed kSphereVertexBudget.
SceneMesh tessellate(const Scene& scene, const Camera& camera, int imageHeight);

}  // namespace sl
