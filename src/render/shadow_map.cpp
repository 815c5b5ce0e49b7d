#include "render/shadow_map.h"

#include <chrono>
#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>

#include "gl/state.h"
#include "render/scene_pass.h"
#include "scene/mesh.h"

namespace sl {

namespace {
// How much farther from the light the receivers lie in the "everything lit" map: 10 % of their
// distance is many 8-bit depth steps and more than any filter's reach on the lessons' receivers.
constexpr float kLitFrameFarther = 0.1f;
}  // namespace

MapStorage parseStorage(const std::string& t) {
    if (t == "rgb8") return MapStorage::Rgb8;
    if (t == "depth16" || t == "16") return MapStorage::Depth16;
    if (t == "depth24" || t == "24") return MapStorage::Depth24;
    if (t == "depth32f" || t == "32f") return MapStorage::Depth32F;
    throw std::invalid_argument("unknown map storage '" + t + "'");
}

bool ShadowMapSettings::operator==(const ShadowMapSettings& o) const {
    return storage == o.storage && size == o.size && fit == o.fit && castersOnly == o.castersOnly &&
           farOverNear == o.farOverNear && offsetFactor == o.offsetFactor &&
           offsetUnits == o.offsetUnits && cullFront == o.cullFront && cullBack == o.cullBack &&
           depthFlipped == o.depthFlipped && compare == o.compare && linear == o.linear &&
           everyFrame == o.everyFrame;
}

std::size_t ShadowMap::bytes() const {
    std::size_t texels = std::size_t(settings_.size) * settings_.size;
    switch (settings_.storage) {
        case MapStorage::Rgb8:
            return texels * (3 + 4);  // colour + depth renderbuffer
        case MapStorage::Depth16:
            return texels * 2;
        case MapStorage::Depth24:
            return texels * 4;
        case MapStorage::Depth32F:
            return texels * 4;
    }
    return 0;
}

void ShadowMap::allocate(const ShadowMapSettings& s) {
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (s.size < 16 || s.size > maxSize)
        throw std::invalid_argument("map-size " + std::to_string(s.size) + " is outside 16 to " +
                                    std::to_string(maxSize) +
                                    " (this driver's GL_MAX_TEXTURE_SIZE)");
    map_ = Texture::create();
    extraColour_.reset();
    depth_.reset();
    fbo_ = Framebuffer::create();
    plain_ = Sampler::create();
    addedColour_ = false;

    glBindTexture(GL_TEXTURE_2D, map_.id());
    GLint filter = s.linear ? GL_LINEAR : GL_NEAREST;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    // Outside the map counts as lit: clamp to a border at the far value.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    const float white[4] = {1, 1, 1, 1};
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, white);
    glSamplerParameteri(plain_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(plain_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(plain_.id(), GL_TEXTURE_COMPARE_MODE, GL_NONE);

    ScopedFramebuffer bind(fbo_.id(), s.size, s.size);
    if (s.storage == MapStorage::Rgb8) {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, s.size, s.size, 0, GL_RGB, GL_UNSIGNED_BYTE,
                     nullptr);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, map_.id(), 0);
        depth_ = Renderbuffer::create();
        glBindRenderbuffer(GL_RENDERBUFFER, depth_.id());
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, s.size, s.size);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                  depth_.id());
        glDrawBuffer(GL_COLOR_ATTACHMENT0);
    } else {
        GLenum format = s.storage == MapStorage::Depth16   ? GL_DEPTH_COMPONENT16
                        : s.storage == MapStorage::Depth24 ? GL_DEPTH_COMPONENT24
                                                           : GL_DEPTH_COMPONENT32F;
        GLenum type = s.storage == MapStorage::Depth32F ? GL_FLOAT : GL_UNSIGNED_INT;
        glTexImage2D(GL_TEXTURE_2D, 0, format, s.size, s.size, 0, GL_DEPTH_COMPONENT, type,
                     nullptr);
        if (s.compare) {
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
        }
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, map_.id(), 0);
        glDrawBuffer(GL_NONE);  // no colour writes where none are needed
        glReadBuffer(GL_NONE);
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
            // Some drivers (the lab's) want a colour attachment before they call it complete.
            extraColour_ = Texture::create();
            glBindTexture(GL_TEXTURE_2D, extraColour_.id());
            glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, s.size, s.size, 0, GL_RED, GL_FLOAT, nullptr);
            glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                                   extraColour_.id(), 0);
            glDrawBuffer(GL_COLOR_ATTACHMENT0);
            addedColour_ = true;
        }
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    std::string incomplete = checkFramebufferComplete("shadow map framebuffer");
    if (!incomplete.empty()) throw std::runtime_error(incomplete);
    allocated_ = true;
}

std::vector<Aabb> ShadowMap::boundsInMap(const FrameContext& f, bool castersOnly) const {
    std::vector<Aabb> boxes;
    for (const Object& o : f.scene.objects) {
        if (castersOnly && !o.castsShadow) continue;
        glm::mat4 m = modelMatrix(o);
        Aabb b{glm::vec3(INFINITY), glm::vec3(-INFINITY)};
        for (int k = 0; k < 8; ++k) {  // the unit primitive's corners, placed in the world
            glm::vec3 c((k & 1) ? 0.5f : -0.5f, (k & 2) ? 0.5f : -0.5f, (k & 4) ? 0.5f : -0.5f);
            if (o.kind == PrimitiveKind::Sphere) c *= 2.0f;  // the unit sphere has radius 1
            if (o.kind == PrimitiveKind::Quad) c.z = 0;
            glm::vec3 w = glm::vec3(m * glm::vec4(c, 1));
            b.lo = glm::min(b.lo, w);
            b.hi = glm::max(b.hi, w);
        }
        boxes.push_back(b);
    }
    return boxes;
}

void ShadowMap::update(FrameContext& f, const ShadowMapSettings& s, Program& program) {
    PassScope pass("shadow");
    bool reallocate = !allocated_ || s.storage != settings_.storage || s.size != settings_.size ||
                      s.compare != settings_.compare || s.linear != settings_.linear;
    if (reallocate) allocate(s);
    settings_ = s;
    f.stats.mapSize = s.size;
    f.stats.lightViewProjection = lightViewProjection_;
    bool stale = reallocate || s.everyFrame || f.lightPosition != renderedLight_ ||
                 f.sceneGeneration != renderedScene_ || f.allLit != renderedAllLit_ ||
                 program.id() != renderedProgram_ || s != renderedSettings_;
    if (!stale) return;

    auto start = std::chrono::steady_clock::now();
    frustum_ = fitLightFrustum(f.lightPosition, f.scene.light.target, boundsInMap(f, s.castersOnly),
                               s.fit);
    frustum_ = withFarOverNear(frustum_, s.farOverNear);
    glm::mat4 projection =
        s.depthFlipped ? depthFlippedProjection(frustum_.projection) : frustum_.projection;
    lightViewProjection_ = projection * frustum_.view;
    // Where the GL refuses glDepthRange(1, 0) (WebGL), the map is drawn with the standard
    // projection and range: its window depth (1 + z_standard) / 2 is exactly the flipped pair's
    // (1 - z_flipped) / 2, so the map is the same, and the lit pass still gets the flipped
    // projection: the slides' -0.5 is right with it and +0.5 inverted, as on the desktop.
    const bool flipRange = s.depthFlipped && kDepthRangeFlips;
    const glm::mat4 drawnFrom = s.depthFlipped && !kDepthRangeFlips
                                    ? frustum_.projection * frustum_.view
                                    : lightViewProjection_;
    {
        ScopedFramebuffer bind(fbo_.id(), s.size, s.size);
        ScopedDepthRange range(flipRange ? 1.0 : 0.0, flipRange ? 0.0 : 1.0);
        // With the flipped range, nearer fragments have larger NDC z but smaller window z, so the
        // usual GL_LESS still keeps the nearest one.
        ScopedPolygonOffset offset(s.offsetFactor, s.offsetUnits);
        ScopedCullFace cull(s.cullFront ? GL_FRONT : s.cullBack ? GL_BACK : GL_NONE);
        glClearColor(1, 1, 1, 1);  // the far value, in colour too
        glClearDepth(1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        // Without a border clamp (WebGL) a lookup outside the map reads the edge texel: the pass
        // leaves the outermost texels at the clear value (the border's white, the far depth), so
        // the edge texel is the border and outside the map is lit, as on the desktop.
        ScopedScissor ring(!kBorderClamp, 1, 1, s.size - 2, s.size - 2);
        // Forced "everything lit" (grading): the same frustum and pass over a real scene whose
        // casters are out of the light's way and whose receivers lie a little farther from the
        // light (scaled about it, so each covers the same texels): no surface is in shadow, not
        // even of itself (acne), yet the map is one a real scene makes. A map of all far texels
        // was a frame no scene makes, and a shader could recognise it.
        FromLight which = s.castersOnly ? FromLight::Casters : FromLight::All;
        if (f.allLit) which = s.castersOnly ? FromLight::None : FromLight::Receivers;
        const glm::mat4 away = glm::translate(glm::mat4(1), f.lightPosition) *
                               glm::scale(glm::mat4(1), glm::vec3(1.0f + kLitFrameFarther)) *
                               glm::translate(glm::mat4(1), -f.lightPosition);
        drawSceneFromLight(program, f, drawnFrom, which,
                           [&](Program& p, std::size_t i, const glm::mat4& model) {
                               if (f.allLit) p.set("model", away * model);
                               if (!s.cullBack) return;
                               bool closed = f.scene.objects[i].kind != PrimitiveKind::Quad;
                               closed ? glEnable(GL_CULL_FACE) : glDisable(GL_CULL_FACE);
                           });
    }
    ++f.stats.shadowMapRenders;
    f.stats.lightViewProjection = lightViewProjection_;
    if (f.timePasses) {
        glFinish();
        f.stats.shadowMs =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
    }
    renderedLight_ = f.lightPosition;
    renderedScene_ = f.sceneGeneration;
    renderedAllLit_ = f.allLit;
    renderedProgram_ = program.id();
    renderedSettings_ = s;
}

void ShadowMap::bind(int unit) const {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, map_.id());
    glBindSampler(unit, 0);
    glActiveTexture(GL_TEXTURE0);
}

void ShadowMap::bindPlain(int unit) const {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, map_.id());
    glBindSampler(
        unit, plain_.id());  // compare mode off: sampling a compare texture as plain is undefined
    glActiveTexture(GL_TEXTURE0);
}

}  // namespace sl
