// Stage 4: the margin fix for acne, constant (the slides' 0.01, the notes' 1/256 for 8 bits) or
// scaled with the slope between N and L.
#include "stages/shadow_stage.h"

namespace sl {

namespace {

class MarginStage : public ShadowStage {
  public:
    MarginStage() : ShadowStage("margin") {}

  protected:
    ShadowMapSettings settings(const ParamSet& p) const override {
        ShadowMapSettings s = commonShadowSettings(p);
        s.storage = parseStorage(p.choice("storage"));
        return s;
    }
    void setLitUniforms(Program& lit, const ParamSet& p) const override {
        lit.set("marginKind", p.is("margin-kind", "slope") ? 1 : 0);
        lit.set("margin", static_cast<float>(p.number("margin")));
        lit.set("slopeK", static_cast<float>(p.number("slope-k")));
        lit.set("slopeMin", static_cast<float>(p.number("slope-min")));
        lit.set("slopeMax", static_cast<float>(p.number("slope-max")));
    }
};

}  // namespace

StageDefinition marginStage() {
    StageDefinition s;
    s.id = "margin";
    s.title = "The margin: constant or slope-scaled from N and L";
    s.lecture = "acne cured by a margin; too much of it detaches shadows";
    s.params = commonShadowParams("all");
    s.params.push_back(
        ParamSpec::choice("margin-kind", {"constant", "slope"},
                          "constant margin, or clamp(k * tan(acos(N.L)), min, max)"));
    s.params.push_back(ParamSpec::number("margin", 0.01, 0.0, 0.1, 0.001,
                                         "the constant margin (1/256 = 0.0039 for 8 bits)"));
    s.params.push_back(ParamSpec::number("slope-k", 0.004, 0.0, 0.1, 0.0005, "slope-scaled: k"));
    s.params.push_back(
        ParamSpec::number("slope-min", 0.002, 0.0, 0.1, 0.0005, "slope-scaled: smallest margin"));
    s.params.push_back(
        ParamSpec::number("slope-max", 0.03, 0.0, 0.2, 0.001, "slope-scaled: largest margin"));
    s.params.push_back(ParamSpec::choice("storage", {"rgb8", "depth16", "depth24", "depth32f"},
                                         "what the map stores depth in"));
    s.views = shadowViews();
    // The slope kind's margin grows with the angle between N and L: the value the shadow test
    // adds must depend on both (a constant margin passes the pictures of some views).
    s.sourceRules = {
        gamingRule(),
        SourceRule::comparisonDependsOn(
            "lit", "shadowMap",
            {{"the normal", {"normal", "gl_Normal", kScreenDerivative}},
             {"the light direction", {"lightPosition", "gl_LightSource"}}},
            "the slope-scaled margin (margin-kind=slope) must grow with the angle between the "
            "normal and the light direction")};
    s.benchSeries = {
        BenchSeries(BenchGroup::MapSize, "margin/constant"),
        BenchSeries(BenchGroup::MapSize, "margin/slope", {{"margin-kind", "slope"}}),
        BenchSeries(BenchGroup::Format, "margin/rgb8", {{"storage", "rgb8"}}),
        BenchSeries(BenchGroup::Format, "margin/depth16", {{"storage", "depth16"}}),
        BenchSeries(BenchGroup::Format, "margin/depth24", {{"storage", "depth24"}}),
        BenchSeries(BenchGroup::Format, "margin/depth32f", {{"storage", "depth32f"}}),
        BenchSeries(BenchGroup::EqualAccuracy, "margin/constant").ranked(1),  // after hardware
    };
    s.create = [] { return std::make_unique<MarginStage>(); };
    return s;
}

}  // namespace sl
