// Stage 2: a depth-component texture written through gl_FragDepth: more precision than 8 bits,
// the same manual comparison.
#include "stages/shadow_stage.h"

namespace sl {

namespace {

class DepthStage : public ShadowStage {
  public:
    DepthStage() : ShadowStage("depth") {}

  protected:
    ShadowMapSettings settings(const ParamSet& p) const override {
        ShadowMapSettings s = commonShadowSettings(p);
        s.storage = parseStorage(p.choice("depth-format"));
        return s;
    }
    void setLitUniforms(Program& lit, const ParamSet& p) const override {
        lit.set("margin", static_cast<float>(p.number("margin")));
    }
};

}  // namespace

StageDefinition depthStage() {
    StageDefinition s;
    s.id = "depth";
    s.title = "Depth texture written through gl_FragDepth";
    s.lecture = "more precision: GL_DEPTH_COMPONENT16 instead of 8-bit colour";
    s.params = commonShadowParams("all");
    s.params.push_back(
        ParamSpec::choice("depth-format", {"16", "24", "32f"}, "depth texture format (bits)"));
    s.params.push_back(ParamSpec::number("margin", 0.01, 0.0, 0.1, 0.001,
                                         "added to the stored depth before comparing"));
    s.views = shadowViews();
    s.sourceRules = {gamingRule()};
    s.benchSeries = {
        BenchSeries(BenchGroup::MapSize, "depth"),
        BenchSeries(BenchGroup::Format, "depth/16", {{"depth-format", "16"}}),
        BenchSeries(BenchGroup::Format, "depth/24", {{"depth-format", "24"}}),
        BenchSeries(BenchGroup::Format, "depth/32f", {{"depth-format", "32f"}}),
        BenchSeries(BenchGroup::EqualAccuracy, "depth").ranked(2),  // after hardware, margin
    };
    s.create = [] { return std::make_unique<DepthStage>(); };
    return s;
}

}  // namespace sl
