// The renderer: one scene, one shader tree, the current stage and its parameters. It draws a
// frame into whatever framebuffer the platform hands it; it never knows which platform that is.
#pragma once

#include <cmath>
#include <map>
#include <memory>

#include "render/stage_interface.h"

namespace sl {

class Renderer {
  public:
    // Needs a current GL context. `imageHeight` sets how finely spheres are tessellated.
    // `stages` (the registry's stageInfos(), never empty) outlive the renderer; the first is
    // selected.
    Renderer(Scene scene, ShaderLibrary shaders, int imageHeight,
             std::vector<const StageInfo*> stages);

    // Throws std::invalid_argument naming the allowed ids.
    void selectStage(const std::string& id);
    void selectStage(std::size_t index) { selectStage(stages_.at(index)->id); }
    const StageInfo& stage() const { return *info_; }
    std::size_t stageIndex() const;
    ParamSet& params() { return params_[info_->id]; }

    // Draws one frame of the current stage into `target` (width x height).
    void render(GLuint target, int width, int height);

    // Rebuilds changed (or all) shader programs; a failure keeps the last good program.
    std::vector<std::string> reloadShaders(bool force,
                                           const std::set<std::string>* stages = nullptr) {
        return shaders_.reload(force, stages);
    }
    std::string explain() const { return stage_ ? stage_->explain() : ""; }

    const Scene& scene() const { return scene_; }
    ShaderLibrary& shaders() { return shaders_; }
    GpuScene& gpu() { return gpu_; }

    Camera camera;
    glm::vec3 lightPosition;
    ViewMode view = ViewMode::Final;
    bool allLit = false;
    bool timePasses = false;
    RenderStats stats;
    // Call after moving the light or objects so cached shadow maps are re-rendered.
    void sceneChanged() { ++sceneGeneration_; }

  private:
    Scene scene_;
    ShaderLibrary shaders_;
    GpuScene gpu_;
    std::vector<const StageInfo*> stages_;
    const StageInfo* info_ = nullptr;
    std::unique_ptr<Stage> stage_;
    std::map<std::string, ParamSet> params_;  // kept per stage while switching
    unsigned sceneGeneration_ = 0;
    glm::vec3 lastLight_{NAN};
};

}  // namespace sl
