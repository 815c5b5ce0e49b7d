#include "stages/drawn.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <sstream>

#include "stages/stage.h"

namespace sl {

namespace {

using nlohmann::json;

bool coversTree(const DrawnRow& row, const std::string& tree) {
    if (row.trees.empty()) return true;
    for (const auto& t : row.trees)
        if (t == tree) return true;
    return false;
}

DrawnParam parseDraw(const ParamSpec& spec, const json& v, const std::string& where) {
    DrawnParam d;
    d.name = spec.name;
    if (spec.kind == ParamKind::Choice) {
        if (!v.is_array() || v.size() < 2)
            throw ExpectationError(where + ": a choice is drawn from a list of two or more");
        for (const auto& c : v) {
            bool known = false;
            for (const auto& allowed : spec.choices)
                known = known || (c.is_string() && c == allowed);
            if (!known)
                throw ExpectationError(where + ": '" + c.dump() + "' is not one of " +
                                       spec.rangeText());
            d.choices.push_back(c.get<std::string>());
        }
        return d;
    }
    if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
        throw ExpectationError(where + ": a number is drawn from [min, max]");
    d.min = v[0].get<double>();
    d.max = v[1].get<double>();
    if (!(d.min < d.max) || d.min < spec.min || d.max > spec.max)
        throw ExpectationError(where + ": [min, max] must be increasing within " +
                               spec.rangeText());
    return d;
}

DrawnRow parseRow(const json& j, const std::string& where) {
    auto fail = [&](const std::string& what) { throw ExpectationError(where + ": " + what); };
    if (!j.is_object()) fail("an entry must be an object");
    for (const auto& [key, value] : j.items())
        if (key != "stage" && key != "scene" && key != "trees" && key != "set" && key != "draw" &&
            key != "tolerance" && key != "why" && key != "measured" && key != "response")
            fail("unknown field '" + key + "'");
    DrawnRow row;
    if (!j.contains("stage") || !j["stage"].is_string()) fail("missing \"stage\"");
    row.stage = j["stage"].get<std::string>();
    const StageInfo* info = findStage(row.stage);
    if (!info) fail("unknown stage '" + row.stage + "'");
    if (j.contains("scene")) row.scene = j.value("scene", "");
    if (j.contains("trees")) row.trees = j["trees"].get<std::vector<std::string>>();
    if (!j.contains("why") || !j["why"].is_string()) fail("missing \"why\"");
    row.why = j["why"].get<std::string>();
    ParamSet values(info->params);
    const json set = j.contains("set") ? j["set"] : json::object();
    if (!set.is_object()) fail("\"set\" must be an object of NAME: \"VALUE\"");
    for (const auto& [name, value] : set.items()) {
        if (!value.is_string()) fail("set." + name + " must be a string");
        std::string err = values.set(name, value.get<std::string>());
        if (!err.empty()) fail("set " + name + ": " + err);
        row.set.emplace_back(name, value.get<std::string>());
    }
    if (!j.contains("draw") || !j["draw"].is_object() || j["draw"].empty())
        fail("\"draw\" must be a non-empty object of PARAMETER: [min, max] or [choices]");
    for (const auto& [name, value] : j["draw"].items()) {
        const ParamSpec* spec = values.find(name);
        if (!spec) fail("draw: stage " + row.stage + " has no parameter '" + name + "'");
        row.draw.push_back(parseDraw(*spec, value, where + ": draw." + name));
    }
    if (!j.contains("tolerance") || !j["tolerance"].is_object() || j["tolerance"].empty())
        fail("\"tolerance\" must be a non-empty object of FIGURE: {\"abs\": A, \"factor\": F}");
    for (const auto& [figure, t] : j["tolerance"].items()) {
        bool known = false;
        for (const auto& f : figureNames()) known = known || f == figure;
        if (!known) fail("tolerance: unknown figure '" + figure + "'");
        if (!t.is_object() || !t.contains("abs") || !t["abs"].is_number() ||
            !t.contains("factor") || !t["factor"].is_number() || t["factor"].get<double>() < 1 ||
            t["abs"].get<double>() < 0 || t.size() != 2)
            fail("tolerance." + figure + " must be {\"abs\": A >= 0, \"factor\": F >= 1}");
        row.tolerances.push_back({figure, t["abs"].get<double>(), t["factor"].get<double>()});
    }
    return row;
}

// The entry's "response": {"param": P, "ratio": [MIN, MAX], "figure": F, "abs": A, "factor": X}.
// P is one of the entry's drawn numbers whose range holds MAX twice over (max / min >= MAX^2), so
// that the value times r, or divided by r, always stays inside it: both rows keep the range's
// measured acne, and `check --set` finds the second row's values in it.
DrawnResponse parseResponse(const DrawnRow& row, const json& r, const std::string& where) {
    auto fail = [&](const std::string& what) { throw ExpectationError(where + ": " + what); };
    const std::string shape =
        "must be {\"param\": P, \"ratio\": [MIN, MAX], \"figure\": F, \"abs\": A, "
        "\"factor\": X}";
    if (!r.is_object() || r.size() != 5 || !r.contains("param") || !r["param"].is_string() ||
        !r.contains("ratio") || !r["ratio"].is_array() || r["ratio"].size() != 2 ||
        !r["ratio"][0].is_number() || !r["ratio"][1].is_number() || !r.contains("figure") ||
        !r["figure"].is_string() || !r.contains("abs") || !r["abs"].is_number() ||
        !r.contains("factor") || !r["factor"].is_number())
        fail(shape);
    DrawnResponse out;
    out.param = r["param"].get<std::string>();
    out.ratioMin = r["ratio"][0].get<double>();
    out.ratioMax = r["ratio"][1].get<double>();
    out.change = {r["figure"].get<std::string>(), r["abs"].get<double>(),
                  r["factor"].get<double>()};
    const DrawnParam* drawn = nullptr;
    for (const DrawnParam& d : row.draw)
        if (d.name == out.param && d.choices.empty()) drawn = &d;
    if (!drawn) fail("'" + out.param + "' is not a number the entry draws");
    if (!(out.ratioMin > 1) || out.ratioMax < out.ratioMin)
        fail("ratio [MIN, MAX] must have 1 < MIN <= MAX");
    if (!(drawn->min > 0) || drawn->max / drawn->min < out.ratioMax * out.ratioMax)
        fail("draw." + out.param + "'s range must hold the ratio's MAX twice over (max / min >= " +
             std::to_string(out.ratioMax * out.ratioMax) + ")");
    bool tolerated = false;  // so the first row's figures (shipped for a student edition) hold it
    for (const DrawnTolerance& t : row.tolerances)
        tolerated = tolerated || t.figure == out.change.figure;
    if (!tolerated)
        fail("figure '" + out.change.figure + "' is not one the entry's tolerance names");
    if (out.change.abs < 0 || out.change.factor < 1) fail("abs must be >= 0 and factor >= 1");
    return out;
}

// `digits` significant digits: "margin 0.0047", easy to type back with --set.
std::string withDigits(double v, int digits) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*g", digits, v);
    return text;
}

// The fewest significant digits (two or more) at which [min, max] holds 20 values or more, so
// that no one constant is drawn for many seeds: two for 0.0005-0.003 (25 values), three for
// 0.001-0.0017 (two would give 8: 0.0010, 0.0011, ... 0.0017).
int digitsFor(double min, double max) {
    int digits = 2;
    while (digits < 6) {
        const double step =
            std::pow(10.0, std::floor(std::log10(std::max(max, 1e-300))) - digits + 1);
        if ((max - min) / step >= 20) break;
        ++digits;
    }
    return digits;
}

std::uint64_t labelHash(const std::string& text) {  // FNV-1a: the same on every platform
    std::uint64_t h = 1469598103934665603ull;
    for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
    return h;
}

std::string drawOne(const DrawnParam& d, const ParamSpec& spec, std::mt19937_64& rng) {
    std::uint64_t x = rng();
    if (!d.choices.empty()) return d.choices[x % d.choices.size()];
    double u = double(x >> 11) * 0x1.0p-53;  // [0, 1), not left to the library
    double v = d.min + u * (d.max - d.min);
    if (spec.kind == ParamKind::Integer) {
        double step = d.max - d.min >= 256 ? 64 : 1;
        v = std::clamp(std::round(v / step) * step, d.min, d.max);
        return std::to_string(static_cast<long long>(v));
    }
    const int digits = digitsFor(d.min, d.max);
    std::string text = withDigits(v, digits);
    double back = std::stod(text);
    return back < d.min || back > d.max ? withDigits(std::clamp(back, d.min, d.max), digits) : text;
}

}  // namespace

std::string DrawnRow::entryLabel() const {
    std::string text = stage;
    if (!scene.empty()) text += " scene=" + scene;
    for (const auto& [name, value] : set) text += " " + name + "=" + value;
    return text;
}

std::string DrawnRow::label() const {
    return response ? entryLabel() + " response:" + response->param : entryLabel();
}

std::vector<DrawnRow> parseDrawnRows(const std::string& text, const std::string& origin) {
    json doc = json::parse(text, nullptr, false);
    std::vector<DrawnRow> rows;
    if (!doc.is_object() || !doc.contains("drawn")) return rows;
    if (!doc["drawn"].is_array()) throw ExpectationError(origin + ": \"drawn\" must be a list");
    for (std::size_t k = 0; k < doc["drawn"].size(); ++k) {
        const std::string where = origin + ": drawn[" + std::to_string(k) + "]";
        rows.push_back(parseRow(doc["drawn"][k], where));
        if (!doc["drawn"][k].contains("response")) continue;
        DrawnRow second = rows.back();
        second.response = parseResponse(second, doc["drawn"][k]["response"], where + ": response");
        rows.push_back(std::move(second));
    }
    return rows;
}

const std::vector<DrawnRow>& drawnRows() {
    static const std::vector<DrawnRow> rows = [] {
        std::ifstream in(expectationsPath());
        std::stringstream text;
        text << in.rdbuf();
        return parseDrawnRows(text.str(), expectationsPath());
    }();
    return rows;
}

std::vector<const DrawnRow*> drawnRowsOf(const std::string& stage, const std::string& tree) {
    std::vector<const DrawnRow*> out;
    for (const DrawnRow& row : drawnRows())
        if (row.stage == stage && coversTree(row, tree)) out.push_back(&row);
    return out;
}

namespace {

// The values someone chose for a number parameter of `stage`: its default and each lesson's (a
// shader can recognise those, as one testing textureSize == 2048 recognises the packed lesson).
std::set<double> chosenValues(const std::string& stage, const std::string& param) {
    std::set<double> chosen;
    ParamSet defaults(findStage(stage)->params);
    chosen.insert(defaults.number(param));
    for (const Expectation& e : expectations())
        for (const auto& [name, value] : e.set)
            if (e.stage == stage && name == param) chosen.insert(std::stod(value));
    return chosen;
}

}  // namespace

const DrawnRow* pairedRowOf(const DrawnRow& row) {
    if (!row.response) return nullptr;
    for (const DrawnRow& first : drawnRows())
        if (!first.response && first.stage == row.stage && first.trees == row.trees &&
            first.entryLabel() == row.entryLabel())
            return &first;
    return nullptr;
}

namespace {

// The second row's value of its response's parameter: the first row's `value` times a ratio the
// seed draws, or divided by it where the product would leave the range (the parser made sure the
// quotient then stays in it), to the digits the range is drawn with.
std::string respondedValue(const DrawnRow& row, const std::string& value, std::uint64_t seed) {
    const DrawnResponse& response = *row.response;
    const DrawnParam* d = nullptr;
    for (const DrawnParam& p : row.draw)
        if (p.name == response.param) d = &p;
    const std::set<double> chosen = chosenValues(row.stage, d->name);
    std::mt19937_64 rng(seed ^ labelHash(row.label()));
    const double first = std::stod(value);
    const int digits = digitsFor(d->min, d->max);
    std::string moved = value;
    for (int tries = 0; tries < 16 && (moved == value || chosen.count(std::stod(moved))); ++tries) {
        const double u = double(rng() >> 11) * 0x1.0p-53;
        const double ratio = response.ratioMin + u * (response.ratioMax - response.ratioMin);
        const double v = first * ratio <= d->max ? first * ratio : first / ratio;
        moved = withDigits(std::clamp(v, d->min, d->max), digits);
        if (std::stod(moved) < d->min || std::stod(moved) > d->max)
            moved = withDigits(std::clamp(std::stod(moved), d->min, d->max), digits);
    }
    return moved;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> drawnSettings(const DrawnRow& row,
                                                               std::uint64_t seed) {
    std::mt19937_64 rng(seed ^ labelHash(row.entryLabel()));
    ParamSet values(findStage(row.stage)->params);
    auto settings = row.set;
    for (const DrawnParam& d : row.draw) {
        const ParamSpec& spec = *values.find(d.name);
        std::string drawn = drawOne(d, spec, rng);
        if (d.choices.empty()) {  // a number no lesson names: drawn again (a few tries)
            const std::set<double> chosen = chosenValues(row.stage, d.name);
            for (int tries = 0; tries < 16 && chosen.count(std::stod(drawn)); ++tries)
                drawn = drawOne(d, spec, rng);
        }
        settings.emplace_back(d.name, drawn);
    }
    if (row.response)
        for (auto& [name, value] : settings)
            if (name == row.response->param) value = respondedValue(row, value, seed);
    return settings;
}

const DrawnRow* drawnRowFor(const std::string& stage, const std::string& scene,
                            const std::string& tree, const ParamSet& values) {
    for (const DrawnRow* row : drawnRowsOf(stage, tree)) {
        if (row->response) continue;  // its values are within its first row's
        if ((row->scene.empty() ? defaultSceneOf(stage) : row->scene) != scene) continue;
        ParamSet expected(values.specs());
        for (const auto& [name, value] : row->set) expected.set(name, value);
        bool covered = true;
        for (const ParamSpec& spec : values.specs()) {
            const DrawnParam* d = nullptr;
            for (const DrawnParam& p : row->draw)
                if (p.name == spec.name) d = &p;
            if (!d) {
                covered = covered && values.text(spec.name) == expected.text(spec.name);
            } else if (!d->choices.empty()) {
                bool in = false;
                for (const auto& c : d->choices) in = in || c == values.text(spec.name);
                covered = covered && in;
            } else {
                double v = values.number(spec.name);
                covered = covered && v >= d->min && v <= d->max;
            }
        }
        if (covered) return row;
    }
    return nullptr;
}

}  // namespace sl
