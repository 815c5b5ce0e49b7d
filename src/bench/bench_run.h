// The measuring engine shared by `bench` and `sweep`: one headless context and renderer per
// (tree, scene, size), a configuration = stage + parameters, timed per pass and checked against
// the reference ray tracer.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "eval/evaluator.h"
#include "metrics/timing.h"

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

// The Evaluator with a clock: configurations timed alone or beside phong. Contexts, renderers
// and the figures are the Evaluator's.
class BenchRig : public Evaluator {
  public:
    // Figures to the pixel (EdgeTolerance::Pixel): the bench compares map sizes and methods.
    explicit BenchRig(Backend backend) : Evaluator(backend, EdgeTolerance::Pixel) {}
    using Evaluator::prepare;
    // Selects the stage and its parameters (defaults + sets) on a renderer for the config's
    // tree, the stage's default scene and size: the request below, built from the config. The
    // light is `light` (checked like --light) or else the scene's.
    Renderer& prepare(const BenchConfig& c, const std::optional<glm::vec3>& light = std::nullopt);

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
};

// The frames `bench --instructions` counts under callgrind (metrics/callgrind.h): `frames` frames
// of the rig's current configuration, collected between two callgrind client requests and
// dumped to a file of their own (valgrind's header; without it nothing is counted).
unsigned countedFrames(BenchRig& rig, int frames, bool movingLight);  // returns the map renders
// Whether this build was compiled with valgrind's callgrind.h: without it countedFrames marks
// nothing and callgrind would count 0 instructions.
bool callgrindMarkersBuiltIn();

}  // namespace sl
