// The browser edition's entry (GUIDE section 9): the page (src/web/index.html) calls these C
// functions, which drive the same requests, renderer and stages as `shadowlab render` and the
// window. Strings returned to the page stay valid until the next call.
#include <emscripten/emscripten.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "math/orbit.h"
#include "platform/webgl_context.h"
#include "stages/registry.h"
#include "stages/request.h"
#include "window/window_args.h"

namespace {

struct Page {
    sl::RenderRequest request;
    std::unique_ptr<sl::Renderer> renderer;
    int lesson = -1;   // the current stage's lesson on screen (-1: the defaults)
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
    if (error == GL_NO_ERROR) return "";
    char code[16];
    std::snprintf(code, sizeof code, "0x%04X", error);
    return std::string("WebGL error ") + code + " in the frame";
}

// The stage's lessons the core tree runs, in the window's order (window/lessons.cpp: the
// entries of expectations.json, then the lecture figures of slides_examples/).
std::vector<const sl::WindowLesson*> stageLessons(const std::string& stage) {
    static const std::vector<sl::WindowLesson> all = sl::windowLessons();
    std::vector<const sl::WindowLesson*> found;
    for (const auto& l : all)
        if (l.stage == stage &&
            (l.trees.empty() || std::find(l.trees.begin(), l.trees.end(), "core") != l.trees.end()))
            found.push_back(&l);
    return found;
}

// Rebuilds the renderer for `request` and draws; "" or the one-line reason.
std::string show(const sl::RenderRequest& request) {
    Page& p = page();
    try {
        sl::validateRequest(request);
        p.renderer = sl::makeRenderer(request);
        p.request = request;
        return drawFrame();
    } catch (const std::exception& e) {
        return e.what();
    }
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
                        "run the native program (shadowlab window --stage " +
                        info->id + ")");
    sl::RenderRequest request;  // the stage's defaults: scene, camera, parameters, view
    request.width = p.request.width;
    request.height = p.request.height;
    request.stage = id;
    p.lesson = -1;
    return handOver(show(request));
}

// The window's 'n': the stage's next lesson with its settings (scene, values, view) applied,
// after the last one the defaults again.
EMSCRIPTEN_KEEPALIVE const char* sl_web_next_lesson() {
    Page& p = page();
    auto lessons = stageLessons(p.request.stage);
    if (lessons.empty()) return handOver("");
    p.lesson = p.lesson + 1 < static_cast<int>(lessons.size()) ? p.lesson + 1 : -1;
    sl::RenderRequest request;
    request.width = p.request.width;
    request.height = p.request.height;
    request.stage = p.request.stage;
    if (p.lesson >= 0) {
        const sl::WindowLesson& l = *lessons[static_cast<std::size_t>(p.lesson)];
        if (!l.scene.empty()) {
            request.scene = l.scene;
            request.sceneGiven = true;
        }
        request.sets = l.sets;
        request.view = l.view;
    }
    int lesson = p.lesson;
    std::string message = show(request);
    p.lesson = lesson;
    return handOver(message);
}

// "lesson K/N: NAME\nLOOK" of the lesson on screen, or how many the stage has.
EMSCRIPTEN_KEEPALIVE const char* sl_web_lesson_text() {
    Page& p = page();
    auto lessons = stageLessons(p.request.stage);
    if (p.lesson < 0)
        return handOver(std::to_string(lessons.size()) + " lesson(s): n steps through them");
    const sl::WindowLesson& l = *lessons[static_cast<std::size_t>(p.lesson)];
    return handOver("lesson " + std::to_string(p.lesson + 1) + "/" +
                    std::to_string(lessons.size()) + ": " + l.name + "\n" + l.look);
}

// The window's 'v': the stage's next view (final, shadow map, light, ...), as the stage lists;
// "VIEW\tERROR" (ERROR empty when the frame drew).
EMSCRIPTEN_KEEPALIVE const char* sl_web_next_view() {
    Page& p = page();
    if (!p.renderer) return handOver("no stage selected");
    const auto& views = p.renderer->stage().views;
    if (views.empty()) return handOver(std::string(sl::viewName(p.renderer->view)) + "\t");
    auto at = std::find(views.begin(), views.end(), p.renderer->view);
    p.renderer->view = at == views.end() || at + 1 == views.end() ? views.front() : *(at + 1);
    p.request.view = p.renderer->view;
    try {
        return handOver(std::string(sl::viewName(p.renderer->view)) + "\t" + drawFrame());
    } catch (const std::exception& e) {
        return handOver(std::string(sl::viewName(p.renderer->view)) + "\t" + e.what());
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

// The stage's declared parameters with their values: "name\tvalue\trange\thelp" a line.
EMSCRIPTEN_KEEPALIVE const char* sl_web_params() {
    std::string text;
    if (page().renderer) {
        sl::ParamSet& values = page().renderer->params();
        for (const auto& spec : values.specs())
            text += spec.name + "\t" + values.text(spec.name) + "\t" + spec.rangeText() + "\t" +
                    spec.help + "\n";
    }
    return handOver(text);
}

// Sets a declared parameter from text (as --set does) and redraws; "" or the one-line reason.
EMSCRIPTEN_KEEPALIVE const char* sl_web_set(const char* name, const char* value) {
    if (!page().renderer) return handOver("no stage selected");
    std::string error = page().renderer->params().set(name, value);
    return error.empty() ? sl_web_frame() : handOver(error);
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
