// The one evaluation path (GUIDE sections 4 and 6): a headless context and a renderer for a
// request, the reference traced for its camera and light, and the figures that compare them.
// `check`, `bench`, `sweep` and `example` all measure through an Evaluator, so a figure means
// the same thing wherever it is printed.
#pragma once

#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "eval/trace_view.h"
#include "metrics/figures.h"  // Accuracy
#include "metrics/shadow_metrics.h"
#include "metrics/shadow_truth.h"
#include "platform/headless.h"
#include "reference/raytracer.h"
#include "stages/request.h"

namespace sl {

// The Accuracy of a shadow stage from its figures (edge figures NaN when undefined).
Accuracy shadowAccuracy(const ShadowFigures& f);

// The two renders and the classification behind a shadow stage's figures (diff images use them).
struct ShadowEvidence {
    Image withShadows, allLit;
    std::vector<std::uint8_t> shadowed;  // see Evaluator::shadowEvidence
    ShadowFigures figures;
};

// Holds a context for the current (backend, tree, size) and a renderer for the current (scene,
// overlay, camera) in it, and rebuilds each only when one of those changes, so a run compiles
// each stage's shaders once per renderer. What follows from a view's truth alone is kept across
// overlays (Truth below): grading a class, a student's row costs two renders and one pass.
class Evaluator {
  public:
    // How far from the true shadow edge a rendered edge may be before it counts as an error.
    // Grading forgives one shadow-map texel as it lands on screen (a method cannot resolve less
    // than its map); comparing methods and map sizes must not: there a coarse map would forgive
    // itself, so the bench and the sweeps measure to the pixel.
    enum class EdgeTolerance { MapTexel, Pixel };

    explicit Evaluator(Backend backend, EdgeTolerance tolerance = EdgeTolerance::MapTexel)
        : backend_(backend), tolerance_(tolerance) {}
    virtual ~Evaluator() = default;
    // Selects the request's stage on a renderer for its tree, scene, size, overlay and camera:
    // parameters start from the defaults, then the request's camera, light, view and --set
    // values apply.
    Renderer& prepare(const RenderRequest& request);
    // Drops the context and renderers, e.g. after a shader error left the GL state unknown.
    void reset();
    HeadlessContext& context() { return *context_; }
    // Whether the context it draws in was lost (the browser's WebGL: HeadlessContext::lost()).
    bool contextLost() const { return context_ && context_->lost(); }
    Renderer& renderer() { return *renderer_; }

    // Renders the current configuration and compares it with the reference: the shadow stages'
    // figures, or the mirror's. Our own shaders' (no overlay) are kept by configuration.
    Accuracy accuracy();
    // The reference for the current camera, light and size (traced once, then reused).
    const ReferenceImage& reference();
    // Where a shadow could be seen at all for the current reference (shadowVisiblePixels).
    const std::vector<std::uint8_t>& shadowVisible();
    // The reference's own shading, lit and blocked (referenceShades), for the current view.
    const ReferenceShades& shades();
    // How many references this evaluator traced (a class should trace each view once), and how
    // many times it drew our shipped shaders' pictures of a view (ids, lighting: once a view).
    int tracedCount() const { return traced_; }
    // A reference traced elsewhere (the page's Web Workers: eval/trace_view.h), kept under its
    // view's key until reference() needs it: then it is used instead of tracing here.
    void giveReference(const std::string& key, ReferenceImage reference);
    // The key reference() looks the current view up by (traceKey of its view).
    std::string currentTraceKey() const;
    int givenUsedCount() const { return givenUsed_; }
    void dropGiven() { given_.clear(); }
    // Whether the view under `key` is traced or given already; a traced one becomes the last
    // the Evaluator lets go (a stage about to use it must not lose it to the views it is given).
    bool keepReference(const std::string& key);
    int shippedViewCount() const { return shippedViews_; }
    // How many times accuracy() measured our own shaders (no overlay): once a configuration.
    int oursMeasuredCount() const { return oursMeasured_; }
    // The shadow stages' half of accuracy(): the render with its map and with the map forced to
    // "everything lit", our own unshadowed lighting (phong) and an id render for coverage. A
    // pixel is shadowed where the render is clearly darker than the all-lit one, or the all-lit
    // one clearly darker than our lighting (dark without a caster).
    ShadowEvidence shadowEvidence();
    // The pictures behind the last mirror figures (accuracy() of the mirror stage): the
    // submission's render, our exact stencil reflection and where the mirror is, so a feedback
    // page can show a student what their mirror got wrong.
    struct MirrorPictures {
        Image shown, exact;
        std::vector<std::uint8_t> mask;
    };
    const MirrorPictures& mirrorPictures() const { return mirrorPictures_; }

  private:
    // What the figures of a view take from our shipped shaders and the truth, whoever's shaders
    // are measured: the luma of our lighting without shadows (empty where the stage's all-lit
    // render is its own baseline) and with its highlight, and the truth's half of the figures
    // (its evaluated pixels come from our id render).
    struct ShippedView {
        std::vector<float> baselineLuma, oursLuma;
        ShadowTruth truth;
    };
    const ShippedView& shippedView();
    // mapTexelOnScreen for the current view and the light view-projection and map size of the
    // last render (they depend on the lesson's settings, not on the shaders measured).
    const std::vector<float>& mapTexelBand();
    Accuracy mirrorAccuracy();
    // A renderer over the current scene with our shipped shaders only: what the stage's picture
    // is measured against, whatever the overlay does. Unhighlighted: the scene without its
    // highlight (the least light a lit surface keeps); Lit: as it is; Ids: in id colours.
    enum class Shipped { Unhighlighted, Lit, Ids };
    Renderer& shippedRenderer(Shipped kind);
    Image renderWith(Renderer& r, const std::string& stage);

    Backend backend_;
    EdgeTolerance tolerance_;
    std::string contextKey_, key_;
    std::string overlay_;                   // the current renderer's
    std::map<std::string, Accuracy> ours_;  // accuracy() of our shaders, by configuration
    std::unique_ptr<HeadlessContext> context_;
    std::unique_ptr<Renderer> renderer_;
    std::unique_ptr<Renderer> shipped_[3];  // by Shipped
    glm::vec3 sceneLight_{0};
    MirrorPictures mirrorPictures_;
    // The references of the views seen so far and what follows from them alone, kept across
    // overlays and shader errors (a reference depends on the scene, its displacement, the size,
    // camera and light only): grading a class in one evaluator traces and measures each view's
    // truth once. Bounded (kMaxTruths, fewer where they would take more than a quarter of the
    // worker's memory: maxTruths; oldest dropped first).
    struct Truth {
        ReferenceImage reference;
        bool shaded = false;
        ReferenceShades shades;  // the reference's shading lit and blocked
        std::vector<std::uint8_t> visible;
        ShadeShares shares;
        // By backend, tree and unshadowed stage (our renders of the view).
        std::map<std::string, std::shared_ptr<ShippedView>> shipped;
        // By light view-projection and map size (mapTexelBand).
        std::map<std::string, std::vector<float>> bands;
    };
    static constexpr std::size_t kMaxTruths = 8;
    static std::size_t maxTruths(int width, int height);
    TraceView sceneView_;  // scene, seed and size of the current renderer (camera, light: later)
    std::map<std::string, ReferenceImage> given_;  // giveReference's, not yet used
    std::map<std::string, std::shared_ptr<Truth>> truths_;
    std::vector<std::string> truthOrder_;
    std::string referenceKey_;
    std::shared_ptr<Truth> truth_;  // the current view's
    int traced_ = 0;
    int givenUsed_ = 0;
    int shippedViews_ = 0;
    int oursMeasured_ = 0;
};

}  // namespace sl
