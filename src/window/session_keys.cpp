// Keys, the mouse and `p`: what each does to the session.
#include <cmath>
#include <filesystem>
#include <iostream>

#include "math/orbit.h"
#include "stages/registry.h"
#include "window/session.h"
#include "window/window_text.h"

namespace sl {

bool WindowSession::key(unsigned char key, bool shift) {
    // Caps Lock or Shift on a letter is the same command (Shift only counts with + and -).
    if (key >= 'A' && key <= 'Z') key = static_cast<unsigned char>(key - 'A' + 'a');
    Renderer& r = renderer();
    const auto& specs = r.params().specs();
    const std::size_t stages = stageRegistry().size();
    switch (key) {
        case '[':
            return selectStage((r.stageIndex() + stages - 1) % stages, tree_);
        case ']':
            return selectStage((r.stageIndex() + 1) % stages, tree_);
        case 'g':
            return selectStage(r.stageIndex(),
                               tree_ == GlslTree::Core ? GlslTree::Legacy : GlslTree::Core);
        case '\t':
            if (!specs.empty())
                selectedParam_ = (selectedParam_ + (shift ? specs.size() - 1 : 1)) % specs.size();
            return true;
        case '+':
        case '=':
        case '-':
        case '_': {
            if (specs.empty()) return false;
            const ParamSpec& p = specs[selectedParam_ % specs.size()];
            int direction = (key == '+' || key == '=') ? 1 : -1;
            int steps = shift && p.kind != ParamKind::Choice ? 10 : 1;  // Shift: tenfold
            for (int k = 0; k < steps; ++k) r.params().step(p.name, direction);
            return true;
        }
        case 's':  // the split view: the lesson's failure beside its fix
            split_ = !split_;
            if (split_ && splitHalves().empty()) {
                split_ = false;
                flash("s: this stage has no second lesson in this scene to show beside it", false);
            }
            return true;
        case 'n':  // the stage's next lesson, its settings applied
            nextLesson();
            return true;
        case 'x':  // the stage's parameters back to their defaults
            applySets(r.params(), {});
            flash("parameters of '" + r.stage().id + "' reset", false);
            return true;
        case 'c':
            r.camera = slot_->homeCamera;
            r.lightPosition = slot_->homeLight;
            animateLight_ = false;
            flash("camera and light reset", false);
            return true;
        case 'r':
            flash("r: the shaders on disk drawn in the trial worker, then rebuilt here", false);
            forceNextAdopt_ = true;
            watchdog_->retry(onScreen());
            return true;
        case 'p':
            saveShot();
            return true;
        case 'h':
            showHelp_ = !showHelp_;
            pageScroll_ = 0;
            return true;
        case 'i':
            hudMode_ = hudMode_ == HudMode::Compact ? HudMode::Full
                       : hudMode_ == HudMode::Full  ? HudMode::Hidden
                                                    : HudMode::Compact;
            hudScroll_ = 0;
            return true;
        case 'l':
            animateLight_ = !animateLight_;
            lastAnimation_ = Clock::now();
            return true;
        case 'v': {
            const auto& views = r.stage().views;
            if (views.size() < 2) {
                flash("v: '" + r.stage().id + "' has one view, the final picture", false);
                return true;
            }
            std::size_t i = 0;
            while (i < views.size() && views[i] != r.view) ++i;
            r.view = views[(i + 1) % views.size()];
            return true;
        }
        default:
            if (key >= '0' && key <= '9')
                return selectStage(static_cast<std::size_t>(key - '0'), tree_);
            return false;
    }
}

bool WindowSession::special(SpecialKey key, bool shift) {
    // An arrow orbits as a drag of 1/16 of the window's width does (about 11 degrees); Up
    // raises the camera (a drag downward does: the scene's far side comes toward the viewer).
    const int step = std::max(1, width_ / 16);
    switch (key) {
        case SpecialKey::Left:
            return drag(-step, 0);
        case SpecialKey::Right:
            return drag(step, 0);
        case SpecialKey::Up:
            return drag(0, step);
        case SpecialKey::Down:
            return drag(0, -step);
        case SpecialKey::PageUp:
            scroll(-1);
            return true;
        case SpecialKey::PageDown:
            scroll(1);
            return true;
        case SpecialKey::Home:
            scroll(-1000);
            return true;
        case SpecialKey::End:
            scroll(1000);
            return true;
        case SpecialKey::Other:
            return false;
    }
    (void)shift;
    return false;
}

// PgUp/PgDn: the help page when it shows, else a page of text in the picture's place, else the
// full panel (the draw clamps what goes past the end).
void WindowSession::scroll(int pages) {
    const bool page = showHelp_ || pictureShows_ == "none";
    int& offset = page ? pageScroll_ : hudScroll_;
    const int lines = std::max(1, page ? pageLines_ : panelLines_);
    offset = std::max(0, offset + pages * lines);
}

bool WindowSession::drag(int dx, int dy) {
    // A drag across the window's width turns the camera half a turn, whatever the window's size
    // (0.01 rad a pixel turned 115 degrees for 200 pixels); up and down at the same rate.
    Renderer& r = renderer();
    const float perPixel = 3.14159265f / float(std::max(1, width_ > 0 ? width_ : request_.width));
    r.camera = orbitCamera(r.camera, -dx * perPixel, dy * perPixel, sceneReceiverHeight(r.scene()));
    return true;
}

bool WindowSession::zoom(int steps) {
    Renderer& r = renderer();
    r.camera = zoomCamera(r.camera, std::pow(0.9f, float(steps)));
    return true;
}

}  // namespace sl
