// The shadow map: the scene's depth seen from the light, rendered into a texture through a
// framebuffer object, and re-rendered only when the light, the objects or the settings change.
#pragma once

#include "math/shadow_math.h"
#include "render/stage_interface.h"

namespace sl {

// How the map stores depth. Rgb8 is the slides' first attempt: gl_FragCoord.z written as colour.
enum class MapStorage { Rgb8, Depth16, Depth24, Depth32F };
MapStorage parseStorage(
    const std::string& text);  // "rgb8" | "depth16" | "depth24" | "depth32f" | "16" ...

struct ShadowMapSettings {
    MapStorage storage = MapStorage::Depth24;
    int size = 512;
    LightFit fit = LightFit::Tight;
    bool castersOnly = false;
    float farOverNear = 0;  // > 1: the light's near plane forced to far / this (precision sweep)
    float offsetFactor = 0, offsetUnits = 0;  // glPolygonOffset in the shadow pass
    bool cullFront = false;                   // draw only back faces of casters into the map
    // Skip the back faces of closed casters (boxes, spheres; quads stay two-sided): the depth test
    // keeps the faces nearest the light anyway, so the map is the same for half the fragments.
    bool cullBack = false;
    bool depthFlipped = false;  // projection maps near to NDC +1, with glDepthRange(1, 0)
    bool compare = false;       // GL_COMPARE_REF_TO_TEXTURE (sampler2DShadow)
    bool linear = false;        // GL_LINEAR: with compare, 2x2 percentage-closer filtering
    bool everyFrame = false;    // re-render even when nothing changed (as the tutorials' loops do)
    bool operator==(const ShadowMapSettings& o) const;
    bool operator!=(const ShadowMapSettings& o) const { return !(*this == o); }
};

class ShadowMap {
  public:
    // Renders the map with `program` (its pass named "shadow") if anything it depends on changed.
    void update(FrameContext& f, const ShadowMapSettings& s, Program& program);

    const LightFrustum& frustum() const { return frustum_; }
    // P_light * V_light (P flipped when depthFlipped).
    glm::mat4 lightViewProjection() const { return lightViewProjection_; }
    // bias * P_light * V_light * model, the matrix the lit pass needs per object.
    glm::mat4 shadowMatrix(const glm::mat4& model, float biasZ) const {
        return biasMatrix(biasZ) * lightViewProjection_ * model;
    }
    // Binds the map for the lit pass (with its compare mode) to texture unit `unit`.
    void bind(int unit) const;
    // Binds it through a sampler with no compare mode, for looking at the raw values.
    void bindPlain(int unit) const;
    const ShadowMapSettings& settings() const { return settings_; }
    bool addedColourAttachment() const { return addedColour_; }
    // Size of the texture in bytes, for the HUD.
    std::size_t bytes() const;

  private:
    void allocate(const ShadowMapSettings& s);
    std::vector<Aabb> boundsInMap(const FrameContext& f, bool castersOnly) const;

    ShadowMapSettings settings_;
    bool allocated_ = false;
    Texture map_;          // depth texture, or the RGB8 colour texture
    Texture extraColour_;  // R32F colour when a depth-only FBO is reported incomplete
    Renderbuffer depth_;   // depth for the RGB8 map
    Framebuffer fbo_;
    Sampler plain_;
    bool addedColour_ = false;
    LightFrustum frustum_;
    glm::mat4 lightViewProjection_{1};
    // What the current contents were rendered from.
    glm::vec3 renderedLight_{NAN};
    unsigned renderedScene_ = ~0u;
    bool renderedAllLit_ = false;
    GLuint renderedProgram_ = 0;
    ShadowMapSettings renderedSettings_;
};

}  // namespace sl
