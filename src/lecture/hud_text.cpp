#include "lecture/hud_text.h"

#include <cctype>

namespace sl {

namespace {
bool isMirror(const StageInfo& s) {
    return s.needsMirror;
}
// Phong draws no shadow map: its visibility view is white everywhere, and says why.
bool offersShadowMap(const StageInfo& s) {
    for (ViewMode v : s.views)
        if (v == ViewMode::ShadowMap) return true;
    return false;
}
}  // namespace

std::string viewLabel(const StageInfo& stage, ViewMode view) {
    if (isMirror(stage) && view == ViewMode::ShadowMap) return "mirror-texture";
    return viewName(view);
}

std::string viewLegend(const StageInfo& stage, ViewMode view) {
    switch (view) {
        case ViewMode::Final:
            return "";
        case ViewMode::ShadowMap:
            if (isMirror(stage))
                return "mirror-texture: what the reflected camera rendered, flipped left-right as "
                       "the "
                       "mirror shows it";
            return "shadow-map: depth seen from the light; black = near the light, white = far "
                   "(or nothing drawn)";
        case ViewMode::Light:
            return "light: the scene as the light sees it (the shadow map's frustum)";
        case ViewMode::Visibility:
            if (!offersShadowMap(stage))
                return "visibility: white = lit, black = in shadow; this stage has no shadow map, "
                       "so "
                       "all of it is white";
            return "visibility: white = lit (the map sees this point), black = in shadow";
        case ViewMode::LightDepth:
            return "light-depth: each point's own depth from the light; black = near, white = far";
    }
    return "";
}

std::string stageTitle(const Renderer& r) {
    return std::to_string(r.stageIndex()) + " " + r.stage().id;
}

std::string compactTitle(Renderer& r, const ParamSet& values, std::size_t selected,
                         const StudentFolder& folder) {
    std::string line = stageTitle(r) + " | " + treeName(r.shaders().tree());
    if (!folder.name.empty())
        line += r.shaders().overlay().empty()
                    ? " (your folder is " + std::string(treeName(folder.tree)) + ")"
                    : ", " + folder.name + " over ours";
    const auto& specs = values.specs();
    if (!specs.empty()) {
        const std::string& name = specs[selected % specs.size()].name;
        line += " | " + name + " = " + values.text(name) + ignoredMark(r, name);
    }
    return line + " | h: keys";
}

std::string ignoredMark(Renderer& r, const std::string& param) {
    std::string uniform;
    for (std::size_t i = 0; i < param.size(); ++i)
        if (param[i] == '-' && i + 1 < param.size())
            uniform += char(std::toupper(static_cast<unsigned char>(param[++i])));
        else
            uniform += param[i];
    return r.shaders().ignoredUniforms(r.stage().id).count(uniform)
               ? " (your shader does not read it)"
               : "";
}

}  // namespace sl
