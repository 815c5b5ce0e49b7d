// The lessons `n` steps through: each stage's entries of expectations.json (its defaults
// first), then the lecture's figures of slides_examples/ for that stage (one per variant); which
// one is on screen, which comes next, and the split view's pair.
#include "lecture/lessons.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/data_paths.h"
#include "scene/scene_json.h"
#include "stages/expectations.h"

namespace sl {

namespace {

Sets strings(const nlohmann::json& o) {
    Sets sets;
    if (o.is_object())
        for (const auto& [k, v] : o.items())
            if (v.is_string()) sets.emplace_back(k, v.get<std::string>());
    return sets;
}

// slides_examples' "figure": {"p1": [x, z], ...}; false when it is not one.
bool readPoint(const nlohmann::json& figure, const char* name, glm::vec2& out) {
    if (!figure.contains(name)) return false;
    const auto& p = figure[name];
    if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number()) return false;
    out = {p[0].get<float>(), p[1].get<float>()};
    return true;
}

}  // namespace

std::vector<WindowLesson> windowLessons() {
    std::vector<WindowLesson> lessons;
    for (const Expectation& e : expectations()) {
        WindowLesson l{e.stage, e.scene, e.trees, e.set, e.label() + ": " + e.outcome, e.look};
        lessons.push_back(l);
    }
    namespace fs = std::filesystem;
    std::vector<fs::path> files;
    std::error_code error;
    for (const auto& f : fs::directory_iterator(dataDir() + "/slides_examples", error))
        if (f.path().extension() == ".json") files.push_back(f.path());
    std::sort(files.begin(), files.end());
    for (const auto& path : files) {
        std::ifstream in(path);
        nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
        if (!j.is_object() || !j.contains("stage") || !j["stage"].is_string()) continue;
        WindowLesson l;
        l.stage = j["stage"];
        l.scene = j.value("scene", "");
        if (j.contains("glsl") && j["glsl"].is_string()) l.trees = {j["glsl"]};
        if (j.contains("view") && j["view"].is_string()) parseView(j["view"], l.view);
        if (j.contains("comment") && j["comment"].is_array() && !j["comment"].empty() &&
            j["comment"].back().is_string())
            l.look = j["comment"].back();
        if (j.contains("figure") && j["figure"].is_object()) {
            const auto& f = j["figure"];
            l.topView = readPoint(f, "p1", l.p1) && readPoint(f, "p2", l.p2) &&
                        readPoint(f, "eye", l.eye) && readPoint(f, "at", l.at);
        }
        const std::string name = "figure " + path.stem().string();
        if (j.contains("variants") && j["variants"].is_array()) {
            for (const auto& v : j["variants"]) {
                WindowLesson variant = l;
                variant.name = name + " " + v.value("label", "");
                variant.sets = strings(v.value("parameters", nlohmann::json()));
                lessons.push_back(variant);
            }
        } else {
            l.name = name;
            l.sets = strings(j.value("parameters", nlohmann::json()));
            lessons.push_back(l);
        }
    }
    return lessons;
}

std::vector<const WindowLesson*> lessonsOf(const std::vector<WindowLesson>& all,
                                           const std::string& stage, const std::string& tree) {
    std::vector<const WindowLesson*> list;
    for (const WindowLesson& l : all)
        if (l.stage == stage &&
            (l.trees.empty() || std::find(l.trees.begin(), l.trees.end(), tree) != l.trees.end()))
            list.push_back(&l);
    return list;
}

Sets nonDefault(const ParamSet& params) {
    Sets sets;
    for (const ParamSpec& p : params.specs())
        if (params.text(p.name) != p.defaultText()) sets.emplace_back(p.name, params.text(p.name));
    return sets;
}

void applySets(ParamSet& params, const Sets& sets) {
    for (const ParamSpec& p : params.specs()) params.set(p.name, p.defaultText());
    for (const auto& [name, value] : sets) params.set(name, value);
}

int matchingLesson(const LessonChoice& lessons, const OnScreenSettings& now) {
    const auto& list = lessons.list;
    const Sets values = nonDefault(*now.values);
    auto matches = [&](const WindowLesson& l) {
        ParamSet p(now.values->specs());
        applySets(p, l.sets);
        const std::string& scene = l.scene.empty() ? now.stageScene : l.scene;
        return nonDefault(p) == values && scene == now.scene && l.view == now.view;
    };
    if (lessons.chosen < list.size() && matches(*list[lessons.chosen])) return int(lessons.chosen);
    for (std::size_t k = 0; k < list.size(); ++k)
        if (matches(*list[k])) return int(k);
    return -1;
}

std::size_t nextLessonIndex(const LessonChoice& lessons, int shown) {
    if (lessons.list.empty()) return 0;
    return (shown >= 0 ? std::size_t(shown) + 1 : lessons.chosen + 1) % lessons.list.size();
}

std::string lessonLine(const LessonChoice& lessons, int shown) {
    const auto& list = lessons.list;
    if (list.empty()) return "";
    if (shown < 0) return noLessonText(list.size());
    return lessonText(*list[std::size_t(shown)], std::size_t(shown), list.size());
}

std::string noLessonText(std::size_t lessons) {
    return "the settings on screen are none of the " + std::to_string(lessons) +
           " lessons (n: the next lesson, x: the defaults)";
}

std::string lessonText(const WindowLesson& l, std::size_t k, std::size_t of) {
    std::string line =
        "lesson " + std::to_string(k + 1) + "/" + std::to_string(of) + " (n): " + l.name;
    if (!l.look.empty()) line += ". Look for: " + l.look;
    return line;
}

std::vector<SplitHalf> splitHalves(const ParamSet& values, const LessonChoice& lessons, int shown) {
    if (const ParamSpec* method = values.find("mirror-method")) {
        std::vector<SplitHalf> halves;
        for (const auto& choice : method->choices)
            halves.push_back({"mirror-method=" + choice, {{"mirror-method", choice}}});
        if (halves.size() >= 2) halves.resize(2);
        return halves;
    }
    const auto& list = lessons.list;
    if (list.size() < 2) return {};
    const std::size_t k = (shown >= 0 ? std::size_t(shown) : lessons.chosen) % list.size();
    for (std::size_t step = 1; step < list.size(); ++step) {
        const WindowLesson& next = *list[(k + step) % list.size()];
        if (next.scene == list[k]->scene && next.view == list[k]->view && !next.topView)
            return {{list[k]->name, list[k]->sets}, {next.name, next.sets}};
    }
    return {};
}

std::string splitLabel(std::size_t k, const SplitHalf& half) {
    return (k == 0 ? "left: " : "right: ") + half.name;
}

}  // namespace sl
