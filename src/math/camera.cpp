#include "math/camera.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace sl {

glm::vec3 safeUp(const glm::vec3& eye, const glm::vec3& at, const glm::vec3& preferred) {
    glm::vec3 dir = at - eye;
    float len = glm::length(dir);
    if (len <= 0.0f) return preferred;
    dir /= len;
    glm::vec3 up = glm::normalize(preferred);
    // Within about 0.6 degrees of the up vector lookAt's cross product loses its precision.
    if (std::abs(glm::dot(dir, up)) < 0.99995f) return up;
    // Looking along the preferred up: pick the world axis least aligned with the view direction.
    glm::vec3 a = glm::abs(dir);
    if (a.x <= a.y && a.x <= a.z) return {1, 0, 0};
    if (a.z <= a.y) return {0, 0, -1};
    return {0, 1, 0};
}

glm::mat4 viewMatrix(const Camera& c) {
    return glm::lookAt(c.eye, c.at, safeUp(c.eye, c.at));
}

glm::mat4 projectionMatrix(const Camera& c, float aspect) {
    return glm::perspective(glm::radians(c.fovyDegrees), aspect, c.zNear, c.zFar);
}

glm::vec2 pixelCenterNdc(int i, int j, int width, int height) {
    return {(i + 0.5f) / width * 2.0f - 1.0f, 1.0f - (j + 0.5f) / height * 2.0f};
}

Ray pixelRay(const Camera& c, int i, int j, int width, int height) {
    return PixelRays(c, width, height)(i, j);
}

PixelRays::PixelRays(const Camera& c, int width, int height)
    : invView_(glm::inverse(viewMatrix(c))),
      eye_(c.eye),
      tanHalfFovy_(std::tan(glm::radians(c.fovyDegrees) * 0.5f)),
      aspect_(static_cast<float>(width) / static_cast<float>(height)),
      width_(width),
      height_(height) {}

Ray PixelRays::operator()(int i, int j) const {
    glm::vec2 ndc = pixelCenterNdc(i, j, width_, height_);
    glm::vec3 dirCam(ndc.x * tanHalfFovy_ * aspect_, ndc.y * tanHalfFovy_, -1.0f);
    glm::vec3 dir = glm::normalize(glm::vec3(invView_ * glm::vec4(dirCam, 0.0f)));
    return {eye_, dir};
}

bool projectToPixel(const Camera& c, int width, int height, const glm::vec3& p, glm::vec2& pixel) {
    glm::vec4 clip =
        projectionMatrix(c, float(width) / float(height)) * viewMatrix(c) * glm::vec4(p, 1.0f);
    if (clip.w <= 0.0f) return false;
    glm::vec2 ndc = glm::vec2(clip) / clip.w;
    pixel = {(ndc.x + 1.0f) * 0.5f * width, (1.0f - ndc.y) * 0.5f * height};
    return true;
}

}  // namespace sl
