#include "eval/evaluator.h"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "io/box.h"
#include "metrics/mirror_metrics.h"
#include "metrics/shadow_metrics.h"
#include "stages/registry.h"

namespace sl {

Renderer& Evaluator::prepare(const RenderRequest& request) {
    validateRequest(request);
    RenderRequest r = request;
    r.scene = effectiveScene(request);
    r.sceneGiven = true;
    // The camera is part of the key: spheres are tessellated for the camera they are seen from.
    auto vec = [](const std::optional<glm::vec3>& v) { return v ? exactText(*v) : std::string(); };
    // The context depends on the profile and size only: a new overlay or view builds a new
    // renderer in it (a context's start-up cost as much as a row's figures).
    const std::string contextKey = std::to_string(static_cast<int>(r.tree)) + "/" +
                                   std::to_string(r.width) + "x" + std::to_string(r.height);
    std::ostringstream key;
    key << contextKey << "/" << r.scene << "/overlay=" << r.overlay << "/eye=" << vec(r.eye)
        << "/at=" << vec(r.at) << "/fovy=" << (r.fovy ? exactText(*r.fovy) : "")
        << "/displaced=" << (r.displaceSeed ? std::to_string(*r.displaceSeed) : "");
    if (context_ && contextKey == contextKey_ && !context_->makeCurrent())
        throw std::runtime_error(std::string("could not make the ") + context_->backendName() +
                                 " context current again");  // another may have been since
    if (key.str() != key_) {
        if (!context_ || contextKey != contextKey_) {
            reset();
            context_ = createHeadlessContext(backend_, r.tree, r.width, r.height);
            installGlDebugOutput(
                true);  // a GL error is caught in the draw that raised it (whose shader)
            contextKey_ = contextKey;
        } else {
            for (auto& shipped : shipped_) shipped.reset();  // they draw the old scene
            renderer_.reset();
            key_.clear();
        }
        renderer_ = makeRenderer(r);
        overlay_ = r.overlay;
        sceneLight_ = renderer_->scene().light.position;
        key_ = key.str();
        sceneView_ = TraceView{r.scene, r.displaceSeed, r.width, r.height, {}, {}};
    }
    renderer_->selectStage(r.stage);
    renderer_->params() = ParamSet(renderer_->stage().params);
    renderer_->lightPosition = sceneLight_;
    renderer_->allLit = false;
    applyRequest(*renderer_, r);
    return *renderer_;
}

std::size_t Evaluator::maxTruths(int width, int height) {
    // A view's truth holds the reference (sizeof(ReferencePixel) a pixel) and about 100 bytes a
    // pixel more (shades, our pictures' luma for both trees, the truth's half of the figures, the
    // band of a few map settings): at most a quarter of the worker's memory goes to them.
    static const long long budget = [] {
        Box box = readBox();
        std::optional<long long> limit = box.addressSpaceBytes;
        if (box.memoryBytes && (!limit || *box.memoryBytes < *limit)) limit = box.memoryBytes;
        return limit ? *limit / 4 : 1LL << 30;
    }();
    const long long perTruth =
        (long long)(sizeof(ReferencePixel) + 100) * std::max(1, width) * std::max(1, height);
    return std::size_t(std::clamp<long long>(budget / perTruth, 1, kMaxTruths));
}

void Evaluator::reset() {
    for (auto& r : shipped_) r.reset();  // the renderers' GL objects go before the context
    renderer_.reset();
    context_.reset();
    contextKey_.clear();
    key_.clear();
    referenceKey_.clear();
    truth_.reset();
}

std::string Evaluator::currentTraceKey() const {
    TraceView view = sceneView_;
    view.camera = renderer_->camera;
    view.light = renderer_->lightPosition;
    return traceKey(view);
}

const ReferenceImage& Evaluator::reference() {
    Renderer& r = *renderer_;
    const std::string key = currentTraceKey();
    if (!truth_ || key != referenceKey_) {
        referenceKey_ = key;
        auto found = truths_.find(referenceKey_);
        if (found != truths_.end()) {
            truth_ = found->second;
            keepReference(referenceKey_);
        } else {
            truth_ = std::make_shared<Truth>();
            auto given = given_.find(key);
            if (given != given_.end()) {
                truth_->reference = std::move(given->second);
                given_.erase(given);
                ++givenUsed_;
            } else {
                truth_->reference = traceReference(r.scene(), r.camera, r.lightPosition,
                                                   context_->width(), context_->height());
                ++traced_;
            }
            while (truthOrder_.size() >= maxTruths(context_->width(), context_->height())) {
                truths_.erase(truthOrder_.front());
                truthOrder_.erase(truthOrder_.begin());
            }
            truths_[referenceKey_] = truth_;
            truthOrder_.push_back(referenceKey_);
        }
    }
    return truth_->reference;
}

bool Evaluator::keepReference(const std::string& key) {
    if (given_.count(key)) return true;
    if (!truths_.count(key)) return false;
    // The views seen least recently go first (truthOrder_ from the oldest).
    truthOrder_.erase(std::find(truthOrder_.begin(), truthOrder_.end(), key));
    truthOrder_.push_back(key);
    return true;
}

void Evaluator::giveReference(const std::string& key, ReferenceImage reference) {
    if (truths_.count(key)) return;
    given_[key] = std::move(reference);
}

const ReferenceShades& Evaluator::shades() {
    reference();
    if (!truth_->shaded) {
        Renderer& r = *renderer_;
        truth_->shades = referenceShades(r.scene(), r.camera, truth_->reference, r.lightPosition);
        truth_->visible = shadowVisiblePixels(truth_->shades);
        truth_->shares = shadeShares(truth_->shades);
        truth_->shaded = true;
    }
    return truth_->shades;
}

const std::vector<std::uint8_t>& Evaluator::shadowVisible() {
    shades();
    return truth_->visible;
}

Accuracy shadowAccuracy(const ShadowFigures& f) {
    Accuracy a;
    // A figure over an empty set measured nothing: undefined, not a perfect 0 (a sweep would
    // call a light too low to show any shadow the most robust).
    a.falseShadowPct = f.litOutside > 0 ? f.falseShadowPct : NAN;
    a.falseLitPct = f.shadowOutside > 0 ? f.falseLitPct : NAN;
    a.falseShadowBandPct = f.falseShadowBandPct;
    a.falseLitBandPct = f.falseLitBandPct;
    a.edgeMeanPx = f.edgeDefined ? f.edgeMeanPx : NAN;
    a.edgeP95Px = f.edgeDefined ? f.edgeP95Px : NAN;
    a.darkWithoutCasterPct = f.darkWithoutCasterPct;
    a.falseShadowSpecklePct = f.falseShadowSpecklePct;
    a.shadowLevelOffPct = f.shadowLevelOffPct;
    a.litLightLostPct = f.litLightLostPct;
    a.litTooBrightPct = f.litTooBrightPct;
    a.errorPct = 0.5 * (a.falseShadowPct + a.falseLitPct);  // NaN when either is
    return a;
}

Accuracy Evaluator::accuracy() {
    // Our own shaders' figures are the same whoever is graded (a class measures them in every
    // displaced view for each student's bounds): measured once a configuration.
    std::string key;
    if (overlay_.empty()) {
        const Renderer& r = *renderer_;
        key = key_ + "/stage=" + r.stage().id + "/view=" + viewName(r.view) +
              "/light=" + exactText(r.lightPosition) + "/eye=" + exactText(r.camera.eye) +
              "/at=" + exactText(r.camera.at) + "/fovy=" + exactText(r.camera.fovyDegrees);
        const ParamSet& params = renderer_->params();
        for (const ParamSpec& p : params.specs())
            key += "/" + p.name + "=" +
                   (p.kind == ParamKind::Choice ? params.choice(p.name)
                                                : exactText(params.number(p.name)));
        auto found = ours_.find(key);
        if (found != ours_.end()) return found->second;
    }
    Accuracy a = renderer_->stage().needsMirror ? mirrorAccuracy()
                                                : shadowAccuracy(shadowEvidence().figures);
    if (!key.empty()) {
        ++oursMeasured_;
        constexpr std::size_t kMaxOurs = 64;
        if (ours_.size() >= kMaxOurs) ours_.clear();
        ours_[key] = a;
    }
    return a;
}

ShadowEvidence Evaluator::shadowEvidence() {
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
    // Our lighting without shadows (dark without a caster) and with its highlight (too bright:
    // bounded from above too, flat white, a flat colour, infinities written to an 8-bit target),
    // and our id render (coverage): the same for every submission, drawn once a view.
    const ShippedView& ours = shippedView();
    RenderClassification c =
        classifyRender(e.withShadows, e.allLit, ours.baselineLuma, ours.oursLuma, truth_->shares);
    if (tolerance_ == EdgeTolerance::MapTexel) c.inputs.bandPx = mapTexelBand();
    e.shadowed = std::move(c.shadowed);
    e.figures = shadowFigures(ref, ours.truth, e.shadowed, c.inputs);
    return e;
}

const Evaluator::ShippedView& Evaluator::shippedView() {
    Renderer& r = *renderer_;
    shades();
    const std::string lighting = lightingStage().id;
    const std::string unshadowed = r.stage().unshadowedIsOwn ? "" : lighting;
    std::shared_ptr<ShippedView>& slot =
        truth_->shipped[std::string(context_->backendName()) + "/" + treeName(r.shaders().tree()) +
                        "/" + unshadowed];
    if (!slot) {
        auto view = std::make_shared<ShippedView>();
        if (!unshadowed.empty())
            view->baselineLuma =
                lumaOf(renderWith(shippedRenderer(Shipped::Unhighlighted), unshadowed));
        view->oursLuma = lumaOf(renderWith(shippedRenderer(Shipped::Lit), lighting));
        const std::vector<int> ids =
            decodeIdImage(renderWith(shippedRenderer(Shipped::Ids), lighting),
                          int(r.scene().objects.size()), 1.0f);
        view->truth = shadowTruth(truth_->reference, ids, truth_->visible);
        slot = std::move(view);
        ++shippedViews_;
    }
    return *slot;
}

const std::vector<float>& Evaluator::mapTexelBand() {
    constexpr std::size_t kMaxBands = 8;  // a view's lessons: a few map sizes
    const Renderer& r = *renderer_;
    reference();
    std::string key = std::to_string(r.stats.mapSize);
    for (int c = 0; c < 4; ++c)
        for (int k = 0; k < 4; ++k) key += "," + exactText(r.stats.lightViewProjection[c][k]);
    auto found = truth_->bands.find(key);
    if (found != truth_->bands.end()) return found->second;
    if (truth_->bands.size() >= kMaxBands) truth_->bands.clear();
    return truth_->bands[key] = mapTexelOnScreen(truth_->reference, r.camera,
                                                 r.stats.lightViewProjection, r.stats.mapSize);
}

namespace {

// The baseline for "dark without a caster" is our lighting without its highlight: ambient and
// diffuse are what every lit pass must keep, while the highlight's size and shape are a choice
// (a student's Blinn-Phong with a sharper exponent is lit correctly, yet darker than our broad
// highlight: counted as dark without a caster, 1.5 % false shadow, before this).
Scene withoutHighlight(Scene scene) {
    scene.material.specular = 0.0f;
    return scene;
}

}  // namespace

Renderer& Evaluator::shippedRenderer(Shipped kind) {
    std::unique_ptr<Renderer>& slot = shipped_[static_cast<int>(kind)];
    if (!slot) {
        Renderer& r = *renderer_;
        GlslTree tree = r.shaders().tree();
        Scene scene = kind == Shipped::Ids             ? idColouredScene(r.scene())
                      : kind == Shipped::Unhighlighted ? withoutHighlight(r.scene())
                                                       : r.scene();
        slot = std::make_unique<Renderer>(std::move(scene),
                                          ShaderLibrary(tree, shaderTreeRoot(tree), ""),
                                          context_->height(), stageInfos());
    }
    return *slot;
}

Image Evaluator::renderWith(Renderer& other, const std::string& stage) {
    const Renderer& r = *renderer_;
    other.selectStage(stage);
    other.camera = r.camera;
    other.lightPosition = r.lightPosition;
    other.view = ViewMode::Final;
    other.allLit = false;
    other.render(context_->framebuffer(), context_->width(), context_->height());
    return context_->read();
}

// The mirror (GUIDE section 4). Around it the stage is graded like any lit pass (its shadows
// and its lighting); inside it, its picture against the exact stencil reflection drawn with our
// shipped shaders, and our shipped shaders' id picture against the reference's bounce. Nothing
// is measured against the submission's own renders: a tint after the branch, a lit pass without
// shadows or a shader that recognises an id render would otherwise agree with itself.
Accuracy Evaluator::mirrorAccuracy() {
    Renderer& r = *renderer_;
    const ReferenceImage& ref = reference();
    std::vector<std::uint8_t> mask = mirrorMask(ref, r.scene());
    const ShadowEvidence e = shadowEvidence();
    Accuracy a = shadowAccuracy(e.figures);
    const Image& shown = e.withShadows;  // the stage as it is, mirror included
    auto ours = [&](Shipped kind, const std::string& method) {
        Renderer& other = shippedRenderer(kind);
        other.selectStage(r.stage().id);
        other.params() = r.params();
        other.params().set("mirror-method", method);
        return renderWith(other, r.stage().id);
    };
    Image stencil = ours(Shipped::Lit, "stencil");
    // Our id picture is drawn by the stage's own method, unless our trees are the student
    // edition, whose texture path (the mirror's surface shaders) is a stub: then by the exact
    // reflection, which its stubs keep. Either way it does not depend on the submission.
    std::string idMethod = isStudentEdition(r.shaders().tree()) ? std::string("stencil")
                                                                : r.params().text("mirror-method");
    std::vector<int> seen =
        decodeIdImage(ours(Shipped::Ids, idMethod), mirrorId(r.scene()) - 1, kMirrorReflectance);
    a.mirrorIdPct = mirrorIdAgreementPct(ref, seen);
    a.mirrorPsnrDb = psnrInMask(shown, stencil, mask);
    a.errorPct = 100.0 - a.mirrorIdPct;
    mirrorPictures_ = {shown, std::move(stencil), std::move(mask)};
    return a;
}

}  // namespace sl
