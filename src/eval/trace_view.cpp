#include "eval/trace_view.h"

#include <cstdio>
#include <cstring>
#include <map>
#include <stdexcept>
#include <type_traits>

#include "io/json_fields.h"
#include "scene/mirror_displace.h"
#include "scene/scene_json.h"

namespace sl {

namespace {

// A reference crosses to the page's workers as its bytes: plain ints, bools and glm vectors of
// floats (whose copy constructor GLM_FORCE_CTOR_INIT makes user-provided, so the type is not
// formally trivially copyable; nothing in it points anywhere).
static_assert(std::is_standard_layout_v<ReferencePixel> && sizeof(glm::vec3) == 3 * sizeof(float),
              "a reference pixel must be plain data");

Scene sceneOf(const std::string& name, const std::optional<std::uint64_t>& seed) {
    Scene scene = loadScene(name);
    return seed ? displacedViewOf(scene, *seed) : scene;
}

}  // namespace

std::string exactText(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%a", v);
    return text;
}

std::string exactText(const glm::vec3& v) {
    return exactText(v.x) + "," + exactText(v.y) + "," + exactText(v.z);
}

namespace {

TraceView viewIn(const RenderRequest& request, const std::string& sceneName, const Scene& scene) {
    TraceView v;
    v.scene = sceneName;
    v.displaceSeed = request.displaceSeed;
    v.width = request.width;
    v.height = request.height;
    v.camera = scene.camera;
    if (request.eye) v.camera.eye = *request.eye;
    if (request.at) v.camera.at = *request.at;
    if (request.fovy) v.camera.fovyDegrees = *request.fovy;
    v.light = request.light ? *request.light : scene.light.position;
    return v;
}

}  // namespace

TraceView traceViewOf(const RenderRequest& request) {
    const std::string name = effectiveScene(request);
    return viewIn(request, name, sceneOf(name, request.displaceSeed));
}

std::vector<std::optional<TraceView>> traceViewsOf(
    const std::vector<const RenderRequest*>& requests) {
    std::map<std::pair<std::string, std::optional<std::uint64_t>>, std::optional<Scene>> scenes;
    std::vector<std::optional<TraceView>> views(requests.size());
    for (std::size_t k = 0; k < requests.size(); ++k) {
        try {
            const RenderRequest& request = *requests[k];
            const std::string name = effectiveScene(request);
            auto [at, added] = scenes.try_emplace({name, request.displaceSeed});
            if (added) at->second = sceneOf(name, request.displaceSeed);
            if (at->second) views[k] = viewIn(request, name, *at->second);
        } catch (const std::exception&) {
            // a scene that does not load: its row fails with the reason (and so do the next
            // rows of that scene, whose cached entry stays empty)
        }
    }
    return views;
}

std::string traceKey(const TraceView& v) {
    return v.scene + "/" + std::to_string(v.width) + "x" + std::to_string(v.height) +
           "/displaced=" + (v.displaceSeed ? std::to_string(*v.displaceSeed) : "") + "/" +
           exactText(v.camera.fovyDegrees) + "/" + exactText(v.light) + "/" +
           exactText(v.camera.eye) + "/" + exactText(v.camera.at);
}

ReferenceImage traceView(const TraceView& v) {
    const Scene scene = sceneOf(v.scene, v.displaceSeed);
    Camera camera = scene.camera;
    camera.eye = v.camera.eye;
    camera.at = v.camera.at;
    camera.fovyDegrees = v.camera.fovyDegrees;
    return traceReference(scene, camera, v.light, v.width, v.height);
}

nlohmann::json traceViewJson(const TraceView& v) {
    return {{"scene", v.scene},
            {"seed",
             v.displaceSeed ? nlohmann::json(std::to_string(*v.displaceSeed)) : nlohmann::json()},
            {"size", {v.width, v.height}},
            {"eye", vec3Json(v.camera.eye)},
            {"at", vec3Json(v.camera.at)},
            {"fovy", v.camera.fovyDegrees},
            {"light", vec3Json(v.light)}};
}

TraceView traceViewFromJson(const nlohmann::json& j) {
    try {
        TraceView v;
        v.scene = j.at("scene").get<std::string>();
        if (!j.at("seed").is_null()) v.displaceSeed = std::stoull(j["seed"].get<std::string>());
        v.width = j.at("size").at(0).get<int>();
        v.height = j.at("size").at(1).get<int>();
        v.camera.eye = vec3FromJson(j.at("eye"));
        v.camera.at = vec3FromJson(j.at("at"));
        v.camera.fovyDegrees = j.at("fovy").get<float>();
        v.light = vec3FromJson(j.at("light"));
        if (v.width <= 0 || v.height <= 0 || v.width > 8192 || v.height > 8192)
            throw std::invalid_argument("a view's size is out of range");
        return v;
    } catch (const nlohmann::json::exception& e) {
        throw std::invalid_argument(std::string("a trace view: ") + e.what());
    } catch (const std::logic_error& e) {  // stoull's
        throw std::invalid_argument(std::string("a trace view: ") + e.what());
    }
}

std::string referenceBytes(const ReferenceImage& image) {
    std::string bytes(image.pixels.size() * sizeof(ReferencePixel), '\0');
    if (!bytes.empty()) std::memcpy(bytes.data(), image.pixels.data(), bytes.size());
    return bytes;
}

ReferenceImage referenceFromBytes(int width, int height, int mirrorObjectId, const void* bytes,
                                  std::size_t size) {
    if (width <= 0 || height <= 0 ||
        size != std::size_t(width) * std::size_t(height) * sizeof(ReferencePixel))
        throw std::invalid_argument("a reference of " + std::to_string(size) +
                                    " bytes is not one of " + std::to_string(width) + "x" +
                                    std::to_string(height) + " pixels");
    ReferenceImage image;
    image.width = width;
    image.height = height;
    image.mirrorObjectId = mirrorObjectId;
    image.pixels.resize(std::size_t(width) * std::size_t(height));
    std::memcpy(static_cast<void*>(image.pixels.data()), bytes, size);  // plain data (above)
    return image;
}

}  // namespace sl
