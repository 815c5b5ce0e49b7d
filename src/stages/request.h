// One render, as the command line, the tests and the grader describe it, and the code that
// turns it into a configured Renderer. Bad values throw UsageError (exit code 2). It sits in
// stages/, above render/: a request names a stage, resolved in the registry (stages/registry.h).
#pragma once

#include <cstdint>
#include <optional>
#include <utility>

#include "render/renderer.h"

namespace sl {

struct RenderRequest {
    std::string stage = "phong";
    GlslTree tree = GlslTree::Core;
    std::string scene = "slides";
    // True when the user chose the scene (--scene). When false and scene is the default
    // "slides", the stage's own default scene (StageInfo::defaultScene) is used instead.
    bool sceneGiven = false;
    std::string overlay;  // student shader folder, "" for none
    int width = 640, height = 480;
    std::optional<glm::vec3> eye, at, light;
    std::optional<float> fovy;
    std::vector<std::pair<std::string, std::string>> sets;  // --set NAME=VALUE
    ViewMode view = ViewMode::Final;
    // Grading's displaced view: displacedViewOf(scene, seed), the scene's casters, light and
    // camera moved, or in a scene with a mirror its camera and mirror (scene/mirror_displace.h);
    // an --eye, --at or --fovy given still wins.
    std::optional<std::uint64_t> displaceSeed;
};

// The folder of our shaders for a tree: <data>/shaders_core (or _legacy), or where an install
// has the `solutions` component, <data>/solutions/shaders_core (the marked trees beside the
// student edition's stubs).
std::string shaderTreeRoot(GlslTree tree);

// The note `release --student-edition` leaves at the root of each tree it writes (every marked
// solution region there is a stub), and whether our tree for `tree` carries it.
inline constexpr const char* kStudentEditionNote = "STUDENT_EDITION.md";
bool isStudentEdition(GlslTree tree);

// Checks the request against the stage (exists, tree allowed, view offered, parameters) before
// any GL work; throws UsageError with a one-line message.
void validateRequest(const RenderRequest& request);

// The scene a request renders: its own, or the stage's default when none was chosen.
std::string effectiveScene(const RenderRequest& request);

// Builds the renderer for a request (a GL context must be current). Throws UsageError,
// SceneError or ShaderError.
std::unique_ptr<Renderer> makeRenderer(const RenderRequest& request);
// Applies stage, camera, light, view and parameters to an existing renderer.
void applyRequest(Renderer& renderer, const RenderRequest& request);

}  // namespace sl
