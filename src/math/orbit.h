// The window's camera and light motion as plain functions: orbiting the camera around its
// target without going under the floor, turning the light at a speed in radians per second, and
// the field of view of a picture narrower than the scenes were framed for.
#pragma once

#include "scene/scene.h"

namespace sl {

// The lowest point of the scene's objects (the floor's height in the lecture scenes).
float sceneFloorHeight(const Scene& scene);
// What an orbiting camera must stay above: the top of the floor when the lowest object is a
// horizontal slab or quad (the lecture scenes' floor: its top at y = 0, its bottom at -0.1),
// else the lowest point.
float sceneReceiverHeight(const Scene& scene);

// Turns the camera around `at` by yaw and pitch (radians); the eye stays at least `clearance`
// above `floorY` and short of straight up, whatever the drag.
Camera orbitCamera(const Camera& c, float yaw, float pitch, float floorY, float clearance = 0.05f);

// Moves the eye along its line to `at`, its distance times `factor` (the mouse wheel), kept
// between twice the near plane and half the far plane so the scene never leaves the frustum.
Camera zoomCamera(const Camera& c, float factor);

// The scenes' cameras are framed for 4:3 (the default 640x480). A picture narrower than that (a
// split half, a tall window) gets a vertical field of view widened so that the scene's width
// still fits, at most 150 degrees; a wider one keeps `fovyDegrees`. The window and the page.
constexpr float kFramedAspect = 4.0f / 3.0f;
float fovyFittingWidth(float fovyDegrees, float aspect);

// The light on its circle around the y axis after `seconds` at `radiansPerSecond`, starting
// from `start` (height and radius kept).
// The lecture's circling light (the window's and the page's `l`), radians a second.
constexpr float kLightRadiansPerSecond = 0.6f;
glm::vec3 circlingLight(const glm::vec3& start, float radiansPerSecond, double seconds);

}  // namespace sl
