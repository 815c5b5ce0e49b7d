// Stage 8 (after the lecture): what a student would otherwise copy from the tutorials, written
// from their published descriptions on our shadow-map machinery, so `check` and `bench` put
// them on the same scale as ours.
//   learnopengl:     LearnOpenGL "Shadow Mapping": a sampler2D depth map of the whole scene
//                    drawn every frame, 3x3 manual PCF, bias max(0.05 (1 - N.L), 0.005),
//                    receivers beyond the light's far plane lit.
//   opengl-tutorial: opengl-tutorial.org "Tutorial 16": sampler2DShadow (GL_LINEAR), four
//                    Poisson-disk taps, bias 0.005 tan(acos(N.L)) clamped to [0, 0.01], the
//                    map drawn every frame.
//   normal-offset:   the lookup point pushed along the normal by a texel-sized amount that
//                    grows as N.L falls (the modern form of the slides' "margin from N and L").
#include "stages/shadow_stage.h"

namespace sl {

namespace {

class PeersStage : public ShadowStage {
  public:
    PeersStage() : ShadowStage("peers") {}

  protected:
    ShadowMapSettings settings(const ParamSet& p) const override {
        ShadowMapSettings s = commonShadowSettings(p);
        bool learnOpenGl = p.is("method", "learnopengl");
        s.compare = !learnOpenGl;  // LearnOpenGL compares by hand in the shader
        s.linear = !learnOpenGl;   // the other two sample with GL_LINEAR (hardware 2x2 PCF)
        s.everyFrame = !p.is("method", "normal-offset");
        return s;
    }
    std::string litPass(const ParamSet& p) const override {
        if (p.is("method", "learnopengl")) return "lit_learnopengl";
        if (p.is("method", "opengl-tutorial")) return "lit_opengl_tutorial";
        return "lit_normal_offset";
    }
    void setLitUniforms(Program& lit, const ParamSet& p) const override {
        lit.set("texelSize", 1.0f / static_cast<float>(settings_.size));
        // A perspective light's texel spans (2 / (P[1][1] size)) world units per unit of depth
        // in front of the light; the clip w of a point is that depth.
        float projectionY = map_.frustum().projection[1][1];
        lit.set("texelPerDepth", 2.0f / (projectionY * static_cast<float>(settings_.size)));
        lit.set("normalOffset", static_cast<float>(p.number("normal-offset")));
        lit.set("minOffset", static_cast<float>(p.number("min-offset")));
    }
};

}  // namespace

StageDefinition peersStage() {
    StageDefinition s;
    s.id = "peers";
    s.title = "The tutorials' methods: LearnOpenGL, opengl-tutorial, normal offset";
    s.lecture = "after the lecture: what the popular tutorials do, on the same scale as ours";
    s.params = commonShadowParams("all");
    s.params.insert(
        s.params.begin(),
        ParamSpec::choice("method", {"learnopengl", "opengl-tutorial", "normal-offset"},
                          "learnopengl: sampler2D, 3x3 PCF, bias max(0.05(1-N.L), 0.005); "
                          "opengl-tutorial: sampler2DShadow, 4 Poisson taps, bias "
                          "0.005 tan(acos(N.L)) in [0, 0.01]; normal-offset: lookup pushed "
                          "along N by texels * (1 - N.L)"));
    s.params.push_back(ParamSpec::number("normal-offset", 1.0, 0.0, 10.0, 0.25,
                                         "normal-offset: texels along N added as N.L falls to 0"));
    s.params.push_back(ParamSpec::number("min-offset", 0.5, 0.0, 10.0, 0.25,
                                         "normal-offset: texels along N where N.L = 1"));
    s.views = shadowViews();
    s.sourceRules = {gamingRule()};
    // The tutorials' methods on the same axes as ours, ranked after every series of ours.
    s.benchSeries = {
        BenchSeries(BenchGroup::MapSize, "peers/learnopengl", {{"method", "learnopengl"}})
            .ranked(1),
        BenchSeries(BenchGroup::MapSize, "peers/opengl-tutorial", {{"method", "opengl-tutorial"}})
            .ranked(1),
        BenchSeries(BenchGroup::MapSize, "peers/normal-offset", {{"method", "normal-offset"}})
            .ranked(1),
        BenchSeries(BenchGroup::EqualAccuracy, "peers/learnopengl", {{"method", "learnopengl"}})
            .ranked(3),
        BenchSeries(BenchGroup::EqualAccuracy, "peers/opengl-tutorial",
                    {{"method", "opengl-tutorial"}})
            .ranked(3),
        BenchSeries(BenchGroup::EqualAccuracy, "peers/normal-offset", {{"method", "normal-offset"}})
            .ranked(3),
    };
    s.create = [] { return std::make_unique<PeersStage>(); };
    return s;
}

}  // namespace sl
