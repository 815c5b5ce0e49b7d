#include "scene/scene.h"

namespace sl {

glm::vec3 mirrorRight(const Mirror& m) {
    return glm::normalize(glm::cross(m.up, m.normal));
}

bool pointInside(const Object& o, const glm::vec3& p) {
    switch (o.kind) {
        case PrimitiveKind::Box: {
            glm::vec3 d = glm::abs(p - o.center) - 0.5f * o.size;
            return d.x < 0 && d.y < 0 && d.z < 0;
        }
        case PrimitiveKind::Sphere:
            return glm::length(p - o.center) < o.radius;
        case PrimitiveKind::Quad:
            return false;
    }
    return false;
}

MirrorCorners mirrorCorners(const Mirror& m) {
    glm::vec3 r = mirrorRight(m) * (0.5f * m.width);
    glm::vec3 u = glm::normalize(m.up) * (0.5f * m.height);
    return {{m.center - r - u, m.center + r - u, m.center + r + u, m.center - r + u}};
}

}  // namespace sl
