// Drawing the scene's objects with a program: the uniforms every pass shares, set once here.
#pragma once

#include <functional>

#include "render/stage_interface.h"

namespace sl {

// Where the scene is seen from in a pass: the camera, or the light for the light's-view picture.
struct Viewer {
    glm::mat4 view{1}, projection{1};
    glm::vec3 eye{0};
};
Viewer cameraViewer(const FrameContext& f);

using PerObject = std::function<void(Program&, std::size_t index, const glm::mat4& model)>;

// Lit pass: lighting uniforms (lightPosition, eyePosition, material, debugView), then every
// object with model, normalMatrix and objectColor; `perObject` adds a stage's own uniforms.
void drawSceneLit(Program& program, const FrameContext& f, const Viewer& viewer, int debugView,
                  const PerObject& perObject = {});

// Which objects a pass from the light draws: every one, the shadow casters only, or the objects
// that cast no shadow only (grading's "everything lit" map: a real map of the scene with its
// casters out of the light's way, which a shader cannot tell from any other frame).
enum class FromLight { All, Casters, Receivers, None };

// Depth-only style pass (shadow map): `lightViewProjection` as `lightViewProjection`, each
// object's `model`, for the objects `which` names.
void drawSceneFromLight(Program& program, const FrameContext& f,
                        const glm::mat4& lightViewProjection, FromLight which,
                        const PerObject& perObject = {});

// Clears the bound framebuffer to the scene's background.
void clearToBackground(const FrameContext& f);

}  // namespace sl
