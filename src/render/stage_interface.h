// What the renderer knows of a stage: an id, a title, the lecture step it teaches, its declared
// parameters and a render hook. The stages themselves live in src/stages/ (listed in
// stage_list.h, the expected outcome of their defaults in expectations.json); render/ never
// includes them nor calls their registry (stages/registry.h): a Renderer is handed the list.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "gl/debug.h"
#include "gl/shader_library.h"
#include "render/gpu_scene.h"
#include "render/stage_params.h"

namespace sl {

enum class ViewMode { Final, ShadowMap, Light, Visibility, LightDepth };
const char* viewName(ViewMode v);
bool parseView(const std::string& text, ViewMode& out);
std::vector<std::string> allViewNames();

// Per-frame figures a stage reports: timings per pass (when timing is on) and what it did.
struct RenderStats {
    unsigned shadowMapRenders = 0;  // cumulative: the map is re-rendered only when inputs change
    double shadowMs = 0, litMs = 0, mirrorMs = 0;
    std::vector<std::string> notes;  // shown in the HUD and by `render --explain`
    // The shadow map the frame looked up (mapSize 0: none), so the figures can tell how large one
    // of its texels lands on screen.
    glm::mat4 lightViewProjection{1.0f};
    int mapSize = 0;
};

// Everything a stage may use to draw one frame. The stage draws into `target`.
struct FrameContext {
    const Scene& scene;
    GpuScene& gpu;
    ShaderLibrary& shaders;
    const ParamSet& params;
    Camera camera;
    glm::vec3 lightPosition;
    int width = 0, height = 0;
    GLuint target = 0;
    ViewMode view = ViewMode::Final;
    bool allLit = false;           // the shadow map forced to "everything lit" (for `check`)
    bool timePasses = false;       // glFinish around passes to time them
    unsigned sceneGeneration = 0;  // bumps when the light or objects move
    RenderStats& stats;
};

class Stage {
  public:
    virtual ~Stage() = default;
    virtual void render(FrameContext& frame) = 0;
    // A readable account of the matrices and choices of the last frame (`render --explain`).
    virtual std::string explain() const { return {}; }
    // The programs of the stage's own folder (shaders_*/<id>/<pass>.vert, .frag) its final
    // picture draws with under `params`, told without drawing (no GL): `release` and `grade`
    // find from it, before rendering anything, a marked file a graded row needs that the
    // assignment does not list. Empty: only drawing tells (the check after grading catches it).
    virtual std::vector<std::string> passes(const ParamSet&) const { return {}; }
};

struct StageInfo {
    std::string id;
    std::string title;
    std::string lecture;  // which lecture step, in a few words
    std::vector<ParamSpec> params;
    // The expected outcome of the defaults lives in src/stages/expectations.json (one source of
    // truth for `check`, `stages`, reports and docs), not here.
    bool legacyOnly = false;  // needs the compatibility profile (the fixed-function stage)
    // The built-in scene used when the user gives no --scene ("" = slides), and whether the
    // scene must have a mirror (an explicit --scene without one is a usage error).
    std::string defaultScene;
    bool needsMirror = false;
    std::vector<ViewMode> views;
    // What `check` finds "dark without a caster" against: by default the lighting stage's picture
    // (the first stage the renderer is handed: lighting without shadows, drawn with our
    // shaders); when set, the stage's own all-lit render (the fixed-function stage, whose
    // lighting no shader of ours reproduces).
    bool unshadowedIsOwn = false;
    std::function<std::unique_ptr<Stage>()> create;
};

}  // namespace sl
