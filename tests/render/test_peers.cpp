// The tutorials' methods (stage `peers`) and hardware 3x3 PCF through real OSMesa contexts, in
// both shader trees: shadows where the reference geometry puts them, and each method's known
// failure measured where it has one.
#include <gtest/gtest.h>

#include "platform/headless.h"
#include "render_fixture.h"

using namespace sl;
using namespace sl::test;

namespace {

struct Method {
    std::string name, stage;
    Settings sets;
    bool acneNearLight;  // opengl-tutorial: its bias vanishes where N.L = 1
};

const Method kMethods[] = {
    {"learnopengl", "peers", {{"method", "learnopengl"}}, false},
    {"opengl_tutorial", "peers", {{"method", "opengl-tutorial"}}, true},
    {"normal_offset", "peers", {{"method", "normal-offset"}}, false},
    {"normal_offset_casters",
     "peers",
     {{"method", "normal-offset"}, {"casters", "casters-only"}},
     false},
    {"hardware_pcf3x3", "hardware", {{"filter", "pcf3x3"}}, false},
};

}  // namespace

class Peers : public ::testing::TestWithParam<std::tuple<Method, GlslTree>> {};

TEST_P(Peers, ShadowsWhereTheReferencePutsThem) {
    auto [m, tree] = GetParam();
    RenderRequest r = smallRequest(m.stage, tree, m.sets);
    Rendered out = renderHeadless(r);
    ASSERT_EQ(out.glErrors, 0);
    RenderRequest phongRequest = smallRequest("phong", tree);
    Image phong = renderHeadless(phongRequest).image;
    for (glm::vec3 p : kDeepShadow)
        EXPECT_LT(lumaAt(out.image, r, p), 0.6f * lumaAt(phong, r, p))
            << m.name << " should shadow the floor at " << p.x << "," << p.z;
    double acne = darkenedNearLightShare(out.image, phong, r);
    if (m.acneNearLight) {
        EXPECT_GT(acne, 0.05) << m.name << ": its bias is 0 where the light hits square on";
    } else {
        EXPECT_LT(acne, 0.02) << m.name;
        for (glm::vec3 p : kClearlyLit)
            EXPECT_GT(lumaAt(out.image, r, p), 0.9f * lumaAt(phong, r, p))
                << m.name << " should light the floor at " << p.x << "," << p.z;
    }
}

TEST_P(Peers, EveryDebugViewRendersWithoutGlErrors) {
    auto [m, tree] = GetParam();
    for (ViewMode v :
         {ViewMode::ShadowMap, ViewMode::Light, ViewMode::Visibility, ViewMode::LightDepth}) {
        RenderRequest r = smallRequest(m.stage, tree, m.sets);
        r.view = v;
        EXPECT_EQ(renderHeadless(r).glErrors, 0) << m.name << " " << viewName(v);
    }
}

INSTANTIATE_TEST_SUITE_P(All, Peers,
                         ::testing::Combine(::testing::ValuesIn(kMethods),
                                            ::testing::Values(GlslTree::Core, GlslTree::Legacy)),
                         [](const auto& info) {
                             return std::get<0>(info.param).name + "_" +
                                    treeName(std::get<1>(info.param));
                         });

TEST(PeersTrees, CoreAndLegacyAgree) {
    for (const Method& m : kMethods) {
        Image a = renderHeadless(smallRequest(m.stage, GlslTree::Core, m.sets)).image;
        Image b = renderHeadless(smallRequest(m.stage, GlslTree::Legacy, m.sets)).image;
        long off = 0;  // under 0.5 % of the pixels differ by more than 8 levels
        for (int j = 0; j < a.height; ++j)
            for (int i = 0; i < a.width; ++i)
                for (int k = 0; k < 3; ++k)
                    if (std::abs(a.at(i, j)[k] - b.at(i, j)[k]) > 8) {
                        ++off;
                        break;
                    }
        EXPECT_LT(off, a.width * a.height / 200) << m.name;
    }
}

// The tutorials draw their depth map every frame; normal offset on our machinery only when the
// light or the scene changed.
TEST(PeersMap, TheTutorialsRedrawEveryFrameNormalOffsetOnlyWhenStale) {
    for (const char* method : {"learnopengl", "opengl-tutorial", "normal-offset"}) {
        RenderRequest r = smallRequest("peers", GlslTree::Core, {{"method", method}});
        auto context = createHeadlessContext(Backend::Auto, r.tree, r.width, r.height);
        auto renderer = makeRenderer(r);
        for (int k = 0; k < 3; ++k) renderer->render(context->framebuffer(), r.width, r.height);
        EXPECT_EQ(renderer->stats.shadowMapRenders,
                  std::string(method) == "normal-offset" ? 1u : 3u)
            << method;
    }
}

// 3x3 PCF: nine compares give more distinct visibility levels on edges than one (nearest), and
// only the ten multiples of 1/9.
TEST(PeersPcf, NineComparesGiveGreysOnEdges) {
    RenderRequest r = smallRequest("hardware", GlslTree::Core, {{"filter", "pcf3x3"}});
    r.view = ViewMode::Visibility;
    Image v = renderHeadless(r).image;
    int greys = 0, offLevel = 0;
    for (int j = 0; j < v.height; ++j)
        for (int i = 0; i < v.width; ++i) {
            const std::uint8_t* p = v.at(i, j);
            if (p[0] != p[2] || p[0] <= 20 || p[0] >= 235) continue;  // grey, not background
            ++greys;
            double ninths = p[0] / 255.0 * 9.0;
            offLevel += std::abs(ninths - std::round(ninths)) > 0.1;
        }
    EXPECT_GT(greys, 200);
    EXPECT_LT(offLevel, greys / 50) << "visibility should be k/9";
}
