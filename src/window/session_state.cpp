// What the session tells outside: the PNGs `p` saves, and the state a test reads (--state).
#include <cmath>
#include <filesystem>
#include <iostream>

#include "io/png.h"
#include "window/session.h"
#include "window/window_text.h"

namespace sl {

namespace {

double secondsOf(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(t.time_since_epoch()).count();
}

}  // namespace

Image WindowSession::readPixels() const {
    Image img(width_, height_);
    std::vector<std::uint8_t> bottomUp(img.rgba.size());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
    std::size_t row = std::size_t(width_) * 4;
    for (int j = 0; j < height_; ++j)
        std::copy_n(&bottomUp[std::size_t(height_ - 1 - j) * row], row,
                    &img.rgba[std::size_t(j) * row]);
    return img;
}

// The picture is read back at once; compressing and writing it (a second or two for a full
// screen) happens on a thread of its own, and the window says "saved" once it is done.
void WindowSession::saveShot() {
    Renderer& r = renderer();
    if (width_ <= 0 || height_ <= 0) {
        complain("p: the window has no pixels to save (minimised?)");
        return;
    }
    namespace fs = std::filesystem;
    std::string path;
    try {
        fs::create_directories(args_.shots);
        auto now = std::chrono::system_clock::now();
        auto ms =
            std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count();
        std::string name =
            shotFileName(r.stage().id, treeName(r.shaders().tree()), viewLabel(r.stage(), r.view),
                         std::chrono::system_clock::to_time_t(now), static_cast<int>(ms % 1000));
        path = (fs::absolute(args_.shots) / name).lexically_normal().string();
    } catch (const std::exception& e) {
        shotSaid(path, e.what());
        return;
    }
    Image picture = pictureAlone(width_, height_);
    shotsPaths_.push_back(path);
    shotsWriting_.push_back(std::async(std::launch::async, [path, picture = std::move(picture)] {
        return writePng(path, picture);
    }));
}

void WindowSession::shotSaid(const std::string& path, const std::string& error) {
    if (!error.empty()) {  // shown and reported; the session goes on and its exit code stays
        complain("p: could not save into '" + args_.shots + "': " + error);
        return;
    }
    std::cout << "saved " << path << std::endl;
    flash("saved " + path, false);
}

void WindowSession::finishShots() {
    for (std::size_t k = 0; k < shotsWriting_.size(); ++k)
        shotSaid(shotsPaths_[k], shotsWriting_[k].get());
    shotsWriting_.clear();
    shotsPaths_.clear();
}

nlohmann::json WindowSession::state() const {
    Renderer& r = renderer();
    nlohmann::json j;
    j["stage"] = r.stage().id;
    j["index"] = r.stageIndex();
    j["tree"] = treeName(r.shaders().tree());
    j["sessionTree"] = treeName(tree_);
    j["scene"] = scene_;
    j["view"] = viewLabel(r.stage(), r.view);
    j["hud"] = hudMode_ == HudMode::Full      ? "full"
               : hudMode_ == HudMode::Compact ? "compact"
                                              : "hidden";
    const std::vector<std::string> errors = shownErrors();
    j["errors"] = errors.size();
    j["error"] = errors.empty() ? "" : oneLine(errors[0]);
    j["trying"] = watchdog_->busy(onScreen(), tree_);  // a trial runs, or waits to start
    j["tryingValues"] = !valuesLine().empty();
    // "stage", "trying" (nothing of the files drew yet), "none" (no good program: the reason
    // shows), "help" (the keys in its place)
    j["picture"] = pictureShows_;
    j["drawn"] = drawnFrames_;
    j["message"] = flash_;
    j["animating"] = animateLight_;
    j["lightAngle"] = std::atan2(r.lightPosition.z, r.lightPosition.x);  // radians, around y
    const auto& specs = r.params().specs();
    j["param"] = specs.empty() ? "" : specs[selectedParam_ % specs.size()].name;
    j["value"] = specs.empty() ? "" : r.params().text(j["param"].get<std::string>());
    j["help"] = showHelp_;
    j["lesson"] = lessonLine();
    j["eye"] = {r.camera.eye.x, r.camera.eye.y, r.camera.eye.z};
    j["at"] = {r.camera.at.x, r.camera.at.y, r.camera.at.z};
    j["eyeDistance"] = glm::length(r.camera.eye - r.camera.at);
    j["split"] = nlohmann::json::array();
    if (split_)
        for (const SplitHalf& h : splitHalves()) j["split"].push_back(h.name);
    for (const ParamSpec& p : specs) j["params"][p.name] = r.params().text(p.name);
    for (const ParamSpec& p : specs)
        if (!ignoredMark(p.name).empty()) j["ignored"].push_back(p.name);
    j["width"] = width_;
    j["height"] = height_;
    j["pictureTop"] = bands_.first;  // window rows above the picture (the top panels' band)
    j["pictureHeight"] = pictureArea_.height;
    auto rect = [&](const Rect& a) {  // window pixels, from the top-left corner
        return nlohmann::json{a.x, height_ - a.y - a.height, a.width, a.height};
    };
    j["pictureRect"] = rect(pictureArea_);
    j["halves"] = nlohmann::json::array();
    for (const Rect& h : halfAreas_) j["halves"].push_back(rect(h));
    j["halvesShow"] = halvesShow_;  // what each half shows: "stage", "trying", "none", "top-view"
    j["topViewLabels"] = nlohmann::json::array();  // each label's box, text padding included
    const int areaTop = height_ - topViewArea_.y - topViewArea_.height;
    for (const TopViewLayout::Label& l : topViewLabels_) {
        const LabelBox& b = l.place.box;
        j["topViewLabels"].push_back(
            {{"text", l.text},
             {"shown", !l.place.placed ? ""
                       : l.place.key   ? l.key
                                       : l.text},
             {"box", {topViewArea_.x + b.x, areaTop + b.y, b.width, b.height}}});
    }
    j["drawnWith"] = nlohmann::json::object();  // the values the picture on screen drew with
    for (const auto& [name, value] : drawnWith_) j["drawnWith"][name] = value;
    j["textScale"] = textScale(width_, height_);
    j["hudText"] = hudText_;    // every line the panels and a page show, as drawn
    j["pageText"] = pageText_;  // the lines of a page in the picture's place (help, an error)
    j["drawMs"] = drawMs_;
    j["idleDrawMs"] = idleDrawMs_;  // the last frame drawn while no trial ran
    // The trials: what runs, what ran (the last ones), and the budget rule.
    j["trial"] = {{"running", watchdog_->running()}, {"count", watchdog_->triedCount()}};
    j["trials"] = nlohmann::json::array();
    for (const Watchdog::Tried& t : watchdog_->tried()) {
        nlohmann::json sets = nlohmann::json::object();
        for (const auto& [name, value] : t.sets) sets[name] = value;
        j["trials"].push_back({{"tree", t.tree},
                               {"stage", t.stage},
                               {"what", t.what},
                               {"sets", sets},
                               {"verdict", t.verdict},
                               {"cpu", t.cpuSeconds},
                               {"budget", t.budgetSeconds},
                               {"ours", t.oursSeconds},
                               {"startedAt", t.startedAt},
                               {"endedAt", t.endedAt}});
    }
    j["folder"] = request_.overlay;
    j["now"] = secondsOf(Clock::now());
    return j;
}

}  // namespace sl
