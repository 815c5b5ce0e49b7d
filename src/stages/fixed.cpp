// Stage 6: the fixed-function way (compatibility profile only, no shaders): depth rendered from
// the light, copied into a depth texture with glCopyTexImage2D, eye-linear texture generation
// with the texture matrix bias * P_light * V_light, GL_COMPARE_R_TO_TEXTURE, and two passes:
// a dim ambient pass, then the lit pass whose shadowed fragments the alpha test discards.
#include <algorithm>
#include <chrono>
#include <glm/gtc/type_ptr.hpp>
#include <stdexcept>

#include "gl/state.h"
#include "render/scene_pass.h"
#include "scene/mesh.h"
#include "stages/shadow_stage.h"

namespace sl {

namespace {

// OpenGL ES (the browser edition) has no fixed function: there the stage is listed, with its
// declarations, but never drawn (gl/gl_es3.h; docs/web.md).
#ifndef SHADOWLAB_GL_ES
double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

class FixedStage : public Stage {
  public:
    void render(FrameContext& f) override {
        int size = f.params.integer("map-size");
        float factor = static_cast<float>(f.params.number("offset-factor"));
        float units = static_cast<float>(f.params.number("offset-units"));
        auto start = std::chrono::steady_clock::now();
        unsigned before = f.stats.shadowMapRenders;
        updateMap(f, size, factor, units);
        f.stats.mapSize = size;
        f.stats.lightViewProjection = lightViewProjection_;
        if (f.timePasses && f.stats.shadowMapRenders != before) {
            glFinish();
            f.stats.shadowMs = msSince(start);
        }
        start = std::chrono::steady_clock::now();
        PassScope pass("lit");
        clearToBackground(f);
        useNoProgram();
        glm::mat4 view = viewMatrix(f);
        glMatrixMode(GL_PROJECTION);
        glLoadMatrixf(glm::value_ptr(cameraViewer(f).projection));
        glMatrixMode(GL_MODELVIEW);
        glLoadMatrixf(glm::value_ptr(view));
        glm::vec4 lightPos(f.lightPosition, 1.0f);
        glLightfv(GL_LIGHT0, GL_POSITION, glm::value_ptr(lightPos));  // transformed by V_camera
        const float zero[4] = {0, 0, 0, 1};
        glLightModelfv(GL_LIGHT_MODEL_AMBIENT, zero);
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        glEnable(GL_NORMALIZE);  // the model matrices scale the unit primitives
        glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
        glEnable(GL_COLOR_MATERIAL);
        const Material& m = f.scene.material;
        // Pass 1: ambient only, everywhere.
        float ambient[4] = {m.ambient, m.ambient, m.ambient, 1};
        glLightfv(GL_LIGHT0, GL_AMBIENT, ambient);
        glLightfv(GL_LIGHT0, GL_DIFFUSE, zero);
        glLightfv(GL_LIGHT0, GL_SPECULAR, zero);
        drawObjects(f, view);
        // Pass 2: diffuse and specular, added only where the depth compare says "lit".
        float diffuse[4] = {m.diffuse, m.diffuse, m.diffuse, 1};
        float specular[4] = {m.specular, m.specular, m.specular, 1};
        glLightfv(GL_LIGHT0, GL_AMBIENT, zero);
        glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
        glLightfv(GL_LIGHT0, GL_SPECULAR, specular);
        glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
        glMaterialf(GL_FRONT, GL_SHININESS, std::min(m.shininess, 128.0f));
        enableShadowTexgen(view);
        glEnable(GL_ALPHA_TEST);
        glAlphaFunc(GL_GREATER, 0.5f);  // the compare result lands in alpha
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ONE);
        glDepthFunc(GL_LEQUAL);
        glDepthMask(GL_FALSE);
        drawObjects(f, view);
        // Put everything back: the next pass may be a shader pass.
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_LESS);
        glDisable(GL_BLEND);
        glDisable(GL_ALPHA_TEST);
        for (GLenum c : {GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q})
            glDisable(c);
        glDisable(GL_TEXTURE_2D);
        glBindTexture(GL_TEXTURE_2D, 0);
        glDisable(GL_COLOR_MATERIAL);
        glDisable(GL_NORMALIZE);
        glDisable(GL_LIGHT0);
        glDisable(GL_LIGHTING);
        glBindVertexArray(0);
        if (f.timePasses) {
            glFinish();
            f.stats.litMs = msSince(start);
        }
    }

  private:
    static glm::mat4 viewMatrix(const FrameContext& f) { return cameraViewer(f).view; }

    void drawObjects(FrameContext& f, const glm::mat4& view) {
        f.gpu.bindFixedFunction();
        for (std::size_t i = 0; i < f.scene.objects.size(); ++i) {
            glLoadMatrixf(glm::value_ptr(view * modelMatrix(f.scene.objects[i])));
            glColor3fv(glm::value_ptr(f.scene.objects[i].color));
            f.gpu.drawObject(i);
        }
        glLoadMatrixf(glm::value_ptr(view));
    }

    // Eye-linear planes are given while the modelview holds V_camera: GL multiplies them by its
    // inverse, so the generated (s, t, r, q) = bias * P_light * V_light * world position.
    void enableShadowTexgen(const glm::mat4& view) {
        glm::mat4 t = glm::transpose(biasMatrix(0.5f) * lightViewProjection_);  // rows as columns
        glLoadMatrixf(glm::value_ptr(view));
        const GLenum coords[] = {GL_S, GL_T, GL_R, GL_Q};
        const GLenum enables[] = {GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R,
                                  GL_TEXTURE_GEN_Q};
        for (int k = 0; k < 4; ++k) {
            glTexGeni(coords[k], GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
            glTexGenfv(coords[k], GL_EYE_PLANE, glm::value_ptr(t[k]));
            glEnable(enables[k]);
        }
        glActiveTexture(GL_TEXTURE0);
        glEnable(GL_TEXTURE_2D);
        glBindTexture(GL_TEXTURE_2D, depth_.id());
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    }

    void updateMap(FrameContext& f, int size, float factor, float units) {
        bool stale = size != size_ || f.lightPosition != light_ || f.sceneGeneration != scene_ ||
                     f.allLit != allLit_ || factor != factor_ || units != units_;
        if (!stale) return;
        PassScope pass("shadow");
        GLint maxSize = 0;
        glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
        if (size > maxSize)
            throw std::invalid_argument("map-size " + std::to_string(size) +
                                        " exceeds GL_MAX_TEXTURE_SIZE " + std::to_string(maxSize));
        if (size != size_) {  // a depth buffer of the map's size to render into and copy from
            fbo_ = Framebuffer::create();
            depthBuffer_ = Renderbuffer::create();
            glBindRenderbuffer(GL_RENDERBUFFER, depthBuffer_.id());
            glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size, size);
            ScopedFramebuffer bind(fbo_.id(), size, size);
            glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                      depthBuffer_.id());
            glDrawBuffer(GL_NONE);
            glReadBuffer(GL_NONE);
            std::string incomplete = checkFramebufferComplete("fixed-function depth framebuffer");
            if (!incomplete.empty()) throw std::runtime_error(incomplete);
            depth_ = Texture::create();
        }
        std::vector<Aabb> casters;
        for (const Object& o : f.scene.objects)
            if (o.castsShadow) {  // the floor need not be drawn into the map
                glm::vec3 half =
                    o.kind == PrimitiveKind::Sphere ? glm::vec3(o.radius) : 0.5f * o.size;
                casters.push_back({o.center - half, o.center + half});
            }
        LightFrustum lf =
            fitLightFrustum(f.lightPosition, f.scene.light.target, casters, LightFit::Tight);
        lightViewProjection_ = lf.projection * lf.view;
        {
            ScopedFramebuffer bind(fbo_.id(), size, size);
            ScopedPolygonOffset offset(factor, units);
            glClear(GL_DEPTH_BUFFER_BIT);
            useNoProgram();
            glMatrixMode(GL_PROJECTION);
            glLoadMatrixf(glm::value_ptr(lf.projection));
            glMatrixMode(GL_MODELVIEW);
            if (!f.allLit) {
                f.gpu.bindFixedFunction();
                for (std::size_t i = 0; i < f.scene.objects.size(); ++i) {
                    if (!f.scene.objects[i].castsShadow) continue;
                    glLoadMatrixf(glm::value_ptr(lf.view * modelMatrix(f.scene.objects[i])));
                    f.gpu.drawObject(i);
                }
                glBindVertexArray(0);
            }
            // The lecture's copy: depth buffer -> depth texture.
            glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.id());
            glBindTexture(GL_TEXTURE_2D, depth_.id());
            glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 0, 0, size, size, 0);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
            glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_ALPHA);
            glBindTexture(GL_TEXTURE_2D, 0);
        }
        ++f.stats.shadowMapRenders;
        size_ = size;
        light_ = f.lightPosition;
        scene_ = f.sceneGeneration;
        allLit_ = f.allLit;
        factor_ = factor;
        units_ = units;
        note_ = lf.note;
    }

    Framebuffer fbo_;
    Renderbuffer depthBuffer_;
    Texture depth_;
    glm::mat4 lightViewProjection_{1};
    int size_ = 0;
    glm::vec3 light_{NAN};
    unsigned scene_ = ~0u;
    bool allLit_ = false;
    float factor_ = -1, units_ = -1;
    std::string note_;
};
#endif

}  // namespace

StageDefinition fixedStage() {
    StageDefinition s;
    s.id = "fixed";
    s.title = "The fixed-function way: copy, texgen, GL_COMPARE_R_TO_TEXTURE";
    s.lecture = "the SuperBible chapter: glCopyTexImage2D, eye-linear texgen, alpha test";
    s.params = {
        ParamSpec::integer("map-size", 512, 16, 8192, 1.0, "shadow map width and height in texels",
                           true),
        ParamSpec::number("offset-factor", 2.0, 0.0, 40.0, 1.0, "glPolygonOffset factor"),
        ParamSpec::number("offset-units", 4.0, 0.0, 100.0, 1.0, "glPolygonOffset units"),
    };
    s.legacyOnly = true;
    s.unshadowedIsOwn = true;  // its Gouraud lighting is its own: judged against its all-lit render
    s.views = {ViewMode::Final};
    s.benchSeries = {BenchSeries(BenchGroup::MapSize, "fixed")};  // legacy tree: legacyOnly
#ifndef SHADOWLAB_GL_ES
    s.create = [] { return std::make_unique<FixedStage>(); };
#else
    s.create = []() -> std::unique_ptr<Stage> {
        throw std::runtime_error(
            "stage 'fixed' needs desktop OpenGL's fixed function, which "
            "WebGL lacks: run the native program (shadowlab window --stage fixed)");
    };
#endif
    return s;
}

}  // namespace sl
