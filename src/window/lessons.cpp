// The lessons `n` steps through: each stage's entries of expectations.json (its defaults
// first), then the lecture's figures of slides_examples/ for that stage (one per variant).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/data_paths.h"
#include "scene/scene_json.h"
#include "stages/expectations.h"
#include "window/window_args.h"

namespace sl {

namespace {

std::vector<std::pair<std::string, std::string>> strings(const nlohmann::json& o) {
    std::vector<std::pair<std::string, std::string>> sets;
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

}  // namespace sl
