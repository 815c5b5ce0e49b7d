// The browser edition's entry (GUIDE section 9): the page (src/web/index.html) calls these C
// functions, which drive the same requests, renderer and stages as `shadowlab render` and the
// window. Strings returned to the page stay valid until the next call.
#include <emscripten/emscripten.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "grade/intake.h"
#include "io/files.h"
#include "lecture/lessons.h"
#include "math/orbit.h"
#include "platform/webgl_context.h"
#include "stages/registry.h"
#include "stages/request.h"
#include "web/split_view.h"
#include "web/taken_folder.h"

namespace {

struct Page {
    sl::RenderRequest request;
    std::unique_ptr<sl::Renderer> renderer;
    std::size_t lesson = 0;    // the stage's lesson `n` chose last (lecture/lessons.h)
    bool split = false;        // `s`: the split view's two halves side by side
    std::string overlay;       // the student's snapshot (intake), laid over ours; "" for none
    int snapshots = 0;         // snapshots taken: each in a fresh folder
    std::string snapshotDir;   // the folder holding `overlay`
    std::string overlayShown;  // how messages name `overlay`'s files (the folder as picked)
    // The folder last picked as the page copied it (kept until the next one): what the page's
    // check takes again, as `check --shaders` takes the folder it is given.
    std::string upload, uploadName;
    std::string text;       // the last string handed to the page
    sl::Camera homeCamera;  // where the stage's renderer began: `c` goes back
    glm::vec3 homeLight{0.0f};
};

Page& page() {
    static Page p;
    return p;
}

const char* handOver(std::string text) {
    page().text = std::move(text);
    return page().text.c_str();
}

// The stage's lessons the core tree runs, in the window's order (lecture/lessons.h: the entries
// of expectations.json, then the lecture figures of slides_examples/), and the one `n` chose.
sl::LessonChoice stageLessons(const std::string& stage) {
    static const std::vector<sl::WindowLesson> all = sl::windowLessons();
    return {sl::lessonsOf(all, stage, "core"), page().lesson};
}

// A request for `stage` at the canvas's size over the student's shaders, the rest defaults.
sl::RenderRequest baseRequest(const std::string& stage) {
    sl::RenderRequest request;
    request.width = page().request.width;
    request.height = page().request.height;
    request.stage = stage;
    request.overlay = page().overlay;
    return request;
}

// The lesson whose settings are on screen (-1: none), as the window's HUD finds it.
int shownLesson() {
    Page& p = page();
    if (!p.renderer) return -1;
    const std::string stageScene = sl::effectiveScene(baseRequest(p.request.stage));
    return sl::matchingLesson(
        stageLessons(p.request.stage),
        {&p.renderer->params(), sl::effectiveScene(p.request), stageScene, p.renderer->view});
}

std::vector<sl::SplitHalf> splitHalves() {
    Page& p = page();
    if (!p.renderer) return {};
    return sl::splitHalves(p.renderer->params(), stageLessons(p.request.stage), shownLesson());
}

// Draws the current stage into the canvas (both halves in the split view); "" or what went
// wrong (a GL error names its call).
std::string drawFrame() {
    Page& p = page();
    if (!p.renderer) return "no stage selected";
    // Another stage, or its only lesson: no pair to split, as in the window.
    const auto halves = p.split ? splitHalves() : std::vector<sl::SplitHalf>{};
    if (halves.empty()) p.split = false;
    if (p.split)
        sl::web::drawSplitHalves(*p.renderer, p.request.width, p.request.height, halves);
    else
        p.renderer->render(0, p.request.width, p.request.height);
    GLenum error = glGetError();
    if (error == GL_NO_ERROR) return "";
    char code[16];
    std::snprintf(code, sizeof code, "0x%04X", error);
    return std::string("WebGL error ") + code + " in the frame";
}

// `text` with the page's copy of a student's folder named as the student picked it
// ("mywork/margin/lit.frag"), not where the page keeps it.
std::string asPicked(std::string text, const std::string& copy, const std::string& name) {
    for (std::size_t at = 0; (at = text.find(copy, at)) != std::string::npos; at += name.size())
        text.replace(at, copy.size(), name);
    return text;
}

// Rebuilds the renderer for `request` and draws; "" or the one-line reason. What fails to build
// or draw (a student's compile error) leaves the last good renderer and its picture.
std::string show(const sl::RenderRequest& request) {
    Page& p = page();
    std::unique_ptr<sl::Renderer> previous = std::move(p.renderer);
    sl::RenderRequest previousRequest = p.request;
    try {
        sl::validateRequest(request);
        p.renderer = sl::makeRenderer(request);
        p.request = request;
        p.homeCamera = p.renderer->camera;
        p.homeLight = p.renderer->lightPosition;
        return drawFrame();
    } catch (const std::exception& e) {
        std::string message = e.what();
        p.renderer = std::move(previous);
        p.request = previousRequest;
        if (p.renderer) {
            try {
                drawFrame();
            } catch (const std::exception&) {  // the message above is the one that matters
            }
        }
        return message;
    }
}

}  // namespace

sl::web::PickedFolder sl::web::pickedFolder() {
    return {page().upload, page().uploadName};
}

std::string sl::web::insidePicked(const PickedFolder& picked, const std::string& read) {
    return read.substr(std::min(read.size(), picked.path.size() + 1));
}

std::string sl::web::shownAsPicked(const PickedFolder& picked, const std::string& read) {
    const std::string inside = insidePicked(picked, read);
    return picked.name + (inside.empty() ? "" : "/" + inside);
}

std::string sl::web::asPicked(const std::string& text) {
    return page().upload.empty() ? text : ::asPicked(text, page().upload, page().uploadName);
}

void sl::web::nameDrawnFolder() {
    const Page& p = page();
    sl::showFolderAs(p.overlay, p.overlay.empty() ? "" : p.overlayShown);
}

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
    p.lesson = 0;  // the stage's defaults: scene, camera, parameters, view
    return handOver(show(baseRequest(id)));
}

// The window's 'n' (lecture/lessons.h, as the window steps): the lesson after the one on
// screen with its settings (scene, values, view) applied, after the last the first.
EMSCRIPTEN_KEEPALIVE const char* sl_web_next_lesson() {
    Page& p = page();
    sl::LessonChoice lessons = stageLessons(p.request.stage);
    if (lessons.list.empty()) return handOver("n: this stage has no lessons");
    const std::size_t next = sl::nextLessonIndex(lessons, shownLesson());
    const sl::WindowLesson& l = *lessons.list[next];
    sl::RenderRequest request = baseRequest(p.request.stage);
    if (!l.scene.empty()) {
        request.scene = l.scene;
        request.sceneGiven = true;
    }
    request.sets = l.sets;
    request.view = l.view;
    p.lesson = next;
    return handOver(show(request));
}

// The HUD's lesson line (lecture/lessons.h): the lesson on screen and what to look for, or that
// the settings are none of the stage's lessons; "" for a stage without lessons.
EMSCRIPTEN_KEEPALIVE const char* sl_web_lesson_text() {
    return handOver(sl::lessonLine(stageLessons(page().request.stage), shownLesson()));
}

// The window's 's': the split view on or off, and a redraw; "" or why not (no pair to show).
EMSCRIPTEN_KEEPALIVE const char* sl_web_split() {
    Page& p = page();
    if (!p.renderer) return handOver("no stage selected");
    p.split = !p.split;
    if (p.split && splitHalves().empty()) {
        p.split = false;
        return handOver("s: this stage has no second lesson in this scene to show beside it");
    }
    try {
        return handOver(drawFrame());
    } catch (const std::exception& e) {
        return handOver(e.what());
    }
}

// The split view's halves on screen, "NAME\tNAME=VALUE,NAME=VALUE" a half a line ("" when the
// split is off): what each half draws with (the browser test renders the same natively).
EMSCRIPTEN_KEEPALIVE const char* sl_web_split_sets() {
    return handOver(page().split ? sl::web::splitSetsText(splitHalves()) : "");
}

// The window's compact HUD for the picture on screen (web/split_view.h: "PLACE\tTEXT" a line),
// with parameter `selected` (the page's Tab).
EMSCRIPTEN_KEEPALIVE const char* sl_web_hud(int selected) {
    Page& p = page();
    if (!p.renderer) return handOver("");
    return handOver(sl::web::hudText(*p.renderer, std::size_t(std::max(0, selected)),
                                     {p.overlay.empty() ? "" : p.overlayShown},
                                     sl::lessonLine(stageLessons(p.request.stage), shownLesson()),
                                     p.split ? splitHalves() : std::vector<sl::SplitHalf>{}));
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

}  // extern "C"

namespace {

// A camera or light change the page asked for (a drag, `l`, `c`), then the stage redrawn.
template <class Change>
const char* redrawAfter(Change change) {
    Page& p = page();
    if (!p.renderer) return handOver("no stage selected");
    change(p);
    return sl_web_frame();
}

}  // namespace

extern "C" {

// Turns the camera around its target (radians), as the window's drag does, and redraws.
EMSCRIPTEN_KEEPALIVE const char* sl_web_orbit(float yaw, float pitch) {
    return redrawAfter([=](Page& p) {
        const sl::Scene& scene = p.renderer->scene();
        p.renderer->camera =
            sl::orbitCamera(p.renderer->camera, yaw, pitch, sl::sceneReceiverHeight(scene));
    });
}

// The window's `l`, a step of it: the light circles the scene for `seconds` (at most one: a
// longer gap is a pause, not a jump), and the stage redraws.
EMSCRIPTEN_KEEPALIVE const char* sl_web_turn_light(double seconds) {
    return redrawAfter([=](Page& p) {
        p.renderer->lightPosition = sl::circlingLight(
            p.renderer->lightPosition, sl::kLightRadiansPerSecond, std::clamp(seconds, 0.0, 1.0));
    });
}

// The window's `c`: camera and light back where the stage began.
EMSCRIPTEN_KEEPALIVE const char* sl_web_home() {
    return redrawAfter([](Page& p) {
        p.renderer->camera = p.homeCamera;
        p.renderer->lightPosition = p.homeLight;
    });
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

// Takes the student's folder (the page wrote it under /student) as `--shaders` does: the same
// intake (wrapper folders, junk, near misses named in notes), a private snapshot laid over our
// tree, then the current stage redrawn with it. Messages name files under `name` (the folder as
// the student picked it). "NOTES\tERROR\tREAD": the intake's notes one a line; ERROR "" or the
// one line that refused the folder or failed to compile (the last good picture stays); READ the
// folder the intake read inside the one picked ("" for itself). An empty `folder` goes back to
// our shaders.
EMSCRIPTEN_KEEPALIVE const char* sl_web_student_folder(const char* folder, const char* name) {
    Page& p = page();
    std::string notes;
    std::string overlay;
    std::string read;
    std::string snapshot;
    std::string shown;  // how messages name the snapshot's files
    // The page's memory holds the snapshot drawn and the folder last picked (the check's).
    if (!p.upload.empty() && p.upload != folder) std::filesystem::remove_all(p.upload);
    p.upload = folder;
    p.uploadName = name;
    if (*folder) {
        snapshot = "/student/snapshot-" + std::to_string(++p.snapshots);
        try {
            std::filesystem::create_directories(snapshot);
            sl::Submission taken =
                sl::takeSubmission(folder, snapshot, sl::shippedTrees().both, {p.request.stage});
            // Messages name the student's own folder (its name as picked), never the copies.
            read = sl::web::insidePicked({folder, name}, taken.folder);
            shown = sl::web::shownAsPicked({folder, name}, taken.folder);
            sl::showFolderAs(taken.root, shown);
            for (auto& note : taken.notes) {
                note = asPicked(note, folder, name);
                notes += note + "\n";
            }
            overlay = taken.root;
        } catch (const std::exception& e) {
            std::filesystem::remove_all(snapshot);
            return handOver(notes + "\t" + asPicked(e.what(), folder, name) + "\t");
        }
    }
    std::string before = p.overlay;
    p.overlay = overlay;
    sl::RenderRequest request = baseRequest(p.request.stage);
    request.scene = p.request.scene;
    request.sceneGiven = p.request.sceneGiven;
    request.sets = p.request.sets;
    request.view = p.request.view;
    std::string error = show(request);
    bool adopted = p.request.overlay == overlay;
    if (adopted) {
        p.overlayShown = shown;
    } else {  // the drawn snapshot's files keep their names in later messages
        p.overlay = before;
    }
    sl::web::nameDrawnFolder();
    // The page's memory holds one snapshot: the one drawn.
    std::string dropped = adopted ? p.snapshotDir : snapshot;
    if (adopted) p.snapshotDir = snapshot;
    if (!dropped.empty()) std::filesystem::remove_all(dropped);
    return handOver(notes + "\t" + error + "\t" + read);
}

// The intake's bounds (grade/intake.h), "entries\tfileBytes\ttotalBytes": the page copies no
// more than one past each into memory, so the intake itself says what was too much.
EMSCRIPTEN_KEEPALIVE const char* sl_web_intake_limits() {
    return handOver(std::to_string(sl::kIntakeLimits.entries) + "\t" +
                    std::to_string(sl::kIntakeLimits.fileBytes) + "\t" +
                    std::to_string(sl::kIntakeLimits.totalBytes));
}

// The window's '+' and '-': the declared parameter one step up or down (ParamSet::step, as the
// window steps it), and a redraw; "" or the one-line reason.
EMSCRIPTEN_KEEPALIVE const char* sl_web_step(const char* name, int direction) {
    if (!page().renderer) return handOver("no stage selected");
    page().renderer->params().step(name, direction);
    return sl_web_frame();
}

// What `check` notes of the student's files of the stage on screen, one a line: the stage's
// source rules (gl/source_rules.h) and uniforms a student's pass uses but the stage never sets.
EMSCRIPTEN_KEEPALIVE const char* sl_web_student_notes() {
    Page& p = page();
    std::string text;
    if (!p.renderer || p.overlay.empty()) return handOver(text);
    sl::ShaderLibrary& shaders = p.renderer->shaders();
    std::vector<std::string> notes;
    if (const sl::StageDefinition* stage = sl::findStage(p.request.stage))
        notes = shaders.sourceNotes(p.request.stage, stage->sourceRules);
    for (const auto& note : shaders.unsetUniformNotes(p.request.stage)) notes.push_back(note);
    for (const auto& note : notes) text += sl::withShownFolders(note) + "\n";
    return handOver(text);
}

// Draws the stage on screen `frames` more times, each waited for (a one-pixel read: WebGL's
// finish does not wait), and returns the median milliseconds a frame, as `shadowlab render`
// prints its own (render + glFinish); -1 when nothing is on screen.
EMSCRIPTEN_KEEPALIVE double sl_web_frame_ms(int frames) {
    Page& p = page();
    if (!p.renderer || frames < 1) return -1;
    std::vector<double> times;
    for (int k = 0; k < frames; ++k) {
        double start = emscripten_get_now();
        p.renderer->render(0, p.request.width, p.request.height);
        unsigned char pixel[4];
        glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
        times.push_back(emscripten_get_now() - start);
    }
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

// The stage whose picture is on screen: a stage whose shaders failed leaves the last good one.
EMSCRIPTEN_KEEPALIVE const char* sl_web_stage_on_screen() {
    return handOver(page().renderer ? page().request.stage : "");
}

// What WebGL compiled for the stage on screen: each stage file's ESSL 3.00 translation
// (gl/glsl_for_driver.h), "// FILE" before each.
EMSCRIPTEN_KEEPALIVE const char* sl_web_translation() {
    std::string text;
    if (page().renderer)
        for (const auto& [file, essl] :
             page().renderer->shaders().driverTexts(page().request.stage))
            text += "// " + file + "\n" + essl + "\n";
    return handOver(text);
}

}  // extern "C"

int main() {
    return 0;  // the page calls in; the runtime stays (EXIT_RUNTIME is off)
}
