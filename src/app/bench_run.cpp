#include "app/bench_run.h"

#include <chrono>
#include <glm/gtc/matrix_transform.hpp>
#include <sstream>

#if __has_include(<valgrind/callgrind.h>)  // header only: the macros are no-ops outside valgrind
#include <valgrind/callgrind.h>
#define SL_HAVE_CALLGRIND 1
#endif

#include "metrics/mirror_metrics.h"
#include "metrics/shadow_metrics.h"

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
    phong.stage = "phong";
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
    Renderer& r = *renderer_;
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
        r.render(context_->framebuffer(), context_->width(), context_->height());
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

void countedFrames(BenchRig& rig, int frames, bool movingLight) {
#ifdef SL_HAVE_CALLGRIND
    CALLGRIND_TOGGLE_COLLECT;  // on (the child runs with --collect-atstart=no)
    rig.time(0, frames, movingLight);
    CALLGRIND_TOGGLE_COLLECT;            // off
    CALLGRIND_DUMP_STATS_AT("counted");  // one dump file per call, in call order
#else
    rig.time(0, frames, movingLight);
#endif
}

Renderer& BenchRig::prepare(const RenderRequest& request) {
    validateRequest(request);
    RenderRequest r = request;
    r.scene = effectiveScene(request);
    r.sceneGiven = true;
    // The camera is part of the key: spheres are tessellated for the camera they are seen from.
    auto vec = [](const std::optional<glm::vec3>& v) {
        std::ostringstream t;
        if (v) t << v->x << "," << v->y << "," << v->z;
        return t.str();
    };
    std::ostringstream key;
    key << static_cast<int>(r.tree) << "/" << r.scene << "/" << r.width << "x" << r.height
        << "/overlay=" << r.overlay << "/eye=" << vec(r.eye) << "/at=" << vec(r.at)
        << "/fovy=" << (r.fovy ? std::to_string(*r.fovy) : "");
    if (key.str() != key_) {
        reset();
        context_ = createHeadlessContext(backend_, r.tree, r.width, r.height);
        renderer_ = makeRenderer(r);
        sceneLight_ = renderer_->scene().light.position;
        key_ = key.str();
    }
    renderer_->selectStage(r.stage);
    renderer_->params() = ParamSet(renderer_->stage().params);
    renderer_->lightPosition = sceneLight_;
    renderer_->allLit = false;
    applyRequest(*renderer_, r);
    return *renderer_;
}

void BenchRig::reset() {
    idRenderer_.reset();  // the renderers' GL objects go before the context
    renderer_.reset();
    context_.reset();
    key_.clear();
    referenceKey_.clear();
}

const ReferenceImage& BenchRig::reference() {
    Renderer& r = *renderer_;
    std::ostringstream key;
    auto put = [&](const glm::vec3& v) { key << "/" << v.x << "," << v.y << "," << v.z; };
    key << key_ << "/" << r.camera.fovyDegrees;
    for (const glm::vec3& v : {r.lightPosition, r.camera.eye, r.camera.at}) put(v);
    if (key.str() != referenceKey_) {
        reference_ = traceReference(r.scene(), r.camera, r.lightPosition, context_->width(),
                                    context_->height());
        referenceKey_ = key.str();
    }
    return reference_;
}

Accuracy shadowAccuracy(const ShadowFigures& f) {
    Accuracy a;
    a.falseShadowPct = f.falseShadowPct;
    a.falseLitPct = f.falseLitPct;
    a.falseShadowBandPct = f.falseShadowBandPct;
    a.falseLitBandPct = f.falseLitBandPct;
    a.edgeMeanPx = f.edgeDefined ? f.edgeMeanPx : NAN;
    a.edgeP95Px = f.edgeDefined ? f.edgeP95Px : NAN;
    a.errorPct = 0.5 * (f.falseShadowPct + f.falseLitPct);
    return a;
}

Accuracy BenchRig::accuracy() {
    if (renderer_->stage().id == "mirror") return mirrorAccuracy();
    return shadowAccuracy(shadowEvidence().figures);
}

ShadowEvidence BenchRig::shadowEvidence() {
    Renderer& r = *renderer_;
    int w = context_->width(), h = context_->height();
    const ReferenceImage& ref = reference();
    ShadowEvidence e;
    r.allLit = false;
    r.render(context_->framebuffer(), w, h);
    e.withShadows = context_->read();
    r.allLit = true;
    r.render(context_->framebuffer(), w, h);
    e.allLit = context_->read();
    r.allLit = false;
    e.shadowed = classifyShadowed(e.withShadows, e.allLit);
    e.figures = shadowFigures(ref, e.shadowed);
    return e;
}

// The mirror (GUIDE section 4): which object each mirror pixel shows, against the reference's
// bounce, and how close the picture is to the exact stencil method, over the mirror's front.
Accuracy BenchRig::mirrorAccuracy() {
    Renderer& r = *renderer_;
    int w = context_->width(), h = context_->height();
    const ReferenceImage& ref = reference();
    std::vector<std::uint8_t> mask = mirrorMask(ref, r.scene());
    r.allLit = false;
    r.render(context_->framebuffer(), w, h);
    Image shown = context_->read();
    const std::string method = r.params().text("mirror-method");
    r.params().set("mirror-method", "stencil");
    r.render(context_->framebuffer(), w, h);
    Image exact = context_->read();
    r.params().set("mirror-method", method);

    if (!idRenderer_)  // same shaders (a student's overlay too), the scene painted in id colours
        idRenderer_ = std::make_unique<Renderer>(
            idColouredScene(r.scene()),
            ShaderLibrary(r.shaders().tree(), shaderTreeRoot(r.shaders().tree()),
                          r.shaders().overlay()),
            h);
    Renderer& ids = *idRenderer_;
    ids.selectStage(r.stage().id);
    ids.params() = r.params();
    ids.camera = r.camera;
    ids.lightPosition = r.lightPosition;
    ids.view = ViewMode::Final;
    ids.render(context_->framebuffer(), w, h);
    std::vector<int> seen =
        decodeIdImage(context_->read(), mirrorId(r.scene()) - 1, kMirrorReflectance);

    Accuracy a;
    a.mirrorIdPct = mirrorIdAgreementPct(ref, seen);
    a.mirrorPsnrDb = psnrInMask(shown, exact, mask);
    a.errorPct = 100.0 - a.mirrorIdPct;
    return a;
}

}  // namespace sl
