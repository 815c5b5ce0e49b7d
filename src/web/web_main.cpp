// The browser edition's entry (GUIDE section 9): the page (src/web/index.html) calls these C
// functions, which drive the same requests, renderer and stages as `shadowlab render` and the
// window. Strings returned to the page stay valid until the next call.
#include <emscripten/emscripten.h>

#include <cstdlib>
#include <memory>
#include <string>

#include "math/orbit.h"
#include "platform/webgl_context.h"
#include "render/request.h"

namespace {

struct Page {
    sl::RenderRequest request;
    std::unique_ptr<sl::Renderer> renderer;
    std::string text;  // the last string handed to the page
};

Page& page() {
    static Page p;
    return p;
}

const char* handOver(std::string text) {
    page().text = std::move(text);
    return page().text.c_str();
}

// Draws the current stage into the canvas; "" or what went wrong (a GL error names its call).
std::string drawFrame() {
    Page& p = page();
    if (!p.renderer) return "no stage selected";
    p.renderer->render(0, p.request.width, p.request.height);
    GLenum error = glGetError();
    return error == GL_NO_ERROR ? "" : "WebGL error 0x" + std::to_string(error) + " in the frame";
}

}  // namespace

extern "C" {

EMSCRIPTEN_KEEPALIVE const char* sl_web_start(int width, int height) {
    setenv("SHADOWLAB_DATA_DIR", "/data", 1);  // the embedded files (cmake/web.cmake)
    page().request.width = width;
    page().request.height = height;
    return handOver(sl::createWebGl2Context("#canvas"));
}

EMSCRIPTEN_KEEPALIVE int sl_web_stage_count() {
    return static_cast<int>(sl::stageRegistry().size());
}

// "id\ttitle\tlecture\tnative-only" of stage i, from the stage's own declaration.
EMSCRIPTEN_KEEPALIVE const char* sl_web_stage(int index) {
    const sl::StageInfo& s = sl::stageRegistry().at(static_cast<std::size_t>(index));
    return handOver(s.id + "\t" + s.title + "\t" + s.lecture + "\t" + (s.legacyOnly ? "1" : "0"));
}

// Builds the stage's renderer (its default scene, camera and parameters) and draws it.
EMSCRIPTEN_KEEPALIVE const char* sl_web_select(const char* id) {
    Page& p = page();
    const sl::StageInfo* info = sl::findStage(id);
    if (info && info->legacyOnly)
        return handOver("stage '" + info->id +
                        "' needs desktop OpenGL's fixed function or GLSL 1.20, which WebGL lacks: "
                        "run the native program (shadowlab window --stage " + info->id + ")");
    try {
        sl::RenderRequest request = p.request;
        request.stage = id;
        sl::validateRequest(request);
        p.renderer = sl::makeRenderer(request);
        p.request = request;
        return handOver(drawFrame());
    } catch (const std::exception& e) {
        return handOver(e.what());
    }
}

EMSCRIPTEN_KEEPALIVE const char* sl_web_frame() {
    try {
        return handOver(drawFrame());
    } catch (const std::exception& e) {
        return handOver(e.what());
    }
}

// Turns the camera around its target (radians), as the window's drag does, and redraws.
EMSCRIPTEN_KEEPALIVE const char* sl_web_orbit(float yaw, float pitch) {
    Page& p = page();
    if (!p.renderer) return handOver("no stage selected");
    const sl::Scene& scene = p.renderer->scene();
    p.renderer->camera =
        sl::orbitCamera(p.renderer->camera, yaw, pitch, sl::sceneReceiverHeight(scene));
    return sl_web_frame();
}

// What the stage did in the last frame (the HUD's notes), one a line.
EMSCRIPTEN_KEEPALIVE const char* sl_web_notes() {
    std::string text;
    if (page().renderer)
        for (const auto& note : page().renderer->stats.notes) text += note + "\n";
    return handOver(text);
}

}  // extern "C"

int main() {
    return 0;  // the page calls in; the runtime stays (EXIT_RUNTIME is off)
}
