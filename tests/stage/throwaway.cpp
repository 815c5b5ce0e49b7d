// A throwaway stage for the "adding a stage" test (docs/adding-a-stage.md): the file a new stage
// would be at src/stages/throwaway.cpp, here so the real program never lists it. It draws the
// scene lit with its own shaders (throwaway/lit.vert, lit.frag: the test copies phong's), so its
// lesson is phong's: no shadows.
#include "render/scene_pass.h"
#include "stages/stage.h"

namespace sl {

namespace {

class ThrowawayStage : public Stage {
  public:
    void render(FrameContext& f) override {
        PassScope pass("lit");
        clearToBackground(f);
        drawSceneLit(f.shaders.program("throwaway", "lit"), f, cameraViewer(f), 0);
    }
};

}  // namespace

StageDefinition throwawayStage() {
    StageDefinition s;
    s.id = "throwaway";
    s.title = "A throwaway stage (the adding-a-stage test)";
    s.lecture = "none: it proves a stage is its own file, its shaders and one line";
    s.views = {ViewMode::Final};
    s.create = [] { return std::make_unique<ThrowawayStage>(); };
    return s;
}

}  // namespace sl
