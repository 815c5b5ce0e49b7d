// Stage 5: the hardware does the comparison: a depth texture with compare mode, sampled through
// sampler2DShadow; polygon offset in the shadow pass instead of a margin; linear filtering
// averages four compares (PCF); filter=pcf3x3 averages nine.
#include "stages/shadow_stage.h"

namespace sl {

namespace {

class HardwareStage : public ShadowStage {
  public:
    HardwareStage() : ShadowStage("hardware") {}

  protected:
    ShadowMapSettings settings(const ParamSet& p) const override {
        ShadowMapSettings s = commonShadowSettings(p);
        s.storage = parseStorage(p.choice("depth-format"));
        s.compare = true;
        s.linear = p.is("filter", "linear");  // pcf3x3: nine GL_NEAREST compares
        s.offsetFactor = static_cast<float>(p.number("offset-factor"));
        s.offsetUnits = static_cast<float>(p.number("offset-units"));
        s.cullFront = p.is("shadow-cull", "front");
        s.cullBack = p.is("shadow-cull", "back");
        return s;
    }
    std::string litPass(const ParamSet& p) const override {
        return p.is("filter", "pcf3x3") ? "lit_pcf3x3" : "lit";
    }
    void setLitUniforms(Program& lit, const ParamSet&) const override {
        lit.set("texelSize", 1.0f / static_cast<float>(settings_.size));
    }
};

}  // namespace

StageDefinition hardwareStage() {
    StageDefinition s;
    s.id = "hardware";
    s.title = "Hardware compare: sampler2DShadow, polygon offset, PCF";
    s.lecture = "GL_COMPARE_REF_TO_TEXTURE + GL_LEQUAL, textureProj, glPolygonOffset(2, 4)";
    s.params = commonShadowParams("casters-only");
    s.params.push_back(
        ParamSpec::choice("filter", {"linear", "nearest", "pcf3x3"},
                          "linear: 2x2 percentage-closer filtering; nearest: one compare; "
                          "pcf3x3: nine compares one texel apart"));
    s.params.push_back(
        ParamSpec::number("offset-factor", 2.0, 0.0, 40.0, 1.0, "glPolygonOffset factor (slope)"));
    s.params.push_back(
        ParamSpec::number("offset-units", 4.0, 0.0, 100.0, 1.0, "glPolygonOffset units"));
    s.params.push_back(ParamSpec::choice(
        "depth-format", {"24", "32f", "16"},
        "depth texture format (bits): 24 as the slides; 32f is the cheapest compare on llvmpipe "
        "but does not clamp the reference, so a shader must clamp it (ours does); 16 halves the "
        "memory the map re-render writes"));
    s.params.push_back(ParamSpec::choice(
        "shadow-cull", {"back", "none", "front"},
        "back: skip closed casters' faces turned away from the light (same map, half the "
        "fragments); none: draw both sides; front: draw only casters' back faces into the map"));
    s.views = shadowViews();
    s.sourceRules = {gamingRule()};
    // Issue 14's speed targets at 640x480 with a 1024 map (issue 6 had asked 1.05x still for
    // the 2x2 filter).
    BenchTarget linear{
        "hardware, 1024 map, ",
        1024,
        {{true, 1.3, "light moving: {ratio}x phong"}, {false, 1.12, "still: {ratio}x"}}};
    BenchTarget nearest{
        "hardware filter=nearest, ", 1024, {{false, 1.06, "light still: {ratio}x phong"}}};
    s.benchSeries = {
        BenchSeries(BenchGroup::MapSize, "hardware/linear").withTarget(linear),
        BenchSeries(BenchGroup::MapSize, "hardware/nearest", {{"filter", "nearest"}})
            .withTarget(nearest),
        // Ranked after fixed: added later, and the published tables keep their order.
        BenchSeries(BenchGroup::MapSize, "hardware/pcf3x3", {{"filter", "pcf3x3"}}).ranked(1),
        BenchSeries(BenchGroup::Format, "hardware/16", {{"depth-format", "16"}}),
        BenchSeries(BenchGroup::Format, "hardware/32f", {{"depth-format", "32f"}}),  // 24: default
        BenchSeries(BenchGroup::Format, "hardware/cull-front", {{"shadow-cull", "front"}}),
        BenchSeries(BenchGroup::EqualAccuracy, "hardware/linear"),
        BenchSeries(BenchGroup::EqualAccuracy, "hardware/nearest", {{"filter", "nearest"}}),
        BenchSeries(BenchGroup::EqualAccuracy, "hardware/pcf3x3", {{"filter", "pcf3x3"}}),
    };
    s.create = [] { return std::make_unique<HardwareStage>(); };
    return s;
}

}  // namespace sl
