// What every shadow-mapping stage does: render the map from the light (only when it is stale),
// then the lit pass that compares against it, plus the debug views. A stage supplies its map
// settings and the uniforms its shaders read; its shaders live in shaders_*/<id>/.
#pragma once

#include "render/shadow_map.h"
#include "stages/stage.h"

namespace sl {

// Parameters every shadow stage shares: map-size, light-fit, casters.
std::vector<ParamSpec> commonShadowParams(const std::string& castersDefault);
// Reads the shared parameters into settings.
ShadowMapSettings commonShadowSettings(const ParamSet& p);
// The views every shadow stage offers.
std::vector<ViewMode> shadowViews();
// The source rule every shadow stage and the mirror carry: a comparison of the camera, the
// light or the pixel's place on screen against a constant is a way to recognise the graded views.
SourceRule gamingRule();

class ShadowStage : public Stage {
  public:
    explicit ShadowStage(std::string id) : id_(std::move(id)) {}
    void render(FrameContext& f) override;
    // Built on demand from the last frame's map (formatting it every frame cost ~150,000
    // instructions a frame, callgrind).
    std::string explain() const override;
    // Its map's pass and its lit pass (litPass), every frame.
    std::vector<std::string> passes(const ParamSet& p) const override {
        return {"shadow", litPass(p)};
    }

  protected:
    virtual ShadowMapSettings settings(const ParamSet& p) const = 0;
    // Uniforms of this stage's shadow-pass and lit-pass programs (margin, encodings...).
    virtual void setShadowUniforms(Program&, const ParamSet&) const {}
    virtual void setLitUniforms(Program&, const ParamSet&) const {}
    // The lit pass's program name in shaders_*/<id>/ (a stage with several lookups has one each).
    virtual std::string litPass(const ParamSet&) const { return "lit"; }
    // z scale of the bias matrix the lit pass uses (+0.5 for OpenGL's projection).
    virtual float biasZ(const ParamSet&) const { return 0.5f; }
    // How the debug view decodes the map: 0 depth, 1 one 8-bit value, 2 packed RGB.
    virtual int mapEncoding(const ParamSet&) const {
        return settings_.storage == MapStorage::Rgb8 ? 1 : 0;
    }

    ShadowMap map_;
    ShadowMapSettings settings_;

  private:
    void showMap(FrameContext& f);
    void describe(FrameContext& f);
    std::string id_;
    float explainedBiasZ_ = 0.5f;  // the bias matrix's z scale of the last frame
};

}  // namespace sl
