// Stage 3: the scale/bias matrix built by hand. The slides use -0.5 on z, which is right only
// when the light's projection maps near to NDC +1 and the depth range is reversed.
#include "stages/shadow_stage.h"

namespace sl {

namespace {

class BiasStage : public ShadowStage {
  public:
    BiasStage() : ShadowStage("bias") {}

  protected:
    ShadowMapSettings settings(const ParamSet& p) const override {
        ShadowMapSettings s = commonShadowSettings(p);
        s.storage = MapStorage::Depth24;
        s.depthFlipped = p.is("light-z", "flipped");
        return s;
    }
    void setLitUniforms(Program& lit, const ParamSet& p) const override {
        lit.set("margin", static_cast<float>(p.number("margin")));
    }
    float biasZ(const ParamSet& p) const override { return p.is("bias-z", "+0.5") ? 0.5f : -0.5f; }
};

}  // namespace

StageDefinition biasStage() {
    StageDefinition s;
    s.id = "bias";
    s.title = "The scale/bias matrix, +0.5 or the slides' -0.5 on z";
    s.lecture = "texture coordinates from light NDC: bias * P_light * V_light * model";
    s.params = commonShadowParams("all");
    s.params.push_back(ParamSpec::choice("bias-z", {"-0.5", "+0.5"},
                                         "z scale of the bias matrix: the slides' -0.5, or +0.5"));
    s.params.push_back(ParamSpec::choice(
        "light-z", {"standard", "flipped"},
        "light projection: standard (near -> NDC -1) or flipped (near -> +1, glDepthRange(1,0))"));
    s.params.push_back(ParamSpec::number("margin", 0.01, 0.0, 0.1, 0.001,
                                         "added to the stored depth before comparing"));
    s.views = shadowViews();
    s.sourceRules = {gamingRule()};
    s.benchSeries = {BenchSeries(BenchGroup::MapSize, "bias")};
    s.create = [] { return std::make_unique<BiasStage>(); };
    return s;
}

}  // namespace sl
