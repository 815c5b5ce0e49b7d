// The measuring engine shared by `bench` and `sweep`: one headless context and renderer per
// (tree, scene, size), a configuration = stage + parameters, timed per pass and checked against
// the reference ray tracer.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "metrics/shadow_metrics.h"
#include "metrics/timing.h"
#include "platform/headless.h"
#include "reference/raytracer.h"
#include "render/request.h"

namespace sl {

// The light of frame k when it moves every frame: half a degree either side of `home` around the
// vertical through `target`, so each frame differs from the last and the map is always stale.
glm::vec3 steppedLight(const glm::vec3& home, const glm::vec3& target, int k);

// One thing to measure. `series` groups points that differ only along one axis (a chart line).
struct BenchConfig {
    std::string group;   // "map-size", "format", "mirror", "window", ...
    std::string series;  // e.g. "hardware/nearest"
    std::string stage;
    std::string scene;  // "" = the stage's own default scene
    GlslTree tree = GlslTree::Core;
    std::vector<std::pair<std::string, std::string>> sets;
    int width = 640, height = 480;
    std::string setsText() const;
    std::string sceneName() const;  // the scene actually rendered  // "map-size=512 filter=linear",
                                    // "defaults" when empty
};

struct PassTimes {
    TimeSummary frame, shadow, lit, mirror;
    unsigned mapRenders = 0;  // shadow-map renders during the timed frames
};

// Raw per-frame times, appended over several rounds and summarised at the end.
struct PassSamples {
    std::vector<double> frame, shadow, lit, mirror;
    unsigned mapRenders = 0;
    void append(const PassSamples& more);
    PassTimes summary() const;
};

// The accuracy figures of one render (GUIDE section 4). Non-applicable ones stay NaN.
struct Accuracy {
    double falseShadowPct = NAN, falseLitPct = NAN;
    double falseShadowBandPct = NAN, falseLitBandPct = NAN;
    double edgeMeanPx = NAN, edgeP95Px = NAN;
    double mirrorIdPct = NAN, mirrorPsnrDb = NAN;
    // One number for charts: shadow stages the balanced error (false shadow % + false lit %) / 2
    // outside the edge band; the mirror 100 - id agreement %.
    double errorPct = NAN;
};

// The Accuracy of a shadow stage from its figures (edge figures NaN when undefined).
Accuracy shadowAccuracy(const ShadowFigures& f);

// The two renders and the classification behind a shadow stage's figures (diff images use them).
struct ShadowEvidence {
    Image withShadows, allLit;
    std::vector<std::uint8_t> shadowed;  // classifyShadowed(withShadows, allLit)
    ShadowFigures figures;
};

// Holds a context and renderer for the current (backend, tree, scene, size) and rebuilds them only
// when one of those changes, so a run compiles each stage's shaders once per context.
class BenchRig {
  public:
    explicit BenchRig(Backend backend) : backend_(backend) {}
    // Selects the stage and its parameters (defaults + sets) on a renderer for the config's
    // tree, the stage's default scene and size: the request below, built from the config. The
    // light is `light` (checked like --light) or else the scene's.
    Renderer& prepare(const BenchConfig& c, const std::optional<glm::vec3>& light = std::nullopt);
    // The same for a whole request (`check`): its student overlay and camera are part of the
    // context key; parameters start from the defaults, then the request's camera, light, view
    // and --set values apply.
    Renderer& prepare(const RenderRequest& request);
    // Drops the context and renderer, e.g. after a shader error left the GL state unknown.
    void reset();
    HeadlessContext& context() { return *context_; }
    Renderer& renderer() { return *renderer_; }

    // `warmup` untimed frames, then `frames` timed ones (glFinish + steady clock). With
    // `movingLight` the light steps around its target every frame, so each frame re-renders
    // the shadow map; otherwise it stays put and a cached map costs nothing.
    PassSamples time(int warmup, int frames, bool movingLight);

    // The configuration and phong (same context, scene and light) measured in `blocks` short
    // interleaved blocks of `framesPerBlock` frames, in ABBA order (configFirst), so drift on a
    // shared machine hits both alike. The figure that matters is the median of the per-block
    // ratios (block median over block median) with its spread. Each block starts with one
    // untimed frame (a stage switch re-creates its map).
    struct Paired {
        PassTimes config, phong;
        RatioSummary ratio;
    };
    Paired timeBesidePhong(const BenchConfig& c, int framesPerBlock, int blocks, bool movingLight);
    // Renders the current configuration with and without its shadow map and compares both with
    // the reference (traced once per camera, light and size, then reused).
    Accuracy accuracy();
    // The reference for the current camera, light and size (traced once, then reused).
    const ReferenceImage& reference();
    // The shadow stages' half of accuracy(): both renders, the classification and the figures.
    ShadowEvidence shadowEvidence();

  private:
    Accuracy mirrorAccuracy();
    Backend backend_;
    std::string key_;
    std::unique_ptr<HeadlessContext> context_;
    std::unique_ptr<Renderer> renderer_;
    std::unique_ptr<Renderer> idRenderer_;  // the same scene in id colours (mirror figures)
    glm::vec3 sceneLight_{0};
    std::string referenceKey_;
    ReferenceImage reference_;
};

// The frames `bench --instructions` counts under callgrind (metrics/callgrind.h): `frames` frames
// of the rig's current configuration, collected between two callgrind client requests and
// dumped to a file of their own (valgrind's header; without it nothing is counted).
void countedFrames(BenchRig& rig, int frames, bool movingLight);

}  // namespace sl
