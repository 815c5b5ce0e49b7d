#include "scene/scene.h"

namespace sl {

glm::vec3 mirrorRight(const Mirror& m) { return glm::normalize(glm::cross(m.up, m.normal)); }

MirrorCorners mirrorCorners(const Mirror& m) {
    glm::vec3 r = mirrorRight(m) * (0.5f * m.width);
    glm::vec3 u = glm::normalize(m.up) * (0.5f * m.height);
    return {{m.center - r - u, m.center + r - u, m.center + r + u, m.center - r + u}};
}

}  // namespace sl
