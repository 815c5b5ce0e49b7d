#include "render/renderer.h"

#include <stdexcept>

namespace sl {

Renderer::Renderer(Scene scene, ShaderLibrary shaders, int imageHeight,
                   std::vector<const StageInfo*> stages)
    : camera(scene.camera),
      lightPosition(scene.light.position),
      scene_(std::move(scene)),
      shaders_(std::move(shaders)),
      gpu_(scene_, camera, imageHeight),
      stages_(std::move(stages)) {
    if (stages_.empty()) throw std::invalid_argument("a renderer needs at least one stage");
    for (const StageInfo* s : stages_) params_.emplace(s->id, ParamSet(s->params));
    selectStage(stages_.front()->id);
}

void Renderer::selectStage(const std::string& id) {
    const StageInfo* info = nullptr;
    std::vector<std::string> known;
    for (const StageInfo* s : stages_) {
        known.push_back(s->id);
        if (s->id == id) info = s;
    }
    if (!info) {
        std::string ids;
        for (const auto& s : known) ids += (ids.empty() ? "" : ", ") + s;
        std::string hint = closestMatch(id, known);
        throw std::invalid_argument("unknown stage '" + id + "'" +
                                    (hint.empty() ? "" : " (did you mean '" + hint + "'?)") +
                                    "; stages: " + ids);
    }
    if (info == info_) return;
    info_ = info;
    stage_ = info->create();
}

std::size_t Renderer::stageIndex() const {
    for (std::size_t i = 0; i < stages_.size(); ++i)
        if (stages_[i] == info_) return i;
    return 0;
}

void Renderer::render(GLuint target, int width, int height) {
    if (lightPosition != lastLight_) {  // a moved light makes every cached shadow map stale
        lastLight_ = lightPosition;
        ++sceneGeneration_;
    }
    stats.notes.clear();
    stats.shadowMs = stats.litMs = stats.mirrorMs = 0;  // a pass that does not run costs 0
    stats.mapSize = 0;
    FrameContext f{scene_, gpu_,   shaders_, params(), camera,     lightPosition,    width,
                   height, target, view,     allLit,   timePasses, sceneGeneration_, stats};
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, width, height);
    glEnable(GL_DEPTH_TEST);
    stage_->render(f);
}

}  // namespace sl
