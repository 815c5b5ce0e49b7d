// Stage 7: a planar mirror. The slides' method renders the scene from the reflected camera
// (eye' behind the mirror, looking through it, an off-axis frustum whose near window is the
// mirror) into a texture, then draws the mirror in the main view with that texture on it. The
// exact method beside it draws the scene reflected about the mirror's plane straight into the
// image, masked to the mirror by the stencil buffer. Both reuse the hardware stage's shadow map,
// so shadows show in the reflection as well.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <sstream>

#include "gl/state.h"
#include "render/mirror_pass.h"
#include "render/scene_pass.h"
#include "render/shadow_map.h"
#include "scene/mesh.h"
#include "stages/shadow_stage.h"

namespace sl {

namespace {

using Clock = std::chrono::steady_clock;

// The back of the mirror: a dull dark grey, lit like any surface (as in the reference).
const glm::vec3 kBackColour(0.3f);

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

class MirrorStage : public Stage {
  public:
    // The lit pass, the map's when shadows are on, and the mirror's surface (drawn in every view
    // the mirror faces: the graded views are chosen to show it).
    std::vector<std::string> passes(const ParamSet& p) const override {
        std::vector<std::string> out = {"lit", "surface"};
        if (p.is("shadows", "on")) out.push_back("shadow");
        return out;
    }
    void render(FrameContext& f) override {
        notes_.clear();
        explanation_.clear();
        f.stats.mirrorMs = f.stats.litMs = 0;  // stay 0 for a pass that does not run
        mirrorPassRan_ = mainPassRan_ = false;
        renderShadowMap(f);
        if (!f.scene.mirror) {  // only when switched to in the window over a scene without one
            PassScope pass("lit");
            clearToBackground(f);
            drawLit(f, cameraViewer(f), false);
            f.stats.notes.push_back("this scene has no mirror: start with --scene mirror");
            return;
        }
        std::string reason;
        std::optional<Mirror> mirror = drawableMirror(*f.scene.mirror, &reason);
        MirrorCamera mc;
        if (mirror)
            mc = mirrorCamera(*mirror, f.camera.eye, sceneReachInFront(f.scene, *mirror));
        else
            mc.reason = reason;
        glm::ivec2 footprint =
            mirror ? mirrorFootprintPixels(*mirror, f.camera, f.width, f.height) : glm::ivec2(0);

        bool stencil = f.params.is("mirror-method", "stencil");
        if (stencil && stencilBits(f.target) == 0) {
            notes_.push_back("stencil: this framebuffer has no stencil bits; texture method used");
            stencil = false;
        }
        if (f.view == ViewMode::ShadowMap)
            showTexture(f, mc, footprint);
        else if (stencil)
            renderStencil(f, mirror, mc, footprint);
        else
            renderTexture(f, mirror, mc, footprint);

        if (!mc.valid) notes_.push_back("no reflection: " + mc.reason);
        describe(f, mirror, mc, stencil);
        for (auto& n : notes_) f.stats.notes.push_back(n);
    }

    std::string explain() const override { return explanation_; }

  private:
    // ---- lighting, shared by every view of the scene ----------------------------------------

    void renderShadowMap(FrameContext& f) {
        shadows_ = f.params.is("shadows", "on");
        if (!shadows_) return;
        // The hardware stage's map: depth compare, 2x2 PCF, glPolygonOffset(2, 4).
        ShadowMapSettings s;
        s.storage = MapStorage::Depth24;
        s.size = 512;
        s.castersOnly = true;
        s.compare = true;
        s.linear = true;
        s.offsetFactor = 2.0f;
        s.offsetUnits = 4.0f;
        map_.update(f, s, f.shaders.program("mirror", "shadow"));
    }

    // The scene, lit (and shadowed), seen by `viewer`. The lighting always happens in the real
    // world: `model` is never reflected, only `view` is, so worldPosition, the light and the
    // shadow map agree in every view; `viewer.eye` is the eye the highlights are seen from.
    // `cullSolids`: back faces of closed objects (boxes, spheres) are culled, which is where a
    // wrong winding would show; quads stay two-sided.
    void drawLit(FrameContext& f, const Viewer& viewer, bool cullSolids) {
        Program& lit = f.shaders.program("mirror", "lit");
        lit.use();
        lit.set("shadows", shadows_ ? 1 : 0);
        lit.set("shadowMap", 1);
        if (shadows_) map_.bind(1);
        ScopedCullFace cull(cullSolids ? GL_BACK : GL_NONE);
        drawSceneLit(lit, f, viewer, 0, [&](Program& p, std::size_t i, const glm::mat4& model) {
            if (shadows_) p.set("shadowMatrix", map_.shadowMatrix(model, 0.5f));
            if (cullSolids) {
                bool solid = f.scene.objects[i].kind != PrimitiveKind::Quad;
                solid ? glEnable(GL_CULL_FACE) : glDisable(GL_CULL_FACE);
            }
        });
        unbindShadowMap();
    }

    // The mirror seen from behind (or edge-on): an ordinary dark surface facing -normal.
    void drawBack(FrameContext& f, const Mirror& m) {
        Program& lit = f.shaders.program("mirror", "lit");
        lit.use();  // view, projection and lighting are still those of the main pass
        glm::mat4 model = mirrorModelMatrix(m);
        lit.set("model", model);
        lit.set("normalMatrix", -glm::mat3(glm::transpose(glm::inverse(model))));
        lit.set("objectColor", kBackColour);
        if (shadows_) {
            map_.bind(1);
            lit.set("shadowMatrix", map_.shadowMatrix(model, 0.5f));
        }
        f.gpu.bind();
        f.gpu.drawUnitQuad();
        glBindVertexArray(0);
        unbindShadowMap();
    }

    void unbindShadowMap() {
        glActiveTexture(GL_TEXTURE1);
        glBindTexture(GL_TEXTURE_2D, 0);
        glActiveTexture(GL_TEXTURE0);
    }

    // The mirror's quad with the surface program: the texture on it (useTexture) or a flat
    // colour (the stencil passes).
    void drawSurface(FrameContext& f, const Mirror& m, const Viewer& viewer, const glm::vec2 uv[4],
                     bool useTexture, const glm::vec4& colour, float reflectance) {
        Program& p = f.shaders.program("mirror", "surface");
        p.use();
        p.set("model", mirrorModelMatrix(m));
        p.set("view", viewer.view);
        p.set("projection", viewer.projection);
        glUniform2fv(p.location("cornerUv"), 4, &uv[0][0]);
        p.set("useTexture", useTexture ? 1 : 0);
        p.set("color", colour);
        p.set("reflectance", reflectance);
        p.set("mirrorTexture", 0);
        if (useTexture) {
            glActiveTexture(GL_TEXTURE0);
            glBindTexture(GL_TEXTURE_2D, target_.texture());
        }
        f.gpu.bind();
        f.gpu.drawUnitQuad();
        glBindVertexArray(0);
        glBindTexture(GL_TEXTURE_2D, 0);
    }

    // ---- the slides' method: render to texture -----------------------------------------------

    // The scene from the reflected camera into the texture. Its near plane is the mirror's
    // plane, so whatever lies behind the mirror is clipped away and never reaches the texture.
    void renderMirrorTexture(FrameContext& f, const MirrorCamera& mc, glm::ivec2 size) {
        PassScope pass("mirror");
        target_.ensure(size.x, size.y);
        ScopedFramebuffer bind(target_.framebuffer(), size.x, size.y);
        clearToBackground(f);
        // An ordinary camera (a rotation, no reflection): the usual winding is still right.
        drawLit(f, Viewer{mc.view, mc.projection, mc.eye}, true);
    }

    void renderTexture(FrameContext& f, const std::optional<Mirror>& mirror, const MirrorCamera& mc,
                       glm::ivec2 footprint) {
        // The mirror off screen or turned away: no texture at all, nothing is wasted on it.
        bool reflect = mc.valid && footprint.x > 0 && footprint.y > 0;
        if (reflect) {
            textureSize_ = mirrorTextureSize(f.params.integer("mirror-size"), footprint, maxSide());
            textureFromFootprint_ = f.params.integer("mirror-size") == 0;
            auto start = beginTiming(f);
            renderMirrorTexture(f, mc, textureSize_);
            endTiming(f, start, true);
        } else {
            textureSize_ = {0, 0};
        }
        PassScope pass("lit");
        auto start = beginTiming(f);
        clearToBackground(f);
        Viewer main = cameraViewer(f);
        drawLit(f, main, false);
        if (reflect)  // the texture on the mirror, at each corner's place in the reflected image
            drawSurface(f, *mirror, main, mc.cornerUv, true, glm::vec4(1.0f), kMirrorReflectance);
        else if (mirror && !mc.valid)  // seen from behind or edge-on: its dark back
            drawBack(f, *mirror);
        endTiming(f, start, false);
    }

    // ---- the exact method: reflect the scene, mask with the stencil buffer -------------------

    void renderStencil(FrameContext& f, const std::optional<Mirror>& mirror, const MirrorCamera& mc,
                       glm::ivec2 footprint) {
        textureSize_ = {0, 0};
        PassScope pass("lit");
        auto litStart = beginTiming(f);
        clearToBackground(f);
        glClearStencil(0);
        glClear(GL_STENCIL_BUFFER_BIT);
        Viewer main = cameraViewer(f);
        drawLit(f, main, false);
        if (mirror && !mc.valid) drawBack(f, *mirror);
        endTiming(f, litStart, false);
        if (!mc.valid || footprint.x == 0 || footprint.y == 0) return;  // nothing to reflect

        PassScope mirrorPass("mirror");
        auto start = beginTiming(f);
        const glm::vec2 noUv[4] = {};
        const Mirror& m = *mirror;
        {  // 1. stencil = 1 wherever the mirror is visible (objects in front of it hide it)
            ScopedStencil mark(GL_ALWAYS, 1, GL_KEEP, GL_KEEP, GL_REPLACE);
            ScopedColorMask noColour(false);
            ScopedDepthMask noDepth(false);
            drawSurface(f, m, main, noUv, false, glm::vec4(0.0f), 1.0f);
        }
        ScopedStencil inside(GL_EQUAL, 1, GL_KEEP, GL_KEEP, GL_KEEP);  // from here on: only there
        {  // 2. inside the mirror: background colour and the far depth, as a fresh image
            ScopedDepthFunc always(GL_ALWAYS);
            ScopedDepthRange far(1.0, 1.0);
            drawSurface(f, m, main, noUv, false, glm::vec4(f.scene.background, 1.0f), 1.0f);
        }
        {  // 3. the scene reflected about the mirror's plane, seen from the real eye
            glm::mat4 reflect = reflectionMatrix(m.center, m.normal);
            glm::mat4 view = main.view * reflect;
            // Reflected geometry in front of the mirror came from behind it: an oblique near
            // plane on the mirror's plane clips it, as the texture camera's near plane does.
            glm::mat4 projection =
                obliqueNearPlane(main.projection, mirrorPlaneInView(m, main.view));
            ScopedFrontFace mirrored(GL_CW);  // det(reflect) = -1 turns the winding around
            drawLit(f, Viewer{view, projection, mc.eye}, true);
        }
        {  // 4. the mirror returns 90%: multiply, and put the mirror's own depth back
            ScopedDepthFunc always(GL_ALWAYS);
            ScopedBlend multiply(GL_ZERO, GL_SRC_COLOR);
            drawSurface(f, m, main, noUv, false, glm::vec4(glm::vec3(kMirrorReflectance), 1.0f),
                        1.0f);
        }
        endTiming(f, start, true);
    }

    // ---- the debug view: the render-to-texture target itself ---------------------------------

    void showTexture(FrameContext& f, const MirrorCamera& mc, glm::ivec2 footprint) {
        PassScope pass("show-texture");
        textureSize_ = {0, 0};
        if (mc.valid) {
            int requested = f.params.integer("mirror-size");
            textureFromFootprint_ = requested == 0 && footprint.x > 0 && footprint.y > 0;
            // Off screen the footprint is empty; show a 512 square so there is something to see.
            textureSize_ = mirrorTextureSize(
                requested == 0 && !textureFromFootprint_ ? 512 : requested, footprint, maxSide());
            auto start = beginTiming(f);
            renderMirrorTexture(f, mc, textureSize_);
            endTiming(f, start, true);
        }
        clearToBackground(f);
        if (!mc.valid) return;
        // The whole texture, as large as fits with its own aspect. It is what the reflected
        // camera saw: left and right are the other way round from the mirror in the main view.
        ScopedEnable noDepth(GL_DEPTH_TEST, false);
        float aspect = float(textureSize_.x) / float(textureSize_.y);
        float screen = float(f.width) / float(f.height);
        glm::vec3 scale = aspect > screen ? glm::vec3(2.0f, 2.0f * screen / aspect, 1.0f)
                                          : glm::vec3(2.0f * aspect / screen, 2.0f, 1.0f);
        Mirror full;  // the unit quad scaled to the letterbox; identity view and projection
        full.width = scale.x;
        full.height = scale.y;
        const glm::vec2 uv[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        drawSurface(f, full, Viewer{}, uv, true, glm::vec4(1.0f), 1.0f);
    }

    // ---- timing, notes, explanation ------------------------------------------------------------

    static Clock::time_point beginTiming(const FrameContext& f) {
        if (f.timePasses) glFinish();  // what came before is not this pass's time
        return Clock::now();
    }
    // Records that the mirror pass (or the main pass) ran and, when timing, how long it took.
    void endTiming(FrameContext& f, Clock::time_point start, bool mirrorPass) {
        (mirrorPass ? mirrorPassRan_ : mainPassRan_) = true;
        if (!f.timePasses) return;
        glFinish();
        (mirrorPass ? f.stats.mirrorMs : f.stats.litMs) = msSince(start);
    }

    static int maxSide() {
        GLint t = 0, r = 0;
        glGetIntegerv(GL_MAX_TEXTURE_SIZE, &t);
        glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &r);
        return std::min({t, r, 4096});
    }

    void describe(FrameContext& f, const std::optional<Mirror>& mirror, const MirrorCamera& mc,
                  bool stencil) {
        char line[256];
        if (stencil && f.view != ViewMode::ShadowMap) {
            std::snprintf(line, sizeof line,
                          "method stencil: scene reflected about the mirror plane, stencil mask, "
                          "oblique near plane");
        } else if (textureSize_.x > 0) {
            std::snprintf(
                line, sizeof line, "method texture: mirror texture %dx%d (%s, %.2f MiB)",
                textureSize_.x, textureSize_.y,
                textureFromFootprint_ ? "the mirror's footprint on screen" : "mirror-size",
                target_.bytes() / 1048576.0);
        } else {
            std::snprintf(line, sizeof line, "method texture: no texture rendered this frame");
        }
        notes_.insert(notes_.begin(), line);
        if (f.view == ViewMode::ShadowMap)
            notes_.push_back(
                "view mirror-texture (--view shadow-map): the mirror texture itself, left-right "
                "flipped");
        if (f.timePasses && mirrorPassRan_) {
            std::snprintf(line, sizeof line, "mirror pass %.2f ms", f.stats.mirrorMs);
            notes_.push_back(line);
        }
        if (f.timePasses && mainPassRan_) {
            std::snprintf(line, sizeof line, "main pass %.2f ms", f.stats.litMs);
            notes_.push_back(line);
        }
        if (!shadows_) notes_.push_back("shadows off");

        std::ostringstream e;
        auto vec = [&](const glm::vec3& v) {
            e << "(" << v.x << ", " << v.y << ", " << v.z << ")";
        };
        auto mat = [&](const char* name, const glm::mat4& m) {
            e << name << " =\n";
            for (int r = 0; r < 4; ++r) {
                e << "  [";
                for (int c = 0; c < 4; ++c) e << (c ? " " : "") << std::to_string(m[c][r]);
                e << " ]\n";
            }
        };
        e << "eye ";
        vec(f.camera.eye);
        e << "\n";
        if (!mc.valid) {
            e << "no reflected camera: " << mc.reason << "\n";
            explanation_ = e.str();
            return;
        }
        e << "eye' (eye reflected through the mirror plane) ";
        vec(mc.eye);
        e << "\nat' = eye' + n ";
        vec(mc.at);
        e << "\nup = the mirror's up ";
        vec(mc.up);
        e << "\noff-axis frustum: left' " << mc.left << " right' " << mc.right << " bottom' "
          << mc.bottom << " top' " << mc.top << " near' " << mc.zNear << " far' " << mc.zFar
          << "\n";
        e << "corner texture coordinates (bottom-left, bottom-right, top-right, top-left):";
        for (const glm::vec2& uv : mc.cornerUv) e << " (" << uv.x << ", " << uv.y << ")";
        e << "\n";
        mat("V' = lookAt(eye', at', up)", mc.view);
        mat("P' = frustum(left', right', bottom', top', near', far')", mc.projection);
        if (stencil && mirror) {
            Viewer main = cameraViewer(f);
            mat("R (reflection about the mirror plane)",
                reflectionMatrix(mirror->center, mirror->normal));
            mat("P with the oblique near plane",
                obliqueNearPlane(main.projection, mirrorPlaneInView(*mirror, main.view)));
        }
        explanation_ = e.str();
    }

    ShadowMap map_;
    bool shadows_ = true;
    MirrorTarget target_;
    glm::ivec2 textureSize_{0};
    bool textureFromFootprint_ = true;
    bool mirrorPassRan_ = false, mainPassRan_ = false;
    std::vector<std::string> notes_;
    std::string explanation_;
};

}  // namespace

StageDefinition mirrorStage() {
    StageDefinition s;
    s.id = "mirror";
    s.title = "A planar mirror: the reflected camera rendered into a texture";
    s.lecture = "eye' behind the mirror, at' - eye' perpendicular to it, an off-axis frustum";
    s.params = {
        ParamSpec::choice("mirror-method", {"texture", "stencil"},
                          "texture: the slides' reflected camera rendered to a texture; stencil: "
                          "the scene reflected about the plane, masked by the stencil buffer"),
        ParamSpec::integer("mirror-size", 0, 0, 4096, 64,
                           "mirror texture side in texels; 0 = the mirror's footprint on screen "
                           "(else 16 to 4096, square)"),
        ParamSpec::choice("shadows", {"on", "off"},
                          "the hardware stage's shadow map, in the main view and the reflection"),
    };
    s.defaultScene = "mirror";
    s.needsMirror = true;
    // shadow-map here means the render-to-texture target: the mirror texture, full screen.
    s.views = {ViewMode::Final, ViewMode::ShadowMap};
    s.sourceRules = {gamingRule()};
    // Both methods, and the texture method at fixed sizes against its footprint-sized default.
    // Issue 6's speed target: the texture method at most 2.2x phong on the mirror scene.
    BenchTarget texture{"mirror (texture, footprint-sized): ",
                        0,
                        {{false, 2.2, "{ratio}x phong on the mirror scene"}}};
    s.benchSeries = {
        BenchSeries(BenchGroup::Mirror, "mirror/texture").withTarget(texture),
        BenchSeries(BenchGroup::Mirror, "mirror/stencil", {{"mirror-method", "stencil"}}),
        BenchSeries(BenchGroup::Mirror, "mirror/texture-128", {{"mirror-size", "128"}})
            .fullRunOnly(),
        BenchSeries(BenchGroup::Mirror, "mirror/texture-256", {{"mirror-size", "256"}}),
        BenchSeries(BenchGroup::Mirror, "mirror/texture-512", {{"mirror-size", "512"}})
            .fullRunOnly(),
        BenchSeries(BenchGroup::Mirror, "mirror/texture-1024", {{"mirror-size", "1024"}})
            .fullRunOnly(),
    };
    s.create = [] { return std::make_unique<MirrorStage>(); };
    return s;
}

}  // namespace sl
