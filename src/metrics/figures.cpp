#include "metrics/figures.h"

namespace sl {

const std::vector<FigureInfo>& figureTable() {
    using B = Better;
    using K = FigureKind;
    static const std::vector<FigureInfo> table = {
        {"false_shadow_pct", &Accuracy::falseShadowPct, "%", B::Lower, K::Shadow,
         "the surfaces the light reaches drawn in shadow"},
        {"false_lit_pct", &Accuracy::falseLitPct, "%", B::Lower, K::Shadow,
         "the true shadows drawn lit"},
        {"false_shadow_band_pct", &Accuracy::falseShadowBandPct, "%", B::Lower, K::Shadow,
         "false shadow near the shadow edges"},
        {"false_lit_band_pct", &Accuracy::falseLitBandPct, "%", B::Lower, K::Shadow,
         "false light near the shadow edges"},
        {"edge_mean_px", &Accuracy::edgeMeanPx, "px", B::Lower, K::Shadow,
         "the mean distance of your shadow edges from the truth"},
        {"edge_p95_px", &Accuracy::edgeP95Px, "px", B::Lower, K::Shadow,
         "the distance within which 95 % of your shadow edges lie"},
        {"mirror_id_pct", &Accuracy::mirrorIdPct, "%", B::Higher, K::Mirror,
         "the mirror showing the right object"},
        {"mirror_psnr_db", &Accuracy::mirrorPsnrDb, "dB", B::Higher, K::Mirror,
         "your mirror's PSNR against the exact (stencil) reflection"},
        {"dark_without_caster_pct", &Accuracy::darkWithoutCasterPct, "%", B::Lower, K::Look,
         "the picture drawn dark where nothing casts a shadow"},
        {"false_shadow_speckle_pct", &Accuracy::falseShadowSpecklePct, "%", B::Lower, K::Look,
         "speckled false shadow (acne)"},
        {"shadow_level_off_pct", &Accuracy::shadowLevelOffPct, "%", B::Lower, K::Look,
         "the shadows at the wrong darkness"},
        {"lit_light_lost_pct", &Accuracy::litLightLostPct, "%", B::Lower, K::Look,
         "the lit surfaces that lost light"},
        {"lit_too_bright_pct", &Accuracy::litTooBrightPct, "%", B::Lower, K::Look,
         "the lit surfaces drawn too bright", /*inEveryRecord*/ false},
    };
    return table;
}

const FigureInfo* findFigure(const std::string& name) {
    for (const FigureInfo& f : figureTable())
        if (name == f.name) return &f;
    return nullptr;
}

std::vector<std::string> figureNamesOf(FigureKind kind) {
    std::vector<std::string> names;
    for (const FigureInfo& f : figureTable())
        if (f.kind == kind) names.push_back(f.name);
    return names;
}

}  // namespace sl
