// Camera conventions shared by the GL path and the CPU reference (GUIDE section 3):
// right-handed world, +Y up; view = lookAt(eye, at, +Y); projection = perspective(fovy, aspect,
// near, far) as gluPerspective; PNG row 0 is the top; pixel (i, j) has its centre at
// NDC x = (i + 0.5) / W * 2 - 1, y = 1 - (j + 0.5) / H * 2.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace sl {

struct Ray {
    glm::vec3 origin;
    glm::vec3 direction;  // unit length
};

// An up vector for lookAt that is never parallel to the viewing direction: +Y unless the
// camera looks (almost) straight up or down, then +Z or -Z... whichever is stable.
glm::vec3 safeUp(const glm::vec3& eye, const glm::vec3& at, const glm::vec3& preferred = {0, 1, 0});

glm::mat4 viewMatrix(const Camera& c);
glm::mat4 projectionMatrix(const Camera& c, float aspect);

// NDC of the centre of pixel (i, j) in a W x H image, row 0 at the top.
glm::vec2 pixelCenterNdc(int i, int j, int width, int height);

// The world-space ray from the eye through the centre of pixel (i, j).
Ray pixelRay(const Camera& c, int i, int j, int width, int height);

// pixelRay for every pixel of one W x H image, the camera's basis (the inverse view matrix)
// computed once instead of per pixel; each ray is bit for bit pixelRay's.
class PixelRays {
  public:
    PixelRays(const Camera& c, int width, int height);
    Ray operator()(int i, int j) const;

  private:
    glm::mat4 invView_;
    glm::vec3 eye_;
    float tanHalfFovy_, aspect_;
    int width_, height_;
};

// Project a world point to pixel coordinates (x right, y down, continuous; pixel (i,j) covers
// [i, i+1) x [j, j+1)). Returns false when the point is behind the camera.
bool projectToPixel(const Camera& c, int width, int height, const glm::vec3& p, glm::vec2& pixel);

}  // namespace sl
