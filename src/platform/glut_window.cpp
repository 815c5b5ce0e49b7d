#include "platform/glut_window.h"

#include "gl/gl.h"  // before freeglut, which would pull in GL/gl.h
#include <GL/freeglut.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "gl/loader.h"
#include "render/hud.h"

namespace sl {

namespace {

// freeglut's callbacks are plain functions, so the window's state lives here.
struct WindowState {
    WindowArgs args;
    RenderRequest request;
    std::unique_ptr<Renderer> renderer;
    std::unique_ptr<Hud> hud;
    int width = 0, height = 0;
    int frame = 0;
    int exitCode = kOk;
    std::size_t selectedParam = 0;
    bool showHelp = false;
    bool animateLight = false;
    float lightAngle = 0;
    std::string error;  // last shader error, shown until a reload succeeds
    double frameMs = 0;
    std::chrono::steady_clock::time_point lastPoll = std::chrono::steady_clock::now();
    std::chrono::steady_clock::time_point lastFrame = std::chrono::steady_clock::now();
    int dragX = -1, dragY = -1;
    bool resizeDone = false;  // --resize-test finished
    int resizeFrames = 0;     // frames the resize script took
};
WindowState* g = nullptr;

const char* kHelp[] = {
    "0-9 stage   [ ] previous/next stage   Tab parameter   + - change it",
    "v view   l animate light   left-drag orbit   r reload shaders   p save PNG",
    "h help   Esc quit",
};

void reportShaderErrors(const std::vector<std::string>& errors) {
    for (const auto& e : errors) std::cerr << "shadowlab: shader error (keeping the last good program):\n" << e;
    if (!errors.empty()) g->error = errors.front();
}

std::vector<HudLine> hudLines() {
    Renderer& r = *g->renderer;
    const StageInfo& s = r.stage();
    std::vector<HudLine> lines;
    std::ostringstream title;
    title << r.stageIndex() << " " << s.id << ": " << s.title << "   [" << treeName(r.shaders().tree())
          << ", view " << viewName(r.view) << "]   " << static_cast<int>(g->frameMs * 10) / 10.0 << " ms/frame";
    lines.push_back({title.str(), {1, 1, 0.6f, 1}});
    const auto& specs = r.params().specs();
    for (std::size_t i = 0; i < specs.size(); ++i) {
        bool selected = i == g->selectedParam;
        lines.push_back({std::string(selected ? "> " : "  ") + specs[i].name + " = " +
                             r.params().text(specs[i].name),
                         selected ? glm::vec4(0.5f, 1, 0.5f, 1) : glm::vec4(0.9f, 0.9f, 0.9f, 1)});
    }
    for (const auto& n : r.stats.notes) lines.push_back({n, {0.7f, 0.8f, 1, 1}});
    if (g->showHelp)
        for (const char* h : kHelp) lines.push_back({h, {1, 1, 1, 1}});
    if (!g->error.empty()) {
        std::istringstream in(g->error);
        std::string line;
        for (int k = 0; k < 6 && std::getline(in, line); ++k) lines.push_back({line, {1, 0.4f, 0.4f, 1}});
    }
    return lines;
}

void savePng(const std::string& path) {
    Image img(g->width, g->height);
    std::vector<std::uint8_t> bottomUp(img.rgba.size());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, g->width, g->height, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
    std::size_t row = std::size_t(g->width) * 4;
    for (int j = 0; j < g->height; ++j)
        std::copy_n(&bottomUp[std::size_t(g->height - 1 - j) * row], row, &img.rgba[std::size_t(j) * row]);
    std::string err = writePng(path, img);
    if (!err.empty()) {
        std::cerr << "shadowlab: " << err << "\n";
        g->exitCode = kBadInput;
    } else {
        std::cout << "saved " << path << "\n";
    }
}

void keyboard(unsigned char key, int, int);
void reshape(int w, int h);

// --resize-test, one step at a time: each waits (a bounded number of frames) until the size it
// asked for has arrived, so the test does not depend on how fast the X server answers.
// A minimised window reports 0x0 through the reshape callback; X itself cannot make a 0x0
// window, so those steps call the callback as freeglut would. The real X resizes go to 16x16:
// under Xvfb (no window manager) a real 1x1 window stops freeglut's redisplays altogether, so
// 1x1 is reached through the callback too.
struct ResizeStep {
    int width, height;
    bool callbackOnly;
};

void runResizeScript() {
    static std::size_t step = 0;
    static int waited = 0;
    const int w = g->request.width, h = g->request.height;
    const ResizeStep steps[] = {{0, 0, true}, {w, h, true}, {16, 16, false},
                                {0, 0, true}, {1, 1, true}, {w, h, false}};
    const std::size_t count = sizeof(steps) / sizeof(steps[0]);
    if (step > count) return;
    if (step > 0) {  // wait for the previous step's size
        const ResizeStep& s = steps[step - 1];
        if ((g->width != s.width || g->height != s.height) && ++waited < 500) return;
        if (waited >= 500) {
            std::cerr << "shadowlab: --resize-test: the window never reached " << s.width << "x"
                      << s.height << "\n";
            g->exitCode = kGlFailure;
        }
    }
    waited = 0;
    if (step < count) {
        const ResizeStep& s = steps[step];
        if (s.callbackOnly)
            reshape(s.width, s.height);
        else
            glutReshapeWindow(s.width, s.height);
    }
    ++step;
    g->resizeDone = step > count;
}

// The scripted input of --keys and --resize-test, applied after frame `frame` was drawn.
void runScript(int frame) {
    const std::string& keys = g->args.keys;
    if (frame >= 1 && std::size_t(frame) <= keys.size())
        keyboard(static_cast<unsigned char>(keys[std::size_t(frame) - 1]), 0, 0);
    if (g->args.resizeTest) runResizeScript();
}

// Counts a frame and ends the loop after the last one (with --frames).
bool finishFrame() {
    ++g->frame;
    if (g->args.resizeTest && !g->resizeDone) ++g->resizeFrames;
    runScript(g->frame);
    // The resize script's frames come on top of --frames: the last ones are drawn at full size.
    return g->args.frames > 0 && g->frame >= g->args.frames + g->resizeFrames &&
           (!g->args.resizeTest || g->resizeDone);
}

void display() {
    if (g->width <= 0 || g->height <= 0) {  // minimised or 0x0: nothing to draw, time goes on
        if (finishFrame()) glutLeaveMainLoop();
        return;
    }
    auto now = std::chrono::steady_clock::now();
    if (now - g->lastPoll > std::chrono::milliseconds(500)) {  // hot reload of edited shaders
        g->lastPoll = now;
        auto errors = g->renderer->reloadShaders(false);
        reportShaderErrors(errors);
    }
    if (g->animateLight) {
        glm::vec3 p = g->renderer->scene().light.position;
        float radius = std::hypot(p.x, p.z);
        g->lightAngle += 0.02f;
        g->renderer->lightPosition = {radius * std::cos(g->lightAngle), p.y, radius * std::sin(g->lightAngle)};
    }
    try {
        g->renderer->render(0, g->width, g->height);
    } catch (const ShaderError& e) {  // no good program yet for this stage: show why
        glClearColor(0.2f, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        if (g->error != e.what()) std::cerr << "shadowlab: shader error:\n" << e.what();
        g->error = e.what();
        if (g->args.frames > 0) g->exitCode = kBadInput;
    }
    bool last = g->args.frames > 0 && g->frame + 1 >= g->args.frames + g->resizeFrames &&
                (!g->args.resizeTest || g->resizeDone);
    if (last && !g->args.screenshot.empty()) savePng(g->args.screenshot);  // the scene, no HUD
    g->hud->draw(g->renderer->shaders(), hudLines(), g->width, g->height, g->height >= 700 ? 2.0f : 1.0f);
    glutSwapBuffers();
    now = std::chrono::steady_clock::now();
    g->frameMs = 0.9 * g->frameMs + 0.1 * std::chrono::duration<double, std::milli>(now - g->lastFrame).count();
    g->lastFrame = now;
    if (glErrorCount() > 0 && g->args.frames > 0) g->exitCode = kGlFailure;
    if (finishFrame()) glutLeaveMainLoop();
}

void selectStage(std::size_t index) {
    if (index >= stageRegistry().size()) return;
    const StageInfo& s = stageRegistry()[index];
    if (s.legacyOnly && g->renderer->shaders().tree() == GlslTree::Core) {
        g->error = "stage '" + s.id + "' needs the compatibility profile: start with --glsl legacy";
        return;
    }
    g->error.clear();
    g->renderer->selectStage(index);
    g->selectedParam = 0;
    bool viewOk = false;
    for (ViewMode v : s.views) viewOk = viewOk || v == g->renderer->view;
    if (!viewOk) g->renderer->view = ViewMode::Final;
}

void keyboard(unsigned char key, int, int) {
    Renderer& r = *g->renderer;
    const auto& specs = r.params().specs();
    switch (key) {
        case 27: glutLeaveMainLoop(); return;
        case '[': selectStage((r.stageIndex() + stageRegistry().size() - 1) % stageRegistry().size()); break;
        case ']': selectStage((r.stageIndex() + 1) % stageRegistry().size()); break;
        case '\t':
            if (!specs.empty()) g->selectedParam = (g->selectedParam + 1) % specs.size();
            break;
        case '+': case '=': case '-': case '_':
            if (!specs.empty()) r.params().step(specs[g->selectedParam].name, (key == '+' || key == '=') ? 1 : -1);
            break;
        case 'r': {
            auto errors = r.reloadShaders(true);
            if (errors.empty()) g->error.clear();
            reportShaderErrors(errors);
            break;
        }
        case 'p': {
            std::string name = "shadowlab-" + r.stage().id + "-" + std::to_string(g->frame) + ".png";
            r.render(0, g->width, g->height);
            savePng(name);
            break;
        }
        case 'h': g->showHelp = !g->showHelp; break;
        case 'l': g->animateLight = !g->animateLight; break;
        case 'v': {
            const auto& views = r.stage().views;
            std::size_t i = 0;
            while (i < views.size() && views[i] != r.view) ++i;
            r.view = views[(i + 1) % views.size()];
            break;
        }
        default:
            if (key >= '0' && key <= '9') selectStage(static_cast<std::size_t>(key - '0'));
    }
    glutPostRedisplay();
}

void reshape(int w, int h) {
    g->width = w;
    g->height = h;
}

void mouse(int button, int state, int x, int y) {
    if (button != GLUT_LEFT_BUTTON) return;
    g->dragX = state == GLUT_DOWN ? x : -1;
    g->dragY = y;
}

void motion(int x, int y) {  // orbit the camera around its target
    if (g->dragX < 0) return;
    Camera& c = g->renderer->camera;
    glm::vec3 d = c.eye - c.at;
    float radius = glm::length(d);
    float yaw = std::atan2(d.x, d.z) - (x - g->dragX) * 0.01f;
    float pitch = std::asin(glm::clamp(d.y / radius, -1.0f, 1.0f)) + (y - g->dragY) * 0.01f;
    pitch = glm::clamp(pitch, -1.5f, 1.5f);
    c.eye = c.at + radius * glm::vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
    g->dragX = x;
    g->dragY = y;
}

}  // namespace

int runWindow(const WindowArgs& args) {
    WindowState state;
    state.args = args;
    state.request = toRequest(args.common);
    validateRequest(state.request);
    if (!args.screenshot.empty() && args.frames <= 0)
        throw UsageError("--screenshot needs --frames N (the frame to save)");
    if ((!args.keys.empty() || args.resizeTest) && args.frames <= 0)
        throw UsageError("--keys and --resize-test need --frames N (scripted input is for tests)");
    if (args.keys.find('\x1b') != std::string::npos)
        throw UsageError("--keys: Esc would quit before the last frame; leave it out");
    g = &state;

    int argc = 1;
    char name[] = "shadowlab";
    char* argv[] = {name, nullptr};
    glutInit(&argc, argv);
    glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_GLUTMAINLOOP_RETURNS);
    glutInitDisplayMode(GLUT_RGBA | GLUT_DOUBLE | GLUT_DEPTH | GLUT_STENCIL);
    glutInitWindowSize(state.request.width, state.request.height);
    if (state.request.tree == GlslTree::Core) {
        glutInitContextVersion(3, 3);
        glutInitContextProfile(GLUT_CORE_PROFILE);
    }
    glutCreateWindow("shadowlab");
    if (!loadGl(reinterpret_cast<GlProcLoader>(&glutGetProcAddress)))
        throw std::runtime_error("could not load GL entry points through glutGetProcAddress");
    installGlDebugOutput();
    state.width = state.request.width;
    state.height = state.request.height;
    state.renderer = makeRenderer(state.request);
    state.hud = std::make_unique<Hud>();

    glutDisplayFunc(display);
    glutIdleFunc(glutPostRedisplay);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutMouseFunc(mouse);
    glutMotionFunc(motion);
    glutMainLoop();
    int code = state.exitCode;
    state.hud.reset();
    state.renderer.reset();
    g = nullptr;
    return code;
}

}  // namespace sl
