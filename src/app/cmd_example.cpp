// `shadowlab example NAME`: one lecture figure from slides_examples/NAME.json rendered into
// out/examples/NAME.png (plus its diff image) and checked against the verdict the figure is
// expected to get; `example --list` names them all. File format: docs/check.md.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "app/commands.h"
#include "app/mirror_figure.h"
#include "bench/bench_output.h"
#include "eval/job_errors.h"
#include "grade/check_run.h"
#include "grade/reports.h"
#include "io/data_paths.h"
#include "io/png.h"
#include "io/usage_error.h"
#include "metrics/mirror_figure.h"
#include "sandbox/worker.h"
#include "scene/scene_json.h"
#include "stages/registry.h"

namespace sl {

namespace {

using nlohmann::json;

struct ExampleArgs {
    std::string name, out = "out/examples", backend = "auto";
    bool list = false;
    LimitOptions limits;
};

// One render of an example: its own parameters, or a variant's merged over them.
struct ExampleRender {
    std::string label;  // "" for the example itself, else the variant's
    RenderRequest request;
    ViewMode view = ViewMode::Final;
    std::string expect;  // "pass" | "fail"
};

std::string examplesDir() {
    return dataDir() + "/slides_examples";
}

std::vector<std::string> exampleNames() {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(examplesDir(), ec))
        if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

json loadExample(const std::string& nameOrPath, std::string& origin) {
    bool isPath = nameOrPath.find('/') != std::string::npos ||
                  (nameOrPath.size() > 5 && nameOrPath.substr(nameOrPath.size() - 5) == ".json");
    origin = isPath ? nameOrPath : examplesDir() + "/" + nameOrPath + ".json";
    std::ifstream in(origin);
    if (!in) {
        std::string names;
        for (const auto& n : exampleNames()) names += (names.empty() ? "" : ", ") + n;
        std::string hint = closestMatch(nameOrPath, exampleNames());
        throw UsageError("example: unknown example '" + nameOrPath + "'" +
                         (hint.empty() ? "" : " (did you mean '" + hint + "'?)") +
                         "; examples: " + names);
    }
    std::stringstream text;
    text << in.rdbuf();
    try {
        return json::parse(text.str());
    } catch (const json::parse_error& e) {
        throw UsageError(origin + ": not valid JSON: " + e.what());
    }
}

std::vector<std::string> comment(const json& j, const std::string& origin) {
    if (!j.contains("comment") || !j["comment"].is_array() || j["comment"].size() != 2 ||
        !j["comment"][0].is_string() || !j["comment"][1].is_string())
        throw UsageError(origin +
                         ": \"comment\" must be two lines: [\"which figure\", \"what it shows\"]");
    return {j["comment"][0], j["comment"][1]};
}

glm::vec3 vec3Of(const json& v, const std::string& where) {
    if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() ||
        !v[2].is_number())
        throw UsageError(where + " must be three numbers [x, y, z]");
    return {v[0].get<float>(), v[1].get<float>(), v[2].get<float>()};
}

glm::vec2 xzOf(const json& v, const std::string& where) {
    if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
        throw UsageError(where + " must be two numbers [x, z]");
    return {v[0].get<float>(), v[1].get<float>()};
}

// The "figure" of the lecture's mirror exercise: {"p1", "p2", "eye", "at"} in the x-z plane,
// seen from above. Checked before any GL work; an impossible set-up is bad input.
MirrorTopView practiceFigure(const json& figure, const std::string& origin) {
    const std::string where = origin + ": figure";
    if (!figure.is_object()) throw UsageError(where + " must be an object {p1, p2, eye, at}");
    for (const auto& [key, value] : figure.items())
        if (key != "p1" && key != "p2" && key != "eye" && key != "at")
            throw UsageError(where + "." + key + ": unknown field; allowed: p1, p2, eye, at");
    for (const char* key : {"p1", "p2", "eye", "at"})
        if (!figure.contains(key)) throw UsageError(where + " needs \"" + key + "\"");
    MirrorTopView view =
        practiceTopView(xzOf(figure["p1"], where + ".p1"), xzOf(figure["p2"], where + ".p2"),
                        xzOf(figure["eye"], where + ".eye"), xzOf(figure["at"], where + ".at"));
    if (!view.valid) throw UsageError(where + ": " + view.reason);
    return view;
}

void applySets(const json& params, RenderRequest& r, const std::string& where) {
    if (!params.is_object()) throw UsageError(where + " must be an object of NAME: \"VALUE\"");
    for (const auto& [name, value] : params.items()) {
        if (!value.is_string()) throw UsageError(where + "." + name + " must be a string");
        const std::string key = name;  // clang before 16 cannot capture a structured binding
        r.sets.erase(std::remove_if(r.sets.begin(), r.sets.end(),
                                    [&](const auto& s) { return s.first == key; }),
                     r.sets.end());
        r.sets.emplace_back(name, value.get<std::string>());
    }
}

std::string expectOf(const json& j, const std::string& where) {
    if (!j.contains("expect") || !(j["expect"] == "pass" || j["expect"] == "fail"))
        throw UsageError(where + ": \"expect\" must be \"pass\" or \"fail\" (the check's verdict)");
    return j["expect"];
}

std::vector<ExampleRender> parseExample(const json& j, const std::string& origin) {
    static const std::vector<std::string> known = {
        "comment", "stage", "glsl",   "scene",    "size",   "parameters", "view",
        "camera",  "light", "expect", "variants", "figure", "see"};
    if (!j.is_object()) throw UsageError(origin + ": an example is a JSON object");
    for (const auto& [key, value] : j.items())
        if (std::find(known.begin(), known.end(), key) == known.end())
            throw UsageError(origin + ": unknown field '" + key + "'");
    comment(j, origin);
    CommonOptions o;
    if (!j.contains("stage") || !j["stage"].is_string())
        throw UsageError(origin + ": \"stage\" is required");
    o.stage = j["stage"];
    auto text = [&](const char* key, std::string& into) {
        if (!j.contains(key)) return;
        if (!j[key].is_string()) throw UsageError(origin + ": \"" + key + "\" must be a string");
        into = j[key];
    };
    text("glsl", o.glsl);
    text("scene", o.scene);
    text("size", o.size);
    std::string view = "final";
    text("view", view);
    RenderRequest base = toRequest(o);
    // A scene file is named relative to the data folder ("scenes/lab.json"), so an example
    // means the same wherever it is run from; a built-in name ("lab") is left as it is.
    bool sceneIsFile =
        base.scene.find('/') != std::string::npos ||
        (base.scene.size() > 5 && base.scene.substr(base.scene.size() - 5) == ".json");
    if (base.sceneGiven && sceneIsFile && base.scene.front() != '/')
        base.scene = dataDir() + "/" + base.scene;
    ViewMode mode = ViewMode::Final;
    if (!parseView(view, mode))
        throw UsageError(origin + ": \"view\": '" + view + "' is not a view");
    if (j.contains("camera")) {
        const json& c = j["camera"];
        if (!c.is_object()) throw UsageError(origin + ": \"camera\" must be {eye, at, fovy}");
        if (c.contains("eye")) base.eye = vec3Of(c["eye"], origin + ": camera.eye");
        if (c.contains("at")) base.at = vec3Of(c["at"], origin + ": camera.at");
        if (c.contains("fovy")) base.fovy = c["fovy"].get<float>();
    }
    if (j.contains("light")) base.light = vec3Of(j["light"], origin + ": light");
    if (j.contains("parameters")) applySets(j["parameters"], base, origin + ": parameters");
    std::vector<ExampleRender> renders;
    if (j.contains("variants")) {
        if (!j["variants"].is_array() || j["variants"].empty())
            throw UsageError(origin + ": \"variants\" must be a non-empty list");
        for (std::size_t k = 0; k < j["variants"].size(); ++k) {
            const json& v = j["variants"][k];
            std::string where = origin + ": variants[" + std::to_string(k) + "]";
            if (!v.is_object() || !v.contains("label") || !v["label"].is_string())
                throw UsageError(where + " needs a \"label\"");
            ExampleRender r{v["label"], base, mode, expectOf(v, where)};
            if (v.contains("parameters"))
                applySets(v["parameters"], r.request, where + ".parameters");
            renders.push_back(r);
        }
    } else {
        renders.push_back({"", base, mode, expectOf(j, origin)});
    }
    for (auto& r : renders) {
        validateRequest(r.request);
        RenderRequest viewed = r.request;
        viewed.view = r.view;
        validateRequest(viewed);  // the stage offers the view
    }
    return renders;
}

int listExamples() {
    for (const auto& name : exampleNames()) {
        std::string origin;
        json j = loadExample(name, origin);
        auto lines = comment(j, origin);
        std::cout << name << "\n    " << lines[0] << "\n    " << lines[1] << "\n";
    }
    return kOk;
}

// Renders and checks each of an example's renders, printing a line for each; the GL part of
// `example`, run inside the worker. Returns the exit code.
int renderExample(const std::vector<ExampleRender>& renders, const std::string& outDir,
                  const std::string& base, Backend backend) {
    Evaluator rig(backend);
    int exitCode = kOk;
    for (const auto& er : renders) {
        std::string stem = outDir + "/" + base + (er.label.empty() ? "" : "-" + er.label);
        CheckResult result =
            runCheck(rig, er.request, stageNeedsMirror(er.request.stage) ? "" : stem + "-diff.png");
        if (unjudged(result.status)) return kBadInput;
        Renderer& r = rig.renderer();
        r.view = er.view;
        r.render(rig.context().framebuffer(), rig.context().width(), rig.context().height());
        Image picture = rig.context().read();
        r.view = ViewMode::Final;
        std::string err = writePng(stem + ".png", picture);
        if (!err.empty()) throw UsageError("--out: " + err);
        std::string got = result.status == Status::Pass   ? "pass"
                          : result.status == Status::Fail ? "fail"
                                                          : "skip";
        bool ok = got == er.expect;
        if (!ok) exitCode = kCheckFailed;
        std::cout << (er.label.empty() ? "" : er.label + ": ") << stem << ".png  "
                  << tableLine(RowRecord{result}) << "    expected " << er.expect << ", got " << got
                  << (ok ? ": as the lecture shows" : ": NOT what the lecture shows") << "\n";
    }
    return exitCode;
}

int runExample(const ExampleArgs& a) {
    if (a.list) return listExamples();
    if (a.name.empty()) throw UsageError("example: give a NAME (see `shadowlab example --list`)");
    std::string origin;
    json j = loadExample(a.name, origin);
    std::vector<ExampleRender> renders = parseExample(j, origin);
    std::string base = a.name.substr(a.name.find_last_of('/') + 1);
    if (base.size() > 5 && base.substr(base.size() - 5) == ".json") base.resize(base.size() - 5);
    makeOutputDir(a.out);
    auto lines = comment(j, origin);
    std::cout << base << ": " << lines[0] << "\n    " << lines[1] << "\n";
    std::optional<MirrorTopView> figure;
    if (j.contains("figure")) figure = practiceFigure(j["figure"], origin);
    if (j.contains("see") && j["see"].is_string())
        std::cout << "see also: " << j["see"].get<std::string>() << "\n";
    const Backend backend = toBackend(a.backend);
    // Every render of the example (one stage and tree) in one bounded worker, as `check` does.
    // The examples draw our shaders: the budget's floors bound them all the same (a broken
    // data tree, a user's example file).
    const Limits limits = provisionalLimits(a.limits.rule());
    WorkerOutcome outcome = runBounded(
        limits,
        [&] {
            return nlohmann::json{{"exit", renderExample(renders, a.out, base, backend)}};
        },
        renderJobErrors());
    if (outcome.kind != WorkerOutcome::Kind::Ok)
        throw UsageError(workerFailureLine("example " + base, outcome, limits));
    int exitCode = outcome.value.at("exit").get<int>();
    if (exitCode == kBadInput) return kBadInput;
    if (figure) {  // the exercise's answer: eye', at' and the frustum, printed and drawn
        std::string path = a.out + "/" + base + "-figure.png";
        std::string err = writeMirrorFigure(path, *figure);
        if (!err.empty()) throw std::runtime_error("figure: " + err);
        std::cout << "the exercise seen from above -> " << path << "\n" << describeTopView(*figure);
    }
    return exitCode;
}

}  // namespace

Command addExampleCommand(CLI::App& app) {
    auto args = std::make_shared<ExampleArgs>();
    auto* cmd =
        app.add_subcommand("example", "render and check one lecture figure (slides_examples/)");
    cmd->add_option("name", args->name, "example name (see --list) or a .json file");
    cmd->add_flag("--list", args->list, "list the examples with what each shows");
    cmd->add_option("--out", args->out, "output folder (default out/examples)");
    cmd->add_option("--backend", args->backend, "headless backend: auto|osmesa|egl");
    addLimitOptions(cmd, args->limits);
    return {cmd, [args] { return guarded([&] { return runExample(*args); }); }};
}

}  // namespace sl
