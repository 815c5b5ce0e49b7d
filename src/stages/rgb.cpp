// Stage 1: render-to-texture. gl_FragCoord.z written into an 8-bit RGB colour texture and
// compared with no margin: the acne of the slides.
#include "stages/shadow_stage.h"

namespace sl {

namespace {

class RgbStage : public ShadowStage {
  public:
    RgbStage() : ShadowStage("rgb") {}

  protected:
    ShadowMapSettings settings(const ParamSet& p) const override {
        ShadowMapSettings s = commonShadowSettings(p);
        s.storage = MapStorage::Rgb8;
        return s;
    }
    void setShadowUniforms(Program& shadow, const ParamSet& p) const override {
        shadow.set("packedDepth", p.is("encoding", "packed") ? 1 : 0);
    }
    void setLitUniforms(Program& lit, const ParamSet& p) const override {
        lit.set("packedDepth", p.is("encoding", "packed") ? 1 : 0);
        lit.set("margin", static_cast<float>(p.number("margin")));
    }
    int mapEncoding(const ParamSet& p) const override { return p.is("encoding", "packed") ? 2 : 1; }
};

}  // namespace

StageDefinition rgbStage() {
    StageDefinition s;
    s.id = "rgb";
    s.title = "Depth as colour: gl_FragCoord.z in an RGB8 texture";
    s.lecture = "render-to-texture; compare with no margin: shadow acne";
    s.params = commonShadowParams("all");
    s.params.push_back(ParamSpec::choice(
        "encoding", {"single", "packed"},
        "single: one 8-bit value (256 depth planes, the slides); packed: 24 bits over r, g, b"));
    s.params.push_back(ParamSpec::number("margin", 0.0, 0.0, 0.1, 0.001,
                                         "added to the stored depth before comparing"));
    s.views = shadowViews();
    s.sourceRules = {gamingRule()};
    s.benchSeries = {
        BenchSeries(BenchGroup::MapSize, "rgb"),
        BenchSeries(BenchGroup::Format, "rgb/packed", {{"encoding", "packed"}}),
    };
    s.create = [] { return std::make_unique<RgbStage>(); };
    return s;
}

}  // namespace sl
