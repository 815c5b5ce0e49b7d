// `shadowlab stages [--json]`: every stage with its declared parameters; `--figures`: the figure
// table (metrics/figures.h), which scripts and tests read instead of lists of their own.
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "io/usage_error.h"
#include "metrics/figures.h"
#include "metrics/figures_json.h"
#include "stages/expectations.h"
#include "stages/registry.h"

namespace sl {

namespace {

// The stage's lesson as `check` judges it: its defaults entry in src/stages/expectations.json,
// the one source of truth (`expectation` and `expected` below both come from it).
const Expectation& defaultsEntry(const StageInfo& s) {
    std::string tree = s.legacyOnly ? "legacy" : "core";
    return *findExpectation(expectations(), s.id,
                            s.defaultScene.empty() ? "slides" : s.defaultScene, tree,
                            ParamSet(s.params))
                .entry;
}

nlohmann::json expectedJson(const Expectation& e) {
    nlohmann::json limits = nlohmann::json::object();
    for (const Limit& l : e.limits) {
        limits[l.figure] = nlohmann::json::object();
        if (!std::isnan(l.min)) limits[l.figure]["min"] = l.min;
        if (!std::isnan(l.max)) limits[l.figure]["max"] = l.max;
    }
    return {{"outcome", e.outcome}, {"why", e.why}, {"limits", limits}};
}

nlohmann::json paramJson(const ParamSpec& p) {
    nlohmann::json j{{"name", p.name}, {"help", p.help}};
    if (p.kind == ParamKind::Choice) {
        j["type"] = "choice";
        j["default"] = p.choices.front();
        j["choices"] = p.choices;
    } else {
        j["type"] = p.kind == ParamKind::Integer ? "integer" : "number";
        j["default"] = p.defaultValue;
        j["min"] = p.min;
        j["max"] = p.max;
    }
    return j;
}

int listStages(bool json) {
    if (json) {
        nlohmann::json out = nlohmann::json::array();
        int key = 0;
        for (const auto& s : stageRegistry()) {
            nlohmann::json j{
                {"id", s.id},
                {"key", key++},
                {"title", s.title},
                {"lecture", s.lecture},
                {"expectation", defaultsEntry(s).outcome + ": " + defaultsEntry(s).why},
                {"trees",
                 s.legacyOnly ? nlohmann::json{"legacy"} : nlohmann::json{"core", "legacy"}},
                // The scene it draws when none is given, and whether it needs a mirror there
                // (no displaced view: tests/check/planned_rows.py counts check's rows from these).
                {"scene", s.defaultScene.empty() ? std::string("slides") : s.defaultScene},
                {"needs_mirror", s.needsMirror}};
            j["expected"] = expectedJson(defaultsEntry(s));
            j["parameters"] = nlohmann::json::array();
            for (const auto& p : s.params) j["parameters"].push_back(paramJson(p));
            j["views"] = nlohmann::json::array();
            for (ViewMode v : s.views) j["views"].push_back(viewName(v));
            out.push_back(j);
        }
        std::cout << out.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
        return kOk;
    }
    int key = 0;
    for (const auto& s : stageRegistry()) {
        std::cout << key++ << "  " << s.id << "  " << s.title
                  << (s.legacyOnly ? "  [legacy only]" : "") << "\n     " << s.lecture << "\n";
        const Expectation& e = defaultsEntry(s);
        std::string limits;
        for (const Limit& l : e.limits)
            limits += (limits.empty() ? "" : ", ") + l.figure + " " + l.bound();
        std::cout << "     expected: " << e.outcome << "; check: " << limits << "\n";
        for (const auto& p : s.params)
            std::cout << "     --set " << p.name << "=" << p.defaultText() << "   ("
                      << p.rangeText() << ") " << p.help << "\n";
    }
    return kOk;
}

// Every figure a check measures, in the table's order (the order of reports and messages).
int listFigures(bool json) {
    if (json) {
        std::cout << figureTableJson().dump(2) << "\n";
        return kOk;
    }
    for (const nlohmann::json& f : figureTableJson())
        std::cout << f["name"].get<std::string>() << "  " << f["unit"].get<std::string>() << "  "
                  << f["better"].get<std::string>() << " is better  ("
                  << f["words"].get<std::string>() << ")\n";
    return kOk;
}

}  // namespace

Command addStagesCommand(CLI::App& app) {
    auto* cmd = app.add_subcommand("stages", "list stages with their parameters and defaults");
    auto json = std::make_shared<bool>(false);
    auto figures = std::make_shared<bool>(false);
    cmd->add_flag("--json", *json, "machine-readable output");
    cmd->add_flag("--figures", *figures,
                  "list the figures a check measures (name, unit, which way is better, words)");
    return {cmd, [json, figures] {
                return guarded([&] { return *figures ? listFigures(*json) : listStages(*json); });
            }};
}

}  // namespace sl
