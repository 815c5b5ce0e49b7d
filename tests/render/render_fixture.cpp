#include "render_fixture.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>

#include "math/camera.h"
#include "platform/headless.h"
#include "scene/scene_json.h"

namespace sl::test {

Rendered renderHeadless(const RenderRequest& request, bool allLit) {
    auto context =
        createHeadlessContext(Backend::Auto, request.tree, request.width, request.height);
    installGlDebugOutput();
    auto renderer = makeRenderer(request);
    renderer->allLit = allLit;
    renderer->render(context->framebuffer(), request.width, request.height);
    glFinish();
    Rendered r;
    r.image = context->read();
    r.stats = renderer->stats;
    r.explain = renderer->explain();
    r.glErrors = glErrorCount();
    return r;
}

int runShadowlab(const std::string& arguments, std::string* output) {
    std::string command = std::string(SHADOWLAB_EXE) + " " + arguments + " 2>&1";
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) return -1;
    std::string text;
    std::array<char, 4096> buffer;
    while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe))
        text.append(buffer.data(), n);
    int status = ::pclose(pipe);
    if (output) *output = text;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool pixelOf(const RenderRequest& request, const glm::vec3& world, int& i, int& j) {
    Camera c = loadScene(request.scene).camera;
    if (request.eye) c.eye = *request.eye;
    if (request.at) c.at = *request.at;
    if (request.fovy) c.fovyDegrees = *request.fovy;
    glm::vec2 px;
    if (!projectToPixel(c, request.width, request.height, world, px)) return false;
    i = static_cast<int>(px.x);
    j = static_cast<int>(px.y);
    return i >= 0 && j >= 0 && i < request.width && j < request.height;
}

RenderRequest smallRequest(const std::string& stage, GlslTree tree, Settings sets) {
    RenderRequest r;
    r.stage = stage;
    r.tree = tree;
    r.width = 320;
    r.height = 240;
    r.sets = std::move(sets);
    return r;
}

float lumaAt(const Image& image, const RenderRequest& request, glm::vec3 world) {
    int i = 0, j = 0;
    EXPECT_TRUE(pixelOf(request, world, i, j)) << "point off screen";
    return image.luma(i, j);
}

double darkenedNearLightShare(const Image& stage, const Image& phong,
                              const RenderRequest& request) {
    int dark = 0, total = 0;
    for (float x = 0.9f; x <= 1.4f; x += 0.02f)
        for (float z = -1.3f; z <= 1.3f; z += 0.05f) {
            if (z > -0.9f && z < 0.6f && x < 1.0f) continue;
            int i = 0, j = 0;
            if (!pixelOf(request, {x, 0.0f, z}, i, j)) continue;
            ++total;
            dark += stage.luma(i, j) < 0.85f * phong.luma(i, j);
        }
    return total ? double(dark) / total : 0.0;
}

std::string tempDir(const std::string& tag) {
    std::string pattern = "/tmp/shadowlab-" + tag + "-XXXXXX";
    std::vector<char> buf(pattern.begin(), pattern.end());
    buf.push_back('\0');
    const char* d = ::mkdtemp(buf.data());
    return d ? d : "/tmp";
}

}  // namespace sl::test
