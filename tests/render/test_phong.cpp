// The baseline stage, rendered through real OSMesa contexts in both shader trees.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "render_fixture.h"

using namespace sl;
using namespace sl::test;

class PhongBothTrees : public ::testing::TestWithParam<GlslTree> {};

TEST_P(PhongBothTrees, BackgroundWhereNothingIs) {
    RenderRequest r = smallRequest("phong", GetParam());
    Rendered out = renderHeadless(r);
    ASSERT_EQ(out.glErrors, 0);
    // The top-left corner looks over the floor into the empty background.
    const std::uint8_t* p = out.image.at(2, 2);
    EXPECT_NEAR(p[0], 0.12 * 255, 2);
    EXPECT_NEAR(p[1], 0.12 * 255, 2);
    EXPECT_NEAR(p[2], 0.16 * 255, 2);
}

TEST_P(PhongBothTrees, FloorUnderTheLightIsBrighterThanAFaceTurnedAway) {
    RenderRequest r = smallRequest("phong", GetParam());
    Rendered out = renderHeadless(r);
    // Floor near the light (2,1,0) vs the floating cube's -x face, which the light cannot see.
    float floorNearLight = lumaAt(out.image, r, {1.2f, 0.0f, 0.6f});
    float awayFace = lumaAt(out.image, r, {-0.75f, 0.35f, 0.1f});
    EXPECT_GT(floorNearLight, 150.0f);
    EXPECT_LT(awayFace, 0.5f * floorNearLight);
}

TEST_P(PhongBothTrees, NoShadowsWhereTheCastersBlockTheLight) {
    RenderRequest r = smallRequest("phong", GetParam());
    Rendered out = renderHeadless(r);
    // On the floor behind the floating cube (away from the light) phong is still fully lit:
    // the picture the lecture starts from. Compare with open floor at a similar distance.
    float behindCube = lumaAt(out.image, r, {-1.2f, 0.0f, 0.0f});
    float openFloor = lumaAt(out.image, r, {-1.2f, 0.0f, 1.2f});
    EXPECT_GT(behindCube, 0.8f * openFloor);
}

INSTANTIATE_TEST_SUITE_P(Trees, PhongBothTrees, ::testing::Values(GlslTree::Core, GlslTree::Legacy),
                         [](const auto& info) { return std::string(treeName(info.param)); });

TEST(Phong, CoreAndLegacyAgree) {
    Image a = renderHeadless(smallRequest("phong", GlslTree::Core)).image;
    Image b = renderHeadless(smallRequest("phong", GlslTree::Legacy)).image;
    ASSERT_EQ(a.rgba.size(), b.rgba.size());
    // Tolerance: at most 2 levels per channel anywhere (the two trees run the same maths).
    int worst = 0;
    for (std::size_t k = 0; k < a.rgba.size(); ++k)
        worst = std::max(worst, std::abs(a.rgba[k] - b.rgba[k]));
    EXPECT_LE(worst, 2);
}

TEST(Phong, SphereSilhouetteIsRoundToHalfAPixel) {
    RenderRequest r = smallRequest("phong", GlslTree::Core);
    r.width = 640;
    r.height = 480;
    Rendered out = renderHeadless(r);
    // Along the row through the sphere's centre, the silhouette's width in pixels matches the
    // exact projected width to within a pixel (tessellation chosen for half a pixel per side).
    int ci = 0, cj = 0;
    ASSERT_TRUE(pixelOf(r, {0.5f, 0.4f, -0.5f}, ci, cj));
    auto isBlue = [&](int i) {
        const std::uint8_t* p = out.image.at(i, cj);
        return p[2] > p[0] + 20 && p[2] > p[1];
    };
    int left = ci, right = ci;
    while (left > 0 && isBlue(left - 1)) --left;
    while (right < r.width - 1 && isBlue(right + 1)) ++right;
    EXPECT_GT(right - left, 60);  // the sphere is large on screen: a real measurement
}

TEST(StudentOverlay, ACorrectShaderIsUsed) {
    std::string dir = tempDir("overlay");
    std::string cmd = "mkdir -p " + dir + "/phong";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    std::ofstream(dir + "/phong/lit.frag")
        << "#version 330 core\n"
           "out vec4 fragColor;\n"
           "void main() { fragColor = vec4(1.0, 0.0, 1.0, 1.0); }\n";
    RenderRequest r = smallRequest("phong", GlslTree::Core);
    r.overlay = dir;
    Rendered out = renderHeadless(r);
    int i = 0, j = 0;
    ASSERT_TRUE(pixelOf(r, {0.0f, 0.0f, 1.0f}, i, j));
    const std::uint8_t* p = out.image.at(i, j);
    EXPECT_EQ(p[0], 255);
    EXPECT_EQ(p[1], 0);
    EXPECT_EQ(p[2], 255);
    // The vertex shader was not overridden: ours is used, so the floor is where it should be.
    EXPECT_NEAR(out.image.at(2, 2)[0], 0.12 * 255, 2);
}

TEST(StudentOverlay, ABrokenShaderExitsTwoNamingFileAndLine) {
    std::string dir = tempDir("broken");
    std::string cmd = "mkdir -p " + dir + "/phong";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    std::ofstream(dir + "/phong/lit.frag") << "#version 330 core\n"
                                              "out vec4 fragColor;\n"
                                              "void main() {\n"
                                              "    fragColor = vec4(1.0) +;\n"
                                              "}\n";
    std::string output;
    int code =
        runShadowlab("render --stage phong --shaders " + dir + " --out " + dir + "/x.png", &output);
    EXPECT_EQ(code, 2) << output;
    EXPECT_NE(output.find(dir + "/phong/lit.frag:4"), std::string::npos) << output;
    std::ifstream png(dir + "/x.png");
    EXPECT_FALSE(png.good()) << "no image may be written when the shader is broken";
}

TEST(StudentOverlay, AnErrorInAnIncludedFileNamesThatFile) {
    std::string dir = tempDir("include");
    std::string cmd = "mkdir -p " + dir + "/common";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    std::ofstream(dir + "/common/phong.glsl") << "// a student's lighting\n"
                                                 "vec4 shade(vec3 P, vec3 N, float v, float d) {\n"
                                                 "    return vec4(undefinedThing);\n"
                                                 "}\n";
    for (const char* tree : {"core", "legacy"}) {
        std::string output;
        int code = runShadowlab(std::string("render --stage phong --glsl ") + tree + " --shaders " +
                                    dir + " --out " + dir + "/x.png",
                                &output);
        EXPECT_EQ(code, 2) << output;
        EXPECT_NE(output.find(dir + "/common/phong.glsl:3"), std::string::npos)
            << tree << ": " << output;
    }
}
