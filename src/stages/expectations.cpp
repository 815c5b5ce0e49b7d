#include "stages/expectations.h"

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "io/data_paths.h"
#include "metrics/figures.h"
#include "scene/scene_json.h"
#include "stages/registry.h"
#include "stages/stage.h"

namespace sl {

namespace {

using nlohmann::json;

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    return text;
}

std::vector<std::string> treesOf(const StageInfo& info) {
    if (info.legacyOnly) return {"legacy"};
    return {"core", "legacy"};
}

bool coversTree(const Expectation& e, const std::string& tree) {
    if (e.trees.empty()) return true;
    for (const auto& t : e.trees)
        if (t == tree) return true;
    return false;
}

bool isDefaultsEntry(const Expectation& e) {
    return e.scene.empty() && e.set.empty();
}

// The entry's settings applied to the stage's defaults; throws with `where` on a bad setting.
ParamSet settingsOf(const Expectation& e, const std::string& where) {
    const StageInfo* info = findStage(e.stage);
    ParamSet values(info->params);
    for (const auto& [name, value] : e.set) {
        std::string err = values.set(name, value);
        if (!err.empty())
            throw ExpectationError(where + ": set " + name + "=" + value + ": " + err);
    }
    return values;
}

bool sameValues(const ParamSet& a, const ParamSet& b) {
    for (const ParamSpec& p : a.specs())
        if (a.text(p.name) != b.text(p.name)) return false;
    return true;
}

// "slope", "lab-factor-40": lower-case letters and digits, words joined by single '-'.
bool isIdText(const std::string& id) {
    if (id.empty() || id.front() == '-' || id.back() == '-') return false;
    for (std::size_t k = 0; k < id.size(); ++k) {
        const char c = id[k];
        bool ok =
            (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || (c == '-' && id[k - 1] != '-');
        if (!ok) return false;
    }
    return true;
}

// Two entries of one stage with the same id: a kept record could not tell which it meant.
void refuseDuplicateIds(const std::vector<Expectation>& book, const std::string& origin) {
    for (std::size_t k = 0; k < book.size(); ++k)
        for (std::size_t j = 0; j < k; ++j)
            if (book[j].stage == book[k].stage && book[j].id == book[k].id)
                throw ExpectationError(origin + ": expectations[" + std::to_string(k) +
                                       "]: the id '" + book[k].id + "' of stage " + book[k].stage +
                                       " is taken by expectations[" + std::to_string(j) + "]");
}

Expectation parseEntry(const json& j, const std::string& where) {
    auto fail = [&](const std::string& what) { throw ExpectationError(where + ": " + what); };
    if (!j.is_object()) fail("an entry must be an object");
    static const std::vector<std::string> known = {"stage",   "id",  "scene",  "trees",    "set",
                                                   "outcome", "why", "limits", "measured", "look"};
    for (const auto& [key, value] : j.items()) {
        bool ok = false;
        for (const auto& k : known) ok = ok || k == key;
        if (!ok) fail("unknown field '" + key + "'");
    }
    auto text = [&](const char* key, bool required) -> std::string {
        if (!j.contains(key)) {
            if (required) fail(std::string("missing \"") + key + "\"");
            return {};
        }
        if (!j[key].is_string() || j[key].get<std::string>().empty())
            fail(std::string("\"") + key + "\" must be a non-empty string");
        return j[key].get<std::string>();
    };
    Expectation e;
    e.stage = text("stage", true);
    const StageInfo* info = findStage(e.stage);
    if (!info) fail("unknown stage '" + e.stage + "'");
    e.id = text("id", true);
    if (!isIdText(e.id))
        fail("\"id\": '" + e.id + "' must be lower-case letters and digits in words joined by '-'");
    e.scene = text("scene", false);
    e.outcome = text("outcome", true);
    e.why = text("why", true);
    e.look = text("look", false);
    if (j.contains("trees")) {
        if (!j["trees"].is_array() || j["trees"].empty()) fail("\"trees\" must be a list");
        for (const auto& t : j["trees"]) {
            bool allowed = false;
            for (const auto& s : treesOf(*info)) allowed = allowed || (t.is_string() && t == s);
            if (!allowed)
                fail("\"trees\": '" + t.dump() + "' is not a tree stage " + e.stage + " runs in");
            e.trees.push_back(t.get<std::string>());
        }
    }
    if (j.contains("set")) {
        if (!j["set"].is_object()) fail("\"set\" must be an object of NAME: \"VALUE\"");
        for (const auto& [name, value] : j["set"].items()) {
            if (!value.is_string()) fail("set." + name + " must be a string");
            e.set.emplace_back(name, value.get<std::string>());
        }
    }
    if (!j.contains("limits") || !j["limits"].is_object() || j["limits"].empty())
        fail("\"limits\" must be a non-empty object of FIGURE: {\"min\": X, \"max\": Y}");
    for (const auto& [figure, bound] : j["limits"].items()) {
        bool ok = false;
        for (const auto& f : figureNames()) ok = ok || f == figure;
        if (!ok) fail("limits: unknown figure '" + figure + "'");
        Limit l{figure};
        if (!bound.is_object() || bound.empty()) fail("limits." + figure + " must be {min, max}");
        for (const auto& [side, v] : bound.items()) {
            if (!v.is_number()) fail("limits." + figure + "." + side + " must be a number");
            if (side == "min")
                l.min = v.get<double>();
            else if (side == "max")
                l.max = v.get<double>();
            else
                fail("limits." + figure + ": unknown bound '" + side + "' (min, max)");
        }
        e.limits.push_back(l);
    }
    settingsOf(e, where);  // every setting must be a declared parameter with an allowed value
    return e;
}

std::optional<glm::vec3> vec3Of(const json& view, const char* key, const std::string& where) {
    if (!view.contains(key)) return std::nullopt;
    const json& v = view[key];
    if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() ||
        !v[2].is_number())
        throw ExpectationError(where + ": \"" + key + "\" must be [x, y, z]");
    return glm::vec3(v[0].get<float>(), v[1].get<float>(), v[2].get<float>());
}

}  // namespace

std::string readStageData(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw ExpectationError(path + ": cannot be read (set SHADOWLAB_DATA_DIR?)");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string defaultSceneOf(const std::string& stage) {
    const StageInfo* info = findStage(stage);
    return info && !info->defaultScene.empty() ? info->defaultScene : "slides";
}

std::vector<GradingView> parseViews(const std::string& text, const std::string& origin,
                                    const std::string& scene) {
    json doc = json::parse(text, nullptr, false);
    std::vector<GradingView> views;
    if (doc.is_object() && doc.contains("views")) {
        if (!doc["views"].is_object())
            throw ExpectationError(origin + ": \"views\" must be an object SCENE: [views]");
        if (doc["views"].contains(scene)) {
            const json& list = doc["views"][scene];
            if (!list.is_array() || list.empty())
                throw ExpectationError(origin + ": views." + scene + " must be a non-empty list");
            for (std::size_t k = 0; k < list.size(); ++k) {
                std::string where = origin + ": views." + scene + "[" + std::to_string(k) + "]";
                const json& v = list[k];
                if (!v.is_object() || !v.contains("name") || !v["name"].is_string())
                    throw ExpectationError(where + ": needs a \"name\"");
                for (const auto& [key, value] : v.items())
                    if (key != "name" && key != "eye" && key != "at" && key != "light" &&
                        key != "fovy" && key != "why")
                        throw ExpectationError(where + ": unknown field '" + key + "'");
                GradingView view;
                view.name = v["name"].get<std::string>();
                view.eye = vec3Of(v, "eye", where);
                view.at = vec3Of(v, "at", where);
                view.light = vec3Of(v, "light", where);
                if (v.contains("fovy")) {
                    if (!v["fovy"].is_number())
                        throw ExpectationError(where + ": \"fovy\" must be a number");
                    view.fovy = v["fovy"].get<float>();
                }
                if (v.contains("why") && v["why"].is_string()) view.why = v["why"];
                for (const auto& other : views)
                    if (other.name == view.name)
                        throw ExpectationError(where + ": the name '" + view.name + "' is taken");
                views.push_back(view);
            }
        }
    }
    if (views.empty()) views.push_back({"scene", {}, {}, {}, {}, "the scene's own camera"});
    return views;
}

const std::vector<GradingView>& gradingViews(const std::string& scene) {
    static std::map<std::string, std::vector<GradingView>> cache;
    auto found = cache.find(scene);
    if (found == cache.end())
        found = cache
                    .emplace(scene, parseViews(readStageData(expectationsPath()),
                                               expectationsPath(), scene))
                    .first;
    return found->second;
}

std::vector<const Expectation*> lessonsOf(const std::vector<Expectation>& book,
                                          const std::string& stage, const std::string& tree) {
    std::vector<const Expectation*> lessons;
    for (const auto& e : book)
        if (e.stage == stage && coversTree(e, tree) && isDefaultsEntry(e)) lessons.push_back(&e);
    for (const auto& e : book)
        if (e.stage == stage && coversTree(e, tree) && !isDefaultsEntry(e)) lessons.push_back(&e);
    return lessons;
}

const Expectation* expectationById(const std::vector<Expectation>& book, const std::string& stage,
                                   const std::string& id, const std::string& tree) {
    for (const auto& e : book)
        if (e.stage == stage && e.id == id && coversTree(e, tree)) return &e;
    return nullptr;
}

std::string Limit::bound() const {
    if (!std::isnan(min) && !std::isnan(max))
        return "in [" + number(min) + ", " + number(max) + "]";
    if (!std::isnan(min)) return ">= " + number(min);
    return "<= " + number(max);
}

std::string Expectation::label() const {
    std::string text = stage;
    if (!scene.empty()) text += " scene=" + scene;
    for (const auto& [name, value] : set) text += " " + name + "=" + value;
    return text;
}

const std::vector<std::string>& figureNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> all;
        for (const FigureInfo& f : figureTable()) all.push_back(f.name);
        return all;
    }();
    return names;
}

std::vector<Expectation> parseExpectations(const std::string& text, const std::string& origin) {
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::parse_error& e) {
        throw ExpectationError(origin + ": not valid JSON: " + e.what());
    }
    if (!doc.is_object() || !doc.contains("expectations") || !doc["expectations"].is_array())
        throw ExpectationError(origin + ": needs an \"expectations\" list");
    std::vector<Expectation> book;
    for (std::size_t k = 0; k < doc["expectations"].size(); ++k)
        book.push_back(parseEntry(doc["expectations"][k],
                                  origin + ": expectations[" + std::to_string(k) + "]"));
    refuseDuplicateIds(book, origin);
    for (const StageInfo& info : stageRegistry())
        for (const std::string& tree : treesOf(info)) {
            int defaults = 0;
            for (const auto& e : book)
                defaults += e.stage == info.id && isDefaultsEntry(e) && coversTree(e, tree);
            if (defaults != 1)
                throw ExpectationError(
                    origin + ": stage " + info.id + " (" + tree +
                    ") needs one entry for its defaults (no scene, no set), found " +
                    std::to_string(defaults));
        }
    return book;
}

std::string expectationsPath() {
    return dataDir() + "/src/stages/expectations.json";
}

const std::vector<Expectation>& expectations() {
    static const std::vector<Expectation> book =
        parseExpectations(readStageData(expectationsPath()), expectationsPath());
    return book;
}

ExpectationMatch findExpectation(const std::vector<Expectation>& book, const std::string& stage,
                                 const std::string& sceneName, const std::string& tree,
                                 const ParamSet& values) {
    ExpectationMatch match;
    for (const auto& e : book) {
        if (e.stage != stage || !coversTree(e, tree)) continue;
        if (isDefaultsEntry(e) && !match.entry) match.entry = &e;
        std::string scene = e.scene.empty() ? defaultSceneOf(stage) : e.scene;
        if (scene == sceneName && sameValues(settingsOf(e, e.label()), values)) return {&e, true};
    }
    return match;
}

}  // namespace sl
