// What a reference is traced from, found from a render request alone (no GL context): the scene
// as the renderer loads it (displaced by the request's seed), the size, the camera and the light.
// The browser's check traces its references in Web Workers (docs/web.md): the page sends each
// worker a view (traceViewJson), the worker traces it with the same code (traceView), and the
// page hands the reference to its Evaluator under the view's key, the key the Evaluator looks it
// up by (traceKey). Native programs trace in the Evaluator itself.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "reference/raytracer.h"
#include "scene/scene.h"
#include "stages/request.h"

namespace sl {

struct TraceView {
    std::string scene;  // the effective scene's name (effectiveScene)
    std::optional<std::uint64_t> displaceSeed;
    int width = 0, height = 0;
    Camera camera;
    glm::vec3 light{0.0f};
};

// The view the Evaluator traces for `request` (prepare, then applyRequest): the scene's camera
// and light, the request's eye, at, fovy and light over them.
TraceView traceViewOf(const RenderRequest& request);
// The same for many requests (a stage's rows), each scene loaded and displaced once: the rows
// share one or two. A request whose scene does not load has none (its row fails with the reason).
std::vector<std::optional<TraceView>> traceViewsOf(
    const std::vector<const RenderRequest*>& requests);

// A number as a key: every bit of it (two lights 1e-7 apart trace different references).
std::string exactText(double v);
std::string exactText(const glm::vec3& v);  // "x,y,z", each exactly

// Every bit of the scene, size, seed, camera and light: two views with one key trace the same
// reference (the scene's near and far planes come with its name and seed).
std::string traceKey(const TraceView& view);

// The reference of `view`, traced here: the scene loaded and displaced as the renderer does.
ReferenceImage traceView(const TraceView& view);

nlohmann::json traceViewJson(const TraceView& view);
// Throws std::invalid_argument on a malformed view.
TraceView traceViewFromJson(const nlohmann::json& j);

// A reference as bytes (its pixels as they lie in memory: the page and its workers run one
// program, so one layout) and back; `fromBytes` throws std::invalid_argument on a size that
// does not match.
std::string referenceBytes(const ReferenceImage& image);
ReferenceImage referenceFromBytes(int width, int height, int mirrorObjectId, const void* bytes,
                                  std::size_t size);

}  // namespace sl
