#include "scene/mesh.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace sl {

glm::mat4 modelMatrix(const Object& o) {
    switch (o.kind) {
        case PrimitiveKind::Box:
            return glm::scale(glm::translate(glm::mat4(1), o.center), o.size);
        case PrimitiveKind::Sphere:
            return glm::scale(glm::translate(glm::mat4(1), o.center), glm::vec3(o.radius));
        case PrimitiveKind::Quad: {
            glm::vec3 right = glm::normalize(glm::cross(o.up, o.normal));
            return glm::mat4(glm::vec4(right * o.width, 0), glm::vec4(o.up * o.height, 0),
                             glm::vec4(o.normal, 0), glm::vec4(o.center, 1));
        }
    }
    return glm::mat4(1);
}

glm::mat4 mirrorModelMatrix(const Mirror& m) {
    Object q;
    q.kind = PrimitiveKind::Quad;
    q.center = m.center;
    q.normal = glm::normalize(m.normal);
    q.up = glm::normalize(m.up);
    q.width = m.width;
    q.height = m.height;
    return modelMatrix(q);
}

int sphereSegmentsForHalfPixel(const Object& sphere, const Camera& camera, int imageHeight) {
    float distance = std::max(glm::length(sphere.center - camera.eye) - sphere.radius, 1e-3f);
    float pixelsPerUnit = 0.5f * imageHeight / std::tan(glm::radians(camera.fovyDegrees) * 0.5f);
    float radiusPixels = sphere.radius / distance * pixelsPerUnit;
    int n = 12;
    if (radiusPixels > 0.5f)
        n = static_cast<int>(std::ceil(glm::pi<float>() / std::acos(1.0f - 0.5f / radiusPixels)));
    return std::clamp(n, 12, 512);
}

namespace {

void addQuadFace(SceneMesh& m, glm::vec3 c, glm::vec3 u, glm::vec3 v, glm::vec3 n) {
    auto base = static_cast<std::uint32_t>(m.vertices.size());
    m.vertices.push_back({c - u - v, n});
    m.vertices.push_back({c + u - v, n});
    m.vertices.push_back({c + u + v, n});
    m.vertices.push_back({c - u + v, n});
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
}

MeshPart addUnitCube(SceneMesh& m) {
    MeshPart part{static_cast<std::uint32_t>(m.indices.size()), 0};
    // Each face: centre, two half-edges (u x v points outward), outward normal.
    const glm::vec3 x(0.5f, 0, 0), y(0, 0.5f, 0), z(0, 0, 0.5f);
    addQuadFace(m, x, -z, y, {1, 0, 0});
    addQuadFace(m, -x, z, y, {-1, 0, 0});
    addQuadFace(m, y, x, -z, {0, 1, 0});
    addQuadFace(m, -y, x, z, {0, -1, 0});
    addQuadFace(m, z, x, y, {0, 0, 1});
    addQuadFace(m, -z, -x, y, {0, 0, -1});
    part.indexCount = static_cast<std::uint32_t>(m.indices.size()) - part.firstIndex;
    return part;
}

MeshPart addUnitSphere(SceneMesh& m, int segments) {
    MeshPart part{static_cast<std::uint32_t>(m.indices.size()), 0};
    int rings = std::max(segments / 2, 6);
    auto base = static_cast<std::uint32_t>(m.vertices.size());
    for (int r = 0; r <= rings; ++r) {
        float theta = glm::pi<float>() * r / rings;  // from +y down to -y
        for (int s = 0; s <= segments; ++s) {
            float phi = glm::two_pi<float>() * s / segments;
            glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                        -std::sin(theta) * std::sin(phi));
            m.vertices.push_back({n, n});  // unit sphere: position == normal
        }
    }
    auto at = [&](int r, int s) { return base + std::uint32_t(r * (segments + 1) + s); };
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            std::uint32_t a = at(r, s), b = at(r + 1, s), c = at(r + 1, s + 1), d = at(r, s + 1);
            if (r != 0) m.indices.insert(m.indices.end(), {a, b, d});
            if (r != rings - 1) m.indices.insert(m.indices.end(), {b, c, d});
        }
    part.indexCount = static_cast<std::uint32_t>(m.indices.size()) - part.firstIndex;
    return part;
}

MeshPart addUnitQuad(SceneMesh& m) {
    MeshPart part{static_cast<std::uint32_t>(m.indices.size()), 0};
    addQuadFace(m, {0, 0, 0}, {0.5f, 0, 0}, {0, 0.5f, 0}, {0, 0, 1});
    part.indexCount = 6;
    return part;
}

// Vertices of a unit sphere with `segments` around (see addUnitSphere).
std::size_t sphereVertices(int segments) {
    return std::size_t(std::max(segments / 2, 6) + 1) * std::size_t(segments + 1);
}

}  // namespace

SceneMesh tessellate(const Scene& scene, const Camera& camera, int imageHeight) {
    std::vector<int> segments(scene.objects.size(), 0);
    std::size_t total = 0;
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        if (scene.objects[i].kind == PrimitiveKind::Sphere) {
            segments[i] = sphereSegmentsForHalfPixel(scene.objects[i], camera, imageHeight);
            total += sphereVertices(segments[i]);
        }
    // Many large spheres near the camera could ask for gigabytes (4096 x 512 segments); above
    // the budget every sphere gets coarser, never below 12 segments.
    while (total > kSphereVertexBudget) {
        total = 0;
        for (std::size_t i = 0; i < segments.size(); ++i)
            if (segments[i] > 0) {
                segments[i] = std::max(segments[i] / 2, 12);
                total += sphereVertices(segments[i]);
            }
        if (std::all_of(segments.begin(), segments.end(), [](int s) { return s == 0 || s == 12; }))
            break;
    }
    SceneMesh mesh;
    MeshPart cube = addUnitCube(mesh);
    mesh.unitQuad = addUnitQuad(mesh);
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        MeshPart part = cube;
        if (o.kind == PrimitiveKind::Sphere)
            part = addUnitSphere(mesh, segments[i]);
        else if (o.kind == PrimitiveKind::Quad)
            part = mesh.unitQuad;
        mesh.objects.push_back(part);
        mesh.sphereSegments.push_back(segments[i]);
    }
    return mesh;
}

}  // namespace sl
