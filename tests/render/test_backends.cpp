// The two headless backends give the same images: every stage in every tree it allows, rendered
// through OSMesa and through EGL's surfaceless platform in the same process.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include "platform/headless.h"
#include "render_fixture.h"
#include "stages/registry.h"

using namespace sl;

namespace {

Image renderWith(Backend backend, const RenderRequest& request) {
    auto context = createHeadlessContext(backend, request.tree, request.width, request.height);
    auto renderer = makeRenderer(request);
    renderer->render(context->framebuffer(), request.width, request.height);
    glFinish();
    return context->read();
}

struct Case {
    std::string stage;
    GlslTree tree;
};

std::vector<Case> everyStageAndTree() {
    std::vector<Case> cases;
    for (const auto& s : stageRegistry()) {
        if (!s.legacyOnly) cases.push_back({s.id, GlslTree::Core});
        cases.push_back({s.id, GlslTree::Legacy});
    }
    return cases;
}

}  // namespace

class Backends : public ::testing::TestWithParam<Case> {};

TEST_P(Backends, EglMatchesOSMesa) {
    if (!osmesaAvailable()) GTEST_SKIP() << "this build has no OSMesa to compare with";
    RenderRequest r;
    r.stage = GetParam().stage;
    r.tree = GetParam().tree;
    r.width = 320;
    r.height = 240;
    Image osmesa = renderWith(Backend::OSMesa, r);
    Image egl = renderWith(Backend::Egl, r);
    ASSERT_EQ(osmesa.rgba.size(), egl.rgba.size());
    // The tolerance of the other render tests: under 0.5 % of the pixels off by more than 8
    // levels. Both are llvmpipe, so we also report the largest difference seen.
    long off = 0;
    int largest = 0;
    for (std::size_t k = 0; k < osmesa.rgba.size(); k += 4) {
        int d = 0;
        for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(osmesa.rgba[k + c] - egl.rgba[k + c]));
        largest = std::max(largest, d);
        if (d > 8) ++off;
    }
    double pct = 100.0 * off / (r.width * r.height);
    EXPECT_LT(pct, 0.5) << "largest channel difference " << largest;
    RecordProperty("largest_difference", largest);
    // And the picture is not empty: a tenth of it at least differs from the corner pixel (the
    // background).
    long drawn = 0;
    for (std::size_t k = 0; k < egl.rgba.size(); k += 4) {
        int d = 0;
        for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(egl.rgba[k + c] - egl.rgba[c]));
        drawn += d > 10;
    }
    EXPECT_GT(drawn, r.width * r.height / 10);
}

INSTANTIATE_TEST_SUITE_P(EveryStage, Backends, ::testing::ValuesIn(everyStageAndTree()),
                         [](const auto& info) {
                             return info.param.stage +
                                    (info.param.tree == GlslTree::Core ? "_core" : "_legacy");
                         });

TEST(BackendChoice, EnvironmentPinsTheAutomaticChoice) {
    setenv("SHADOWLAB_BACKEND", "egl", 1);
    auto egl = createHeadlessContext(Backend::Auto, GlslTree::Core, 8, 8);
    EXPECT_STREQ(egl->backendName(), "egl");
    egl.reset();
    if (osmesaAvailable()) {
        setenv("SHADOWLAB_BACKEND", "osmesa", 1);
        auto osmesa = createHeadlessContext(Backend::Auto, GlslTree::Core, 8, 8);
        EXPECT_STREQ(osmesa->backendName(), "osmesa");
    }
    unsetenv("SHADOWLAB_BACKEND");
}

TEST(BackendChoice, ManyEglContextsInOneProcess) {
    // The display is initialised once and kept; contexts come and go.
    for (int k = 0; k < 5; ++k) {
        auto c =
            createHeadlessContext(Backend::Egl, k % 2 ? GlslTree::Legacy : GlslTree::Core, 16, 16);
        glClearColor(1, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        Image img = c->read();
        EXPECT_EQ(img.rgba[0], 255);
        EXPECT_EQ(img.rgba[1], 0);
    }
}
