// The window's orbit and light animation: plain functions, checked without a window.
#include <gtest/gtest.h>

#include <cmath>

#include "math/orbit.h"

using namespace sl;

TEST(Orbit, FloorHeightIsTheLowestPoint) {
    Scene s;
    Object floor;
    floor.kind = PrimitiveKind::Quad;
    floor.center = {0, 0, 0};
    floor.normal = {0, 1, 0};
    floor.up = {0, 0, -1};
    Object ball;
    ball.kind = PrimitiveKind::Sphere;
    ball.center = {0, 0.2f, 0};
    ball.radius = 0.5f;  // dips below the floor: the lowest point is the ball's
    s.objects = {floor, ball};
    EXPECT_NEAR(sceneFloorHeight(s), -0.3f, 1e-6);
    s.objects = {floor};
    EXPECT_NEAR(sceneFloorHeight(s), 0.0f, 1e-6);
}

// The lecture scenes' floor is a 0.1-thick box with its top at y = 0: the orbit stays above its
// top (it used to reach eye y = -0.05, its bottom plus the clearance); a scene whose lowest
// object is no floor keeps the lowest point.
TEST(Orbit, ReceiverIsTheFloorsTop) {
    Scene s;
    Object floor;
    floor.kind = PrimitiveKind::Box;
    floor.center = {0, -0.05f, 0};
    floor.size = {3, 0.1f, 3};
    Object cube;
    cube.kind = PrimitiveKind::Box;
    cube.center = {0, 0.25f, 0};
    cube.size = {0.5f, 0.5f, 0.5f};
    s.objects = {cube, floor};
    EXPECT_NEAR(sceneReceiverHeight(s), 0.0f, 1e-6);
    Object ball;
    ball.kind = PrimitiveKind::Sphere;
    ball.center = {0, 0, 0};
    ball.radius = 1;
    s.objects = {ball};
    EXPECT_NEAR(sceneReceiverHeight(s), -1.0f, 1e-6);
    Camera c;
    c.eye = {0, 2, 4};
    c.at = {-0.25f, 0, 0};
    s.objects = {cube, floor};
    for (int k = 0; k < 50; ++k) c = orbitCamera(c, 0.0f, -0.2f, sceneReceiverHeight(s));
    EXPECT_GE(c.eye.y, 0.05f - 1e-4f);
}

TEST(Orbit, DraggingDownStopsAboveTheFloor) {
    Camera c;
    c.eye = {0, 2, 4};
    c.at = {0, 0.5f, 0};
    float radius = glm::length(c.eye - c.at);
    for (int k = 0; k < 50; ++k) c = orbitCamera(c, 0.0f, -0.2f, 0.0f, 0.05f);
    EXPECT_GE(c.eye.y, 0.05f - 1e-4f);
    EXPECT_LT(c.eye.y, 0.1f);  // it did go down as far as allowed
    EXPECT_NEAR(glm::length(c.eye - c.at), radius, 1e-4);
}

TEST(Orbit, DraggingUpStopsShortOfStraightUp) {
    Camera c;
    c.eye = {0, 2, 4};
    for (int k = 0; k < 50; ++k) c = orbitCamera(c, 0.3f, 0.2f, 0.0f);
    glm::vec3 d = glm::normalize(c.eye - c.at);
    EXPECT_NEAR(std::asin(d.y), 1.5f, 1e-3);
}

TEST(Orbit, YawKeepsHeightAndDistance) {
    Camera c;
    c.eye = {0, 2, 4};
    Camera turned = orbitCamera(c, 1.0f, 0.0f, 0.0f);
    EXPECT_NEAR(turned.eye.y, 2.0f, 1e-5);
    EXPECT_NEAR(glm::length(turned.eye), glm::length(c.eye), 1e-5);
    EXPECT_NEAR(std::atan2(turned.eye.x, turned.eye.z), 1.0f, 1e-5);
}

TEST(Orbit, LightTurnsByRadiansPerSecondNotPerFrame) {
    glm::vec3 start(2, 3, 0);
    glm::vec3 quarter =
        circlingLight(start, static_cast<float>(M_PI / 2), 1.0);  // 1 s at pi/2 rad/s
    EXPECT_NEAR(quarter.x, 0.0f, 1e-5);
    EXPECT_NEAR(quarter.z, 2.0f, 1e-5);
    EXPECT_NEAR(quarter.y, 3.0f, 1e-6);
    // Ten steps of 0.1 s land where one step of 1 s does: the frame rate does not matter.
    glm::vec3 p = start;
    for (int k = 0; k < 10; ++k) p = circlingLight(p, 0.5f, 0.1);
    glm::vec3 once = circlingLight(start, 0.5f, 1.0);
    EXPECT_NEAR(glm::length(p - once), 0.0f, 1e-4);
}

// The wheel: the eye moves along its line to the target, never closer than twice the near plane
// nor farther than half the far plane.
TEST(Orbit, ZoomKeepsTheDirectionAndStaysInTheFrustum) {
    Camera c;
    c.eye = {0, 3, 4};  // 5 from the target
    c.at = {0, 0, 0};
    Camera in = zoomCamera(c, 0.8f);
    EXPECT_NEAR(glm::length(in.eye - in.at), 4.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(glm::normalize(in.eye), glm::normalize(c.eye)), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::length(zoomCamera(c, 0.001f).eye), 2 * c.zNear, 1e-5f);
    EXPECT_NEAR(glm::length(zoomCamera(c, 100.0f).eye), 0.5f * c.zFar, 1e-4f);
}
