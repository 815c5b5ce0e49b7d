#include "bench/bench_run.h"

#include <chrono>
#include <glm/gtc/matrix_transform.hpp>
#include <sstream>

#include "stages/registry.h"

// Set by CMake when it finds valgrind's header at configure time (CMakeLists.txt: a check that
// runs again at every configure, so the build that follows installing valgrind has it).
#ifdef SHADOWLAB_HAVE_CALLGRIND
#include <valgrind/callgrind.h>  // header only: the macros are no-ops outside valgrind
#endif

namespace sl {

std::string BenchConfig::setsText() const {
    std::string text;
    for (const auto& [name, value] : sets) text += (text.empty() ? "" : " ") + name + "=" + value;
    return text.empty() ? "defaults" : text;
}

std::string BenchConfig::sceneName() const {
    RenderRequest r;
    r.stage = stage;
    if (!scene.empty()) {
        r.scene = scene;
        r.sceneGiven = true;
    }
    return effectiveScene(r);
}

Renderer& BenchRig::prepare(const BenchConfig& c, const std::optional<glm::vec3>& light) {
    RenderRequest request;
    request.stage = c.stage;
    request.tree = c.tree;
    request.width = c.width;
    request.height = c.height;
    request.sets = c.sets;
    request.scene = c.sceneName();
    request.sceneGiven = true;
    request.light = light;
    return prepare(request);
}

glm::vec3 steppedLight(const glm::vec3& home, const glm::vec3& target, int k) {
    float angle = glm::radians(k % 2 ? 0.5f : -0.5f);
    glm::mat4 turn = glm::rotate(glm::mat4(1.0f), angle, glm::vec3(0, 1, 0));
    return target + glm::vec3(turn * glm::vec4(home - target, 0.0f));
}

void PassSamples::append(const PassSamples& more) {
    frame.insert(frame.end(), more.frame.begin(), more.frame.end());
    shadow.insert(shadow.end(), more.shadow.begin(), more.shadow.end());
    lit.insert(lit.end(), more.lit.begin(), more.lit.end());
    mirror.insert(mirror.end(), more.mirror.begin(), more.mirror.end());
    mapRenders += more.mapRenders;
}

PassTimes PassSamples::summary() const {
    return {summarize(frame), summarize(shadow), summarize(lit), summarize(mirror), mapRenders};
}

BenchRig::Paired BenchRig::timeBesidePhong(const BenchConfig& c, int framesPerBlock, int blocks,
                                           bool movingLight) {
    BenchConfig phong = c;
    phong.stage = lightingStage().id;
    phong.sets.clear();
    phong.scene = c.sceneName();
    PassSamples config, base;
    std::vector<double> configBlocks, baseBlocks;  // each block's median frame time
    auto run = [&](const BenchConfig& which, PassSamples& into, std::vector<double>& medians) {
        prepare(which);
        PassSamples block = time(1, framesPerBlock, movingLight);
        medians.push_back(summarize(block.frame).median);
        into.append(block);
    };
    for (int k = 0; k < blocks; ++k) {
        if (configFirst(k)) {
            run(c, config, configBlocks);
            run(phong, base, baseBlocks);
        } else {
            run(phong, base, baseBlocks);
            run(c, config, configBlocks);
        }
    }
    return {config.summary(), base.summary(), summarizeRatios(configBlocks, baseBlocks)};
}

PassSamples BenchRig::time(int warmup, int frames, bool movingLight) {
    Renderer& r = renderer();
    const glm::vec3 home = r.lightPosition;
    const glm::vec3 target = r.scene().light.target;
    auto lightFor = [&](int k) { return movingLight ? steppedLight(home, target, k) : home; };
    r.timePasses = true;
    std::vector<double> frame, shadow, lit, mirror;
    unsigned rendersBefore = 0;
    for (int k = 0; k < warmup + frames; ++k) {
        if (k == warmup) rendersBefore = r.stats.shadowMapRenders;
        r.lightPosition = lightFor(k);
        glFinish();
        auto start = std::chrono::steady_clock::now();
        r.render(context().framebuffer(), context().width(), context().height());
        glFinish();
        double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        if (k < warmup) continue;
        frame.push_back(ms);
        shadow.push_back(r.stats.shadowMs);
        lit.push_back(r.stats.litMs);
        mirror.push_back(r.stats.mirrorMs);
    }
    r.timePasses = false;
    r.lightPosition = home;
    return {frame, shadow, lit, mirror, r.stats.shadowMapRenders - rendersBefore};
}

bool callgrindMarkersBuiltIn() {
#ifdef SHADOWLAB_HAVE_CALLGRIND
    return true;
#else
    return false;
#endif
}

unsigned countedFrames(BenchRig& rig, int frames, bool movingLight) {
#ifdef SHADOWLAB_HAVE_CALLGRIND
    CALLGRIND_TOGGLE_COLLECT;  // on (the child runs with --collect-atstart=no)
    PassSamples counted = rig.time(0, frames, movingLight);
    CALLGRIND_TOGGLE_COLLECT;            // off
    CALLGRIND_DUMP_STATS_AT("counted");  // one dump file per call, in call order
#else
    PassSamples counted = rig.time(0, frames, movingLight);
#endif
    return counted.mapRenders;
}

}  // namespace sl
