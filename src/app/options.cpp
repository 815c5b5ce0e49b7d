#include "app/options.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "io/box.h"
#include "io/usage_error.h"

namespace sl {

namespace {

constexpr int kMaxImageSide = 8192;

float parseFloat(const std::string& option, const std::string& text) {
    char* end = nullptr;
    double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(v) || std::abs(v) > 1e6)
        throw UsageError(option + ": '" + text + "' is not a finite number (|x| <= 1e6)");
    return static_cast<float>(v);
}

glm::vec3 parseVec3(const std::string& option, const std::string& text) {
    std::vector<std::string> parts;
    std::stringstream in(text);
    std::string p;
    while (std::getline(in, p, ',')) parts.push_back(p);
    if (parts.size() != 3 || text.back() == ',')
        throw UsageError(option + ": '" + text + "' must be three numbers X,Y,Z");
    return {parseFloat(option, parts[0]), parseFloat(option, parts[1]),
            parseFloat(option, parts[2])};
}

}  // namespace

void addCommonOptions(CLI::App* app, CommonOptions& o, bool withStage) {
    if (withStage) app->add_option("--stage", o.stage, "stage id (see `shadowlab stages`)");
    app->add_option("--glsl", o.glsl, "shader tree: core (GLSL 3.30) or legacy (GLSL 1.20)");
    app->add_option("--scene", o.scene,
                    "built-in scene or .json file (default: slides; the mirror stage: mirror)");
    app->add_option("--shaders", o.shaders, "student overlay folder: its files replace ours");
    app->add_option("--size", o.size, "image size WxH (default 640x480)");
    app->add_option("--eye", o.eye, "camera position X,Y,Z");
    app->add_option("--at", o.at, "camera target X,Y,Z");
    app->add_option("--fovy", o.fovy, "vertical field of view in degrees");
    app->add_option("--light", o.light, "light position X,Y,Z");
    app->add_option("--displace", o.displace,
                    "move the casters, light and camera (in a scene with a mirror: the camera "
                    "and the mirror) as check's displaced view of this seed");
    app->add_option("--set", o.sets, "stage parameter NAME=VALUE (repeatable)");
    app->add_option("--view", o.view, "final|shadow-map|light|visibility|light-depth");
    app->add_option("--backend", o.backend, "headless backend: auto|osmesa|egl");
}

void addLimitOptions(CLI::App* app, LimitOptions& limits) {
    app->add_option("--time-limit", limits.time,
                    "CPU seconds one stage of a submission may use in its worker: auto (default: " +
                        std::to_string(int(kCpuFactor)) +
                        " x what our shaders take for it, at least " +
                        std::to_string(int(kCpuFloorSeconds)) + " s), a number, or 0 = no limit");
    app->add_option("--memory-limit", limits.memory,
                    "resident memory of one stage's worker in MB: auto (default: " +
                        std::to_string(int(kMemoryFactor)) + " x our shaders' peak, at least " +
                        std::to_string(kMemoryFloorMb) + ", within the " +
                        std::to_string(boxDefaultMemoryMb(2048)) +
                        " MB this box gives a worker), a number, or 0 = no limit");
}

BudgetRule LimitOptions::rule() const {
    BudgetRule r = budgetRuleFrom(time, memory);
    // Less than 2048 where the cgroup or ulimit -v is smaller (src/io/box.h).
    r.memoryCeilingMb = boxDefaultMemoryMb(2048);
    return r;
}

Backend toBackend(const std::string& text) {
    if (text == "auto") return Backend::Auto;
    if (text == "osmesa") return Backend::OSMesa;
    if (text == "egl") return Backend::Egl;
    throw UsageError("--backend: '" + text + "' is not one of auto, osmesa, egl");
}

RenderRequest toRequest(const CommonOptions& o) {
    RenderRequest r;
    r.stage = o.stage;
    if (o.glsl == "core")
        r.tree = GlslTree::Core;
    else if (o.glsl == "legacy")
        r.tree = GlslTree::Legacy;
    else
        throw UsageError("--glsl: '" + o.glsl + "' is not one of core, legacy");
    if (!o.scene.empty()) {
        r.scene = o.scene;
        r.sceneGiven = true;
    }
    r.overlay = o.shaders;

    int w = 0, h = 0;
    char x = 0, extra = 0;
    std::istringstream size(o.size);
    if (!(size >> w >> x >> h) || x != 'x' || (size >> extra))
        throw UsageError("--size: '" + o.size + "' must be WxH, e.g. 640x480");
    if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide)
        throw UsageError("--size: " + o.size + " is out of range; each side must be 1 to " +
                         std::to_string(kMaxImageSide));
    r.width = w;
    r.height = h;

    if (!o.eye.empty()) r.eye = parseVec3("--eye", o.eye);
    if (!o.at.empty()) r.at = parseVec3("--at", o.at);
    if (!o.light.empty()) r.light = parseVec3("--light", o.light);
    r.displaceSeed = o.displace;
    if (!o.fovy.empty()) {
        float f = parseFloat("--fovy", o.fovy);
        if (f < 1 || f > 170)
            throw UsageError("--fovy: " + o.fovy + " must be between 1 and 170 degrees");
        r.fovy = f;
    }
    if (!parseView(o.view, r.view)) {
        std::string all;
        for (const auto& v : allViewNames()) all += (all.empty() ? "" : ", ") + v;
        throw UsageError("--view: '" + o.view + "' is not one of " + all);
    }
    for (const auto& s : o.sets) {
        auto eq = s.find('=');
        if (eq == std::string::npos || eq == 0)
            throw UsageError("--set: '" + s + "' must be NAME=VALUE");
        r.sets.emplace_back(s.substr(0, eq), s.substr(eq + 1));
    }
    return r;
}

}  // namespace sl
