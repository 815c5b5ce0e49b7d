// libFuzzer target: the JSON scene loader (and the tessellation that follows it) on arbitrary
// bytes. A SceneError is the expected answer to bad input; anything else that escapes, and any
// sanitizer report, is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "scene/mesh.h"
#include "scene/scene_json.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string text(reinterpret_cast<const char*>(data), size);
    try {
        sl::Scene scene = sl::parseScene(text, "fuzz");
        // A small image keeps the sphere tessellation cheap; the budget must hold anyway.
        sl::SceneMesh mesh = sl::tessellate(scene, scene.camera, 64);
        if (mesh.objects.size() != scene.objects.size()) __builtin_trap();
    } catch (const sl::SceneError&) {
        // bad input, reported cleanly
    }
    return 0;
}
