#include "eval/trace_view.h"

#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <type_traits>

#include "scene/mirror_displace.h"
#include "scene/scene_json.h"

namespace sl {

namespace {

// A reference crosses to the page's workers as its bytes: plain ints, bools and glm vectors of
// floats (whose copy constructor GLM_FORCE_CTOR_INIT makes user-provided, so the type is not
// formally trivially copyable; nothing in it points anywhere).
static_assert(std::is_standard_layout_v<ReferencePixel> && sizeof(glm::vec3) == 3 * sizeof(float),
              "a reference pixel must be plain data");

std::string exact(double v) {
    return exactText(v);
}

std::string exact(const glm::vec3& v) {
    return exact(v.x) + "," + exact(v.y) + "," + exact(v.z);
}

Scene sceneOf(const std::string& name, const std::optional<std::uint64_t>& seed) {
    Scene scene = loadScene(name);
    return seed ? displacedViewOf(scene, *seed) : scene;
}

nlohmann::json vec(const glm::vec3& v) {
    return {v.x, v.y, v.z};
}

glm::vec3 vecFrom(const nlohmann::json& v) {
    return {v.at(0).get<float>(), v.at(1).get<float>(), v.at(2).get<float>()};
}

}  // namespace

std::string exactText(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%a", v);
    return text;
}

TraceView traceViewOf(const RenderRequest& request) {
    TraceView v;
    v.scene = effectiveScene(request);
    v.displaceSeed = request.displaceSeed;
    v.width = request.width;
    v.height = request.height;
    const Scene scene = sceneOf(v.scene, v.displaceSeed);
    v.camera = scene.camera;
    if (request.eye) v.camera.eye = *request.eye;
    if (request.at) v.camera.at = *request.at;
    if (request.fovy) v.camera.fovyDegrees = *request.fovy;
    v.light = request.light ? *request.light : scene.light.position;
    return v;
}

std::string traceKey(const TraceView& v) {
    return v.scene + "/" + std::to_string(v.width) + "x" + std::to_string(v.height) +
           "/displaced=" + (v.displaceSeed ? std::to_string(*v.displaceSeed) : "") + "/" +
           exact(v.camera.fovyDegrees) + "/" + exact(v.light) + "/" + exact(v.camera.eye) + "/" +
           exact(v.camera.at);
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
            {"eye", vec(v.camera.eye)},
            {"at", vec(v.camera.at)},
            {"fovy", v.camera.fovyDegrees},
            {"light", vec(v.light)}};
}

TraceView traceViewFromJson(const nlohmann::json& j) {
    try {
        TraceView v;
        v.scene = j.at("scene").get<std::string>();
        if (!j.at("seed").is_null()) v.displaceSeed = std::stoull(j["seed"].get<std::string>());
        v.width = j.at("size").at(0).get<int>();
        v.height = j.at("size").at(1).get<int>();
        v.camera.eye = vecFrom(j.at("eye"));
        v.camera.at = vecFrom(j.at("at"));
        v.camera.fovyDegrees = j.at("fovy").get<float>();
        v.light = vecFrom(j.at("light"));
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
