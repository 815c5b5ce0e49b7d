// What a well-formed assignment may still not say (assignment.h, checkAssignmentMeaning): each
// would cost every student points that no shader could earn, so it is refused before anyone
// is graded, naming the file, the JSON path and the line.
#include <cmath>
#include <cstdio>
#include <glm/glm.hpp>

#include "course/assignment.h"
#include "scene/scene_json.h"

namespace sl {

namespace {

// Closer than this to a surface counts as on it (scene units; the scenes are a few units wide).
constexpr float kOnSurface = 1e-3f;

std::string point(const glm::vec3& p) {
    char s[96];
    std::snprintf(s, sizeof s, "(%g, %g, %g)", double(p.x), double(p.y), double(p.z));
    return s;
}

// Whether `p` is inside `o` or on its surface.
bool touches(const Object& o, const glm::vec3& p) {
    glm::vec3 d = p - o.center;
    switch (o.kind) {
        case PrimitiveKind::Box: {
            glm::vec3 out = glm::abs(d) - 0.5f * o.size;
            return out.x < kOnSurface && out.y < kOnSurface && out.z < kOnSurface;
        }
        case PrimitiveKind::Sphere:
            return glm::length(d) < o.radius + kOnSurface;
        case PrimitiveKind::Quad: {
            glm::vec3 n = glm::normalize(o.normal), up = glm::normalize(o.up);
            glm::vec3 right = glm::normalize(glm::cross(up, n));
            return std::abs(glm::dot(d, n)) < kOnSurface &&
                   std::abs(glm::dot(d, right)) <= 0.5f * o.width &&
                   std::abs(glm::dot(d, up)) <= 0.5f * o.height;
        }
    }
    return false;
}

// The name of the object of `scene` that `p` is inside or on, or "".
std::string objectAt(const Scene& scene, const glm::vec3& p) {
    for (std::size_t k = 0; k < scene.objects.size(); ++k)
        if (touches(scene.objects[k], p))
            return scene.objects[k].name.empty() ? "object " + std::to_string(k + 1)
                                                 : "'" + scene.objects[k].name + "'";
    if (scene.mirror) {
        const Mirror& m = *scene.mirror;
        Object quad;
        quad.kind = PrimitiveKind::Quad;
        quad.center = m.center;
        quad.normal = m.normal;
        quad.up = m.up;
        quad.width = m.width;
        quad.height = m.height;
        if (touches(quad, p)) return "the mirror";
    }
    return "";
}

void checkExtraView(const Assignment& a, const ExtraView& v, const std::string& path) {
    Scene scene = loadScene(v.scene);
    glm::vec3 eye = v.eye.value_or(scene.camera.eye), at = v.at.value_or(scene.camera.at);
    glm::vec3 light = v.light.value_or(scene.light.position);
    // The field to name: the one the instructor set, else the view (the scene's default).
    auto field = [&](bool set, const std::string& name) { return set ? path + "/" + name : path; };
    auto fail = [&](const std::string& where, const std::string& what) {
        throw AssignmentError(a.at(where) + ": " + what);
    };
    if (glm::length(at - eye) < kOnSurface)
        fail(field(v.eye.has_value(), "eye"), "the eye " + point(eye) +
                                                  " is at the point it looks at " + point(at) +
                                                  ": the camera has no direction");
    glm::vec3 dir = glm::normalize(at - eye);
    if (glm::length(glm::cross(dir, glm::vec3(0, 1, 0))) < 1e-4f)
        fail(field(v.eye.has_value(), "eye"),
             "the camera looks straight " + std::string(dir.y > 0 ? "up" : "down") + " from " +
                 point(eye) + " to " + point(at) +
                 ": with +Y up its view is undefined; move the eye or at sideways");
    std::string inside = objectAt(scene, eye);
    if (!inside.empty())
        fail(field(v.eye.has_value(), "eye"),
             "the eye " + point(eye) + " is inside or on " + inside + " of scene " + v.scene);
    inside = objectAt(scene, light);
    if (!inside.empty())
        fail(field(v.light.has_value(), "light"),
             "the light " + point(light) + " is inside or on " + inside + " of scene " + v.scene +
                 ": nothing it should light can be judged");
}

}  // namespace

void checkAssignmentMeaning(const Assignment& a) {
    for (std::size_t k = 0; k < a.extraViews.size(); ++k)
        checkExtraView(a, a.extraViews[k], "/extra_views/" + std::to_string(k));
    for (std::size_t k = 0; k < a.stages.size(); ++k) {
        const AssignmentStage& s = a.stages[k];
        if (!s.due) continue;
        std::string path = "/stages/" + std::to_string(k);
        if (!(s.points > 0))
            throw AssignmentError(a.at(path + "/points") + ": a due stage needs points above 0 (" +
                                  s.stage + "/" + s.tree +
                                  " has none); \"due\": false lists it without grading it");
        // Any seed: whether the displaced view is there does not depend on its value.
        if (planStage(a, s, "", std::uint64_t(1)).empty())
            throw AssignmentError(
                a.at(path + (a.lines.count(path + "/lessons") ? "/lessons" : "/views")) +
                ": every row of " + s.stage + "/" + s.tree +
                " weighs 0 (lesson weight x view weight): the stage could earn no points");
    }
}

}  // namespace sl
