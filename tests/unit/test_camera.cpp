#include <gtest/gtest.h>

#include "math/camera.h"

using namespace sl;

TEST(Camera, PixelCentreNdcFollowsTheGuide) {
    glm::vec2 tl = pixelCenterNdc(0, 0, 640, 480);
    EXPECT_FLOAT_EQ(tl.x, 0.5f / 640 * 2 - 1);
    EXPECT_FLOAT_EQ(tl.y, 1 - 0.5f / 480 * 2);
}

TEST(Camera, ProjectingAPixelRayPointLandsOnThatPixel) {
    Camera c;
    c.eye = {1, 2, 3};
    c.at = {0, 0.2f, 0};
    for (int j : {0, 100, 479})
        for (int i : {0, 321, 639}) {
            Ray r = pixelRay(c, i, j, 640, 480);
            glm::vec2 px;
            ASSERT_TRUE(projectToPixel(c, 640, 480, r.origin + 2.0f * r.direction, px));
            EXPECT_NEAR(px.x, i + 0.5f, 1e-3);
            EXPECT_NEAR(px.y, j + 0.5f, 1e-3);
        }
}

TEST(Camera, SafeUpIsNeverParallelToTheViewDirection) {
    for (glm::vec3 at : {glm::vec3(0, -5, 0), glm::vec3(0, 5, 0), glm::vec3(1e-6f, -3, 0)}) {
        glm::vec3 eye(0, 0, 0);
        glm::vec3 up = safeUp(eye, at);
        glm::vec3 d = glm::normalize(at - eye);
        EXPECT_LT(std::abs(glm::dot(d, up)), 0.5f);
    }
    EXPECT_EQ(safeUp({2, 1, 0}, {0, 0, 0}), glm::vec3(0, 1, 0));
}
