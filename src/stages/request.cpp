#include "stages/request.h"

#include <sys/stat.h>

#include <sstream>

#include "io/data_paths.h"
#include "io/usage_error.h"
#include "scene/mirror_displace.h"
#include "scene/scene_json.h"
#include "stages/registry.h"

namespace sl {

std::string shaderTreeRoot(GlslTree tree) {
    std::string name = tree == GlslTree::Core ? "/shaders_core" : "/shaders_legacy";
    // An install with the `solutions` component: its marked trees, not the student edition's
    // stubs beside them (CMakeLists.txt, docs/assignment.md "A student edition").
    struct stat st;
    std::string solutions = dataDir() + "/solutions" + name;
    if (::stat(solutions.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) return solutions;
    return dataDir() + name;
}

bool isStudentEdition(GlslTree tree) {
    struct stat st;
    std::string note = shaderTreeRoot(tree) + "/" + kStudentEditionNote;
    return ::stat(note.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

void validateRequest(const RenderRequest& r) {
    const StageInfo* info = findStage(r.stage);
    if (!info) {
        std::string ids;
        for (const auto& s : stageIds()) ids += (ids.empty() ? "" : ", ") + s;
        std::string hint = closestMatch(r.stage, stageIds());
        throw UsageError("--stage: unknown stage '" + r.stage + "'" +
                         (hint.empty() ? "" : " (did you mean '" + hint + "'?)") +
                         "; stages: " + ids);
    }
    if (info->legacyOnly && r.tree == GlslTree::Core)
        throw UsageError("--glsl core: stage '" + r.stage +
                         "' is the fixed-function method and needs the compatibility profile; "
                         "use --glsl legacy");
    bool viewOk = false;
    std::string views;
    for (ViewMode v : info->views) {
        viewOk = viewOk || v == r.view;
        views += (views.empty() ? "" : ", ") + std::string(viewName(v));
    }
    if (!viewOk)
        throw UsageError("--view " + std::string(viewName(r.view)) + ": stage '" + r.stage +
                         "' offers: " + views);
    ParamSet probe(info->params);
    for (const auto& [name, value] : r.sets) {
        std::string err = probe.set(name, value);
        if (!err.empty()) throw UsageError("--set " + name + "=" + value + ": " + err);
    }
    if (!r.overlay.empty()) {
        struct stat st;
        if (::stat(r.overlay.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
            throw UsageError("--shaders: '" + r.overlay + "' is not a folder");
    }
}

namespace {

// The same rules as a scene file's light: not inside an object, not at its own target (the
// light would have no direction to look in).
void checkLightPosition(const Scene& scene, const glm::vec3& light) {
    std::ostringstream where;
    where << "--light " << light.x << "," << light.y << "," << light.z << ": ";
    for (const Object& o : scene.objects)
        if (pointInside(o, light))
            throw UsageError(where.str() + "the light is inside the object '" + o.name + "'");
    if (glm::length(scene.light.target - light) < 1e-6f)
        throw UsageError(where.str() +
                         "the light is at its own target (the scene's light target); "
                         "move it");
}

}  // namespace

void applyRequest(Renderer& renderer, const RenderRequest& r) {
    validateRequest(r);
    renderer.selectStage(r.stage);
    if (r.eye) renderer.camera.eye = *r.eye;
    if (r.at) renderer.camera.at = *r.at;
    if (r.fovy) renderer.camera.fovyDegrees = *r.fovy;
    if (r.light) {
        checkLightPosition(renderer.scene(), *r.light);
        renderer.lightPosition = *r.light;
    }
    if (glm::length(renderer.camera.at - renderer.camera.eye) < 1e-6f)
        throw UsageError("--eye/--at: the camera needs distinct eye and at points");
    renderer.view = r.view;
    for (const auto& [name, value] : r.sets) renderer.params().set(name, value);
}

std::string effectiveScene(const RenderRequest& r) {
    const StageInfo* info = findStage(r.stage);
    if (!r.sceneGiven && r.scene == "slides" && info && !info->defaultScene.empty())
        return info->defaultScene;
    return r.scene;
}

std::unique_ptr<Renderer> makeRenderer(const RenderRequest& r) {
    validateRequest(r);
    std::string sceneName = effectiveScene(r);
    Scene scene = loadScene(sceneName);
    if (r.displaceSeed) scene = displacedViewOf(scene, *r.displaceSeed);
    const StageInfo* info = findStage(r.stage);
    if (info->needsMirror && !scene.mirror)
        throw UsageError("--scene " + sceneName + ": stage '" + r.stage +
                         "' needs a scene with a \"mirror\" (its default is --scene " +
                         (info->defaultScene.empty() ? "mirror" : info->defaultScene) + ")");
    Camera camera = scene.camera;
    if (r.eye) camera.eye = *r.eye;
    if (r.at) camera.at = *r.at;
    if (r.fovy) camera.fovyDegrees = *r.fovy;
    scene.camera = camera;  // tessellation sees the camera actually used
    auto renderer = std::make_unique<Renderer>(
        std::move(scene), ShaderLibrary(r.tree, shaderTreeRoot(r.tree), r.overlay), r.height,
        stageInfos());
    applyRequest(*renderer, r);
    return renderer;
}

}  // namespace sl
