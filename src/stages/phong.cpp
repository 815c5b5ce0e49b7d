// Stage 0, the baseline: Phong lighting with no shadows at all.
#include <chrono>

#include "render/scene_pass.h"
#include "stages/stage.h"

namespace sl {

namespace {

class PhongStage : public Stage {
  public:
    void render(FrameContext& f) override {
        PassScope pass("lit");
        auto start = std::chrono::steady_clock::now();
        clearToBackground(f);
        int debugView = f.view == ViewMode::LightDepth ? 2 : f.view == ViewMode::Visibility ? 1 : 0;
        drawSceneLit(f.shaders.program("phong", "lit"), f, cameraViewer(f), debugView);
        if (f.timePasses) {
            glFinish();
            f.stats.litMs =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count();
        }
    }
};

}  // namespace

StageDefinition phongStage() {
    StageDefinition s;
    s.id = "phong";
    s.title = "Phong lighting, no shadows";
    s.lecture = "the starting point: the floor is bright where shadows belong";
    s.views = {ViewMode::Final, ViewMode::Visibility, ViewMode::LightDepth};
    s.create = [] { return std::make_unique<PhongStage>(); };
    return s;
}

}  // namespace sl
