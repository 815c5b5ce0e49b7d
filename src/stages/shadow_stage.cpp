#include "stages/shadow_stage.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <sstream>

#include "gl/state.h"
#include "render/scene_pass.h"

namespace sl {

std::vector<ParamSpec> commonShadowParams(const std::string& castersDefault) {
    std::vector<std::string> casters = {"all", "casters-only"};
    if (castersDefault == "casters-only") std::swap(casters[0], casters[1]);
    return {
        ParamSpec::integer("map-size", 512, 16, 8192, 1.0, "shadow map width and height in texels",
                           true),
        ParamSpec::choice(
            "light-fit", {"tight", "sphere", "fixed"},
            "light frustum: tight box fit, the casters' bounding sphere, or the lab's "
            "frustum(-1,1,-1,1,1,100)"),
        ParamSpec::choice("casters", casters,
                          "what goes into the map: every object, or only shadow casters"),
        ParamSpec::number("far-near", 0, 0, 100000, 1.0,
                          "light far/near ratio: 0 = as the fit chose; else near = far / this "
                          "(depth precision)",
                          true),
    };
}

ShadowMapSettings commonShadowSettings(const ParamSet& p) {
    ShadowMapSettings s;
    s.size = p.integer("map-size");
    const std::string& fit = p.choice("light-fit");
    s.fit = fit == "sphere" ? LightFit::Sphere : fit == "fixed" ? LightFit::Fixed : LightFit::Tight;
    s.castersOnly = p.is("casters", "casters-only");
    s.farOverNear = static_cast<float>(p.number("far-near"));
    return s;
}

std::vector<ViewMode> shadowViews() {
    return {ViewMode::Final, ViewMode::ShadowMap, ViewMode::Light, ViewMode::Visibility,
            ViewMode::LightDepth};
}

SourceRule gamingRule() {
    return SourceRule::constantComparison(
        {{"the camera position", {"eyePosition"}},
         {"the view matrix", {"view"}},
         {"the light position", {"lightPosition"}},
         {"the pixel's place on screen", {"gl_FragCoord"}}},
        "a shader may recognise the graded camera, light or image size this way (a note for "
        "the instructor, not a score)");
}

void ShadowStage::render(FrameContext& f) {
    settings_ = settings(f.params);
    Program& shadow = f.shaders.program(id_, "shadow");
    shadow.use();
    setShadowUniforms(shadow, f.params);
    map_.update(f, settings_, shadow);

    PassScope pass("lit");
    auto start = std::chrono::steady_clock::now();
    clearToBackground(f);
    if (f.view == ViewMode::ShadowMap) {
        showMap(f);
    } else if (f.view == ViewMode::Light) {  // the scene as the light sees it
        const LightFrustum& lf = map_.frustum();
        // Square and centred, as the map is: the light's frustum is as wide as it is high (a
        // full 16:9 viewport drew the sphere as an ellipse).
        int side = std::min(f.width, f.height);
        glViewport((f.width - side) / 2, (f.height - side) / 2, side, side);
        drawSceneLit(f.shaders.program("phong", "lit"), f,
                     Viewer{lf.view, lf.projection, f.lightPosition}, 0);
        glViewport(0, 0, f.width, f.height);
    } else {
        Program& lit = f.shaders.program(id_, litPass(f.params));
        lit.use();
        map_.bind(0);
        lit.set("shadowMap", 0);
        lit.set("lightViewProjection", map_.lightViewProjection());
        setLitUniforms(lit, f.params);
        float biasZ = this->biasZ(f.params);
        int debugView = f.view == ViewMode::Visibility ? 1 : f.view == ViewMode::LightDepth ? 2 : 0;
        drawSceneLit(lit, f, cameraViewer(f), debugView,
                     [&](Program& p, std::size_t, const glm::mat4& model) {
                         p.set("shadowMatrix", map_.shadowMatrix(model, biasZ));
                     });
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    if (f.timePasses) {
        glFinish();
        f.stats.litMs =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
    }
    describe(f);
}

void ShadowStage::showMap(FrameContext& f) {
    Program& p = f.shaders.program("common", "show_map");
    ScopedEnable noDepth(GL_DEPTH_TEST, false);
    p.use();
    map_.bindPlain(0);
    p.set("shadowMap", 0);
    p.set("encoding", mapEncoding(f.params));
    p.set("lightNear", map_.frustum().zNear);
    p.set("lightFar", map_.frustum().zFar);
    // Keep the map square and centred.
    int side = std::min(f.width, f.height);
    glViewport((f.width - side) / 2, (f.height - side) / 2, side, side);
    f.gpu.bind();
    f.gpu.drawUnitQuad();
    glBindVertexArray(0);
    glViewport(0, 0, f.width, f.height);
    glBindSampler(0, 0);
}

void ShadowStage::describe(FrameContext& f) {
    const LightFrustum& lf = map_.frustum();
    static const char* storage[] = {"rgb8", "depth16", "depth24", "depth32f"};
    char line[256];
    std::snprintf(line, sizeof line, "map %dx%d %s (%.1f MiB), rendered %u %s%s", settings_.size,
                  settings_.size, storage[static_cast<int>(settings_.storage)],
                  map_.bytes() / 1048576.0, f.stats.shadowMapRenders,
                  f.stats.shadowMapRenders == 1 ? "time" : "times",
                  map_.addedColourAttachment() ? ", R32F colour added for completeness" : "");
    f.stats.notes.push_back(line);
    std::snprintf(line, sizeof line, "light fit %s: near %.3f far %.3f fovy %.1f (far/near %.1f)",
                  lightFitName(lf.used), lf.zNear, lf.zFar, lf.fovyDegrees, farOverNear(lf));
    f.stats.notes.push_back(line);
    if (settings_.castersOnly) {
        std::size_t drawn = 0, all = 0;
        for (std::size_t i = 0; i < f.scene.objects.size(); ++i) {
            std::size_t tris = f.gpu.mesh().objects[i].indexCount / 3;
            all += tris;
            if (f.scene.objects[i].castsShadow) drawn += tris;
        }
        std::snprintf(line, sizeof line, "casters only: %zu of %zu triangles drawn into the map",
                      drawn, all);
        f.stats.notes.push_back(line);
    }
    explainedBiasZ_ = biasZ(f.params);
}

std::string ShadowStage::explain() const {
    const LightFrustum& lf = map_.frustum();
    std::ostringstream e;
    auto mat = [&](const char* name, const glm::mat4& m) {
        e << name << " =\n";
        for (int r = 0; r < 4; ++r) {
            e << "  [";
            for (int c = 0; c < 4; ++c) e << (c ? " " : "") << std::to_string(m[c][r]);
            e << " ]\n";
        }
    };
    e << lf.note << "\n";
    mat("V_light (lookAt)", lf.view);
    mat("P_light", lf.projection);
    e << "depth range "
      << (!settings_.depthFlipped ? "(0, 1)"
          : kDepthRangeFlips
              ? "(1, 0), projection flipped: near -> NDC z +1"
              : "(1, 0)'s map, projection flipped: near -> NDC z +1 (WebGL refuses (1, 0): "
                "the map is drawn with the standard projection and (0, 1), the same depths)")
      << "\n";
    mat("bias (scale/bias)", biasMatrix(explainedBiasZ_));
    mat("bias * P_light * V_light", biasMatrix(explainedBiasZ_) * map_.lightViewProjection());
    return e.str();
}

}  // namespace sl
