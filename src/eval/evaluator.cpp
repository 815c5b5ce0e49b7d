#include "eval/evaluator.h"

#include <sstream>

#include "metrics/mirror_metrics.h"
#include "metrics/shadow_metrics.h"

namespace sl {

Renderer& Evaluator::prepare(const RenderRequest& request) {
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
        << "/fovy=" << (r.fovy ? std::to_string(*r.fovy) : "")
        << "/displaced=" << (r.displaceSeed ? std::to_string(*r.displaceSeed) : "");
    if (key.str() != key_) {
        reset();
        context_ = createHeadlessContext(backend_, r.tree, r.width, r.height);
        installGlDebugOutput(
            true);  // a GL error is caught in the draw that raised it (whose shader)
        renderer_ = makeRenderer(r);
        sceneLight_ = renderer_->scene().light.position;
        key_ = key.str();
        sceneKey_ = r.scene + "/" + std::to_string(r.width) + "x" + std::to_string(r.height);
    }
    renderer_->selectStage(r.stage);
    renderer_->params() = ParamSet(renderer_->stage().params);
    renderer_->lightPosition = sceneLight_;
    renderer_->allLit = false;
    applyRequest(*renderer_, r);
    return *renderer_;
}

void Evaluator::reset() {
    for (auto& r : shipped_) r.reset();  // the renderers' GL objects go before the context
    renderer_.reset();
    context_.reset();
    key_.clear();
    referenceKey_.clear();
    truth_.reset();
}

const ReferenceImage& Evaluator::reference() {
    Renderer& r = *renderer_;
    std::ostringstream key;
    auto put = [&](const glm::vec3& v) { key << "/" << v.x << "," << v.y << "," << v.z; };
    key << sceneKey_ << "/" << r.camera.fovyDegrees;
    for (const glm::vec3& v : {r.lightPosition, r.camera.eye, r.camera.at}) put(v);
    if (!truth_ || key.str() != referenceKey_) {
        referenceKey_ = key.str();
        auto found = truths_.find(referenceKey_);
        if (found != truths_.end()) {
            truth_ = found->second;
        } else {
            truth_ = std::make_shared<Truth>();
            truth_->reference = traceReference(r.scene(), r.camera, r.lightPosition,
                                               context_->width(), context_->height());
            ++traced_;
            if (truthOrder_.size() >= kMaxTruths) {
                truths_.erase(truthOrder_.front());
                truthOrder_.erase(truthOrder_.begin());
            }
            truths_[referenceKey_] = truth_;
            truthOrder_.push_back(referenceKey_);
        }
    }
    return truth_->reference;
}

const ReferenceShades& Evaluator::shades() {
    reference();
    if (!truth_->shaded) {
        Renderer& r = *renderer_;
        truth_->shades = referenceShades(r.scene(), r.camera, truth_->reference, r.lightPosition);
        truth_->visible = shadowVisiblePixels(truth_->shades);
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
    if (renderer_->stage().id == "mirror") return mirrorAccuracy();
    return shadowAccuracy(shadowEvidence().figures);
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
    const std::string& unshadowed = r.stage().unshadowedStage;
    e.baseline = unshadowed.empty()
                     ? e.allLit
                     : renderWith(shippedRenderer(Shipped::Unhighlighted), unshadowed);
    e.renderedIds = decodeIdImage(renderWith(shippedRenderer(Shipped::Ids), "phong"),
                                  int(r.scene().objects.size()), 1.0f);
    ShadowFigureInputs inputs;
    inputs.renderedIds = e.renderedIds;
    inputs.shadowVisible = shadowVisible();
    if (tolerance_ == EdgeTolerance::MapTexel)
        inputs.bandPx =
            mapTexelOnScreen(ref, r.camera, r.stats.lightViewProjection, r.stats.mapSize);
    inputs.darkWithoutCaster = classifyShadowed(e.allLit, e.baseline);
    // Bounded from above too: clearly brighter than our lighting with its highlight is as wrong
    // as darker (flat white, a flat colour, infinities written to an 8-bit target).
    inputs.litTooBright =
        classifyShadowed(renderWith(shippedRenderer(Shipped::Lit), "phong"), e.allLit);
    e.shadowed = classifyShadowed(e.withShadows, e.allLit);
    for (std::size_t k = 0; k < e.shadowed.size(); ++k)
        e.shadowed[k] = e.shadowed[k] || inputs.darkWithoutCaster[k];
    inputs.shadowLevelOff = shadowLevelOff(e.withShadows, e.allLit, shades());
    inputs.lightLost = lightLost(e.withShadows, e.allLit, shades());
    e.figures = shadowFigures(ref, e.shadowed, inputs);
    return e;
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
        slot = std::make_unique<Renderer>(
            std::move(scene), ShaderLibrary(tree, shaderTreeRoot(tree), ""), context_->height());
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
    int w = context_->width(), h = context_->height();
    const ReferenceImage& ref = reference();
    std::vector<std::uint8_t> mask = mirrorMask(ref, r.scene());
    Accuracy a = shadowAccuracy(shadowEvidence().figures);
    r.allLit = false;
    r.render(context_->framebuffer(), w, h);
    Image shown = context_->read();
    auto ours = [&](Shipped kind, const std::string& method) {
        Renderer& other = shippedRenderer(kind);
        other.selectStage(r.stage().id);
        other.params() = r.params();
        other.params().set("mirror-method", method);
        return renderWith(other, r.stage().id);
    };
    Image exact = ours(Shipped::Lit, "stencil");
    std::vector<int> seen = decodeIdImage(ours(Shipped::Ids, r.params().text("mirror-method")),
                                          mirrorId(r.scene()) - 1, kMirrorReflectance);
    a.mirrorIdPct = mirrorIdAgreementPct(ref, seen);
    a.mirrorPsnrDb = psnrInMask(shown, exact, mask);
    a.errorPct = 100.0 - a.mirrorIdPct;
    mirrorPictures_ = {std::move(shown), std::move(exact), std::move(mask)};
    return a;
}

}  // namespace sl
