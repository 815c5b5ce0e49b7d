#include "web/split_view.h"

#include "math/orbit.h"
#include "platform/framebuffer_target.h"

namespace sl::web {

void drawSplitHalves(Renderer& r, int width, int height, const std::vector<SplitHalf>& halves) {
    struct Restore {  // the values and camera on screen, whatever a half throws
        Renderer& r;
        const ParamSet params;
        const Camera camera;
        ~Restore() {
            r.params() = params;
            r.camera = camera;
            r.sceneChanged();
        }
    } restore{r, r.params(), r.camera};
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    for (std::size_t k = 0; k < halves.size() && k < 2; ++k) {
        const int x = int(k) * (width / 2), w = k == 0 ? width / 2 : width - width / 2;
        FramebufferTarget target = createFramebufferTarget(w, height, "a split half");
        applySets(r.params(), halves[k].sets);
        r.sceneChanged();  // another shadow map: no cached one carries over
        r.camera.fovyDegrees =
            fovyFittingWidth(restore.camera.fovyDegrees, float(w) / float(height));
        r.render(target.fbo.id(), w, height);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, target.fbo.id());
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        glBlitFramebuffer(0, 0, w, height, x, 0, x + w, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
}

std::string splitSetsText(const std::vector<SplitHalf>& halves) {
    std::string text;
    for (const SplitHalf& half : halves) {
        text += half.name + "\t";
        for (std::size_t k = 0; k < half.sets.size(); ++k)
            text += (k ? "," : "") + half.sets[k].first + "=" + half.sets[k].second;
        text += "\n";
    }
    return text;
}

std::string hudText(Renderer& r, std::size_t selected, const StudentFolder& folder,
                    const std::string& lesson, const std::vector<SplitHalf>& halves) {
    std::string text = "top\t" + compactTitle(r, r.params(), selected, folder) + "\n";
    if (!lesson.empty()) text += "top\t" + lesson + "\n";
    for (std::size_t k = 0; k < halves.size() && k < 2; ++k)
        text += std::string(k == 0 ? "left" : "right") + "\t" + splitLabel(k, halves[k]) + "\n";
    const std::string legend = viewLegend(r.stage(), r.view);
    if (!legend.empty()) text += "bottom\t" + legend + "\n";
    return text;
}

}  // namespace sl::web
