// Source rules (src/gl/source_rules.cpp) on glslang's real syntax trees, no GL context: our
// shipped shaders produce no finding, a constant margin and shaders that recognise the graded
// camera or light each produce theirs, in the student's file and line.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "gl/shader_library.h"
#include "gl/source_rules.h"
#include "render/stage_interface.h"
#include "stages/registry.h"
#include "stages/request.h"

namespace fs = std::filesystem;
using namespace sl;

namespace {

const std::vector<SourceRule>& rulesOf(const std::string& stage) {
    const StageDefinition* info = findStage(stage);
    EXPECT_NE(info, nullptr) << stage;
    static const std::vector<SourceRule> none;
    return info ? info->sourceRules : none;
}

// The findings of `stage`'s rules on its pass `pass`, built from `overlay` over our tree.
std::vector<std::string> findings(GlslTree tree, const std::string& overlay,
                                  const std::string& stage, const std::string& pass) {
    ShaderLibrary lib(tree, shaderTreeRoot(tree), overlay);
    return sourceFindings(rulesOf(stage), lib.standardProgram(stage, pass));
}

std::string joined(const std::vector<std::string>& lines) {
    std::string out;
    for (const auto& l : lines) out += l + "\n";
    return out;
}

// A copy of our `stage` folder (and common/) as a student's overlay, with one file replaced.
class Overlay {
  public:
    Overlay(GlslTree tree, const std::string& stage) {
        char name[] = "/tmp/sl-rules-XXXXXX";
        dir_ = ::mkdtemp(name);
        for (const std::string& folder : {stage, std::string("common")})
            fs::copy(shaderTreeRoot(tree) + "/" + folder, dir_ + "/" + folder,
                     fs::copy_options::recursive);
    }
    ~Overlay() { fs::remove_all(dir_); }
    // Replaces the first occurrence of `from` in `relative` by `to`.
    void edit(const std::string& relative, const std::string& from, const std::string& to) {
        std::string path = dir_ + "/" + relative;
        std::ifstream in(path);
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::size_t at = text.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        text.replace(at, from.size(), to);
        std::ofstream(path, std::ios::trunc) << text;
    }
    const std::string& dir() const { return dir_; }

  private:
    std::string dir_;
};

}  // namespace

TEST(SourceRules, ShippedShadersHaveNoFinding) {
    int programs = 0;
    for (const StageDefinition& info : stageRegistry()) {
        if (info.sourceRules.empty()) continue;
        for (GlslTree tree : {GlslTree::Core, GlslTree::Legacy}) {
            // Our own tree as the overlay: every file counts as the student's.
            ShaderLibrary lib(tree, shaderTreeRoot(tree), shaderTreeRoot(tree));
            for (const auto& file : fs::directory_iterator(shaderTreeRoot(tree) + "/" + info.id)) {
                if (file.path().extension() != ".vert") continue;
                ProgramSource program = lib.standardProgram(info.id, file.path().stem());
                std::vector<std::string> found = sourceFindings(info.sourceRules, program);
                EXPECT_TRUE(found.empty()) << info.id << " " << treeName(tree) << ":\n"
                                           << joined(found);
                ++programs;
            }
        }
    }
    EXPECT_GE(programs, 20);
}

TEST(SourceRules, ConstantMarginIsFound) {
    for (GlslTree tree : {GlslTree::Core, GlslTree::Legacy}) {
        Overlay o(tree, "margin");
        // The slope branch never written: the constant margin for both kinds.
        o.edit("margin/lit.frag", "if (marginKind == 0) return margin;", "return margin;");
        std::vector<std::string> found = findings(tree, o.dir(), "margin", "lit");
        ASSERT_EQ(found.size(), 1u) << joined(found);
        EXPECT_NE(found[0].find(o.dir() + "/margin/lit.frag:"), std::string::npos) << found[0];
        EXPECT_NE(found[0].find("the shadow comparison does not depend on the normal or the "
                                "light direction"),
                  std::string::npos)
            << found[0];
    }
}

TEST(SourceRules, SlopeMarginUnderOtherNamesIsNoFinding) {
    Overlay o(GlslTree::Core, "margin");
    // The normal carried under another name, the margin computed inline in main.
    o.edit("margin/lit.vert", "out vec3 worldNormal;", "out vec3 n;");
    o.edit("margin/lit.vert", "worldNormal = normalMatrix * normal;", "n = normalMatrix * normal;");
    o.edit("margin/lit.frag", "in vec3 worldNormal;", "in vec3 n;");
    o.edit("margin/lit.frag", "normalize(worldNormal)", "normalize(n)");
    o.edit("margin/lit.frag", "shade(worldPosition, worldNormal,", "shade(worldPosition, n,");
    o.edit("margin/lit.frag", "+ marginFor(N, L)", "+ 0.004 * (1.0 - dot(N, L))");
    std::vector<std::string> found = findings(GlslTree::Core, o.dir(), "margin", "lit");
    EXPECT_TRUE(found.empty()) << joined(found);
    // Only the normal: the light direction is named as missing.
    o.edit("margin/lit.frag", "+ 0.004 * (1.0 - dot(N, L))", "+ 0.004 * (1.0 - N.y)");
    found = findings(GlslTree::Core, o.dir(), "margin", "lit");
    ASSERT_EQ(found.size(), 1u) << joined(found);
    EXPECT_NE(found[0].find("does not depend on the light direction;"), std::string::npos)
        << found[0];
}

// A normal built from screen-space derivatives of the position is a normal: a slope margin made
// from it is no finding, in both trees. A derivative of the position's height (a slope on screen)
// is no normal-free margin either: one from a derivative alone misses only the light direction.
TEST(SourceRules, DerivativeNormalIsANormal) {
    for (GlslTree tree : {GlslTree::Core, GlslTree::Legacy}) {
        Overlay o(tree, "margin");
        o.edit("margin/lit.frag", "+ marginFor(N, L)",
               "+ marginFor(normalize(cross(dFdx(worldPosition), dFdy(worldPosition))), L)");
        std::vector<std::string> found = findings(tree, o.dir(), "margin", "lit");
        EXPECT_TRUE(found.empty()) << treeName(tree) << ":\n" << joined(found);
        o.edit("margin/lit.frag",
               "+ marginFor(normalize(cross(dFdx(worldPosition), dFdy(worldPosition))), L)",
               "+ 0.004 * fwidth(worldPosition.y)");
        found = findings(tree, o.dir(), "margin", "lit");
        ASSERT_EQ(found.size(), 1u) << joined(found);
        EXPECT_NE(found[0].find("does not depend on the light direction;"), std::string::npos)
            << found[0];
    }
}

TEST(SourceRules, CameraRecognisingShaderIsFound) {
    // From the student corpus: recognises the graded cameras by eyePosition.
    std::string overlay =
        std::string(SHADOWLAB_SOURCE_DIR) + "/tests/students/depth_game_known_eyes";
    std::vector<std::string> found = findings(GlslTree::Core, overlay, "depth", "lit");
    ASSERT_EQ(found.size(), 5u) << joined(found);  // the five cameras, each its own line
    EXPECT_NE(found[0].find("possible gaming: " + overlay +
                            "/depth/lit.frag:56 compares the "
                            "camera position (eyePosition) with a constant"),
              std::string::npos)
        << found[0];
}

TEST(SourceRules, LightRecognisingShaderIsFound) {
    std::string overlay =
        std::string(SHADOWLAB_SOURCE_DIR) + "/tests/students/margin_game_known_lights";
    std::vector<std::string> found = findings(GlslTree::Core, overlay, "margin", "lit");
    ASSERT_GE(found.size(), 3u) << joined(found);
    EXPECT_NE(found[0].find("possible gaming: " + overlay +
                            "/margin/lit.frag:58 compares the "
                            "light position (lightPosition) with a constant"),
              std::string::npos)
        << found[0];
}

TEST(SourceRules, ScreenPlaceNotDepthAndThroughAVarying) {
    Overlay o(GlslTree::Legacy, "depth");
    // The pixel's place on screen against a constant is a finding; its depth (.z) is not.
    o.edit("depth/lit.frag", "float visibility = 1.0;",
           "float visibility = gl_FragCoord.z < 0.999 ? 1.0 : 0.5;\n"
           "    if (gl_FragCoord.x > 320.0) visibility = 0.0;");
    std::vector<std::string> found = findings(GlslTree::Legacy, o.dir(), "depth", "lit");
    ASSERT_EQ(found.size(), 1u) << joined(found);
    EXPECT_NE(found[0].find("compares the pixel's place on screen (gl_FragCoord)"),
              std::string::npos)
        << found[0];

    // The camera handed to the fragment stage through a varying of the student's own.
    Overlay v(GlslTree::Core, "depth");
    v.edit("depth/lit.vert", "out vec3 worldPosition;",
           "out vec3 worldPosition;\nout vec3 eyeSeen;\nuniform vec3 eyePosition;");
    v.edit("depth/lit.vert", "worldPosition = world.xyz;",
           "worldPosition = world.xyz;\n    eyeSeen = eyePosition;");
    v.edit("depth/lit.frag", "in vec3 worldPosition;", "in vec3 worldPosition;\nin vec3 eyeSeen;");
    v.edit("depth/lit.frag", "float visibility = 1.0;",
           "float visibility = eyeSeen.y > 2.5 ? 1.0 : 0.0;");
    found = findings(GlslTree::Core, v.dir(), "depth", "lit");
    ASSERT_EQ(found.size(), 1u) << joined(found);
    EXPECT_NE(found[0].find("compares the camera position (eyePosition)"), std::string::npos)
        << found[0];
}

TEST(SourceRules, OnlyTheStudentsFilesAreRead) {
    std::string overlay =
        std::string(SHADOWLAB_SOURCE_DIR) + "/tests/students/depth_game_known_eyes";
    ShaderLibrary lib(GlslTree::Core, shaderTreeRoot(GlslTree::Core), overlay);
    ProgramSource program = lib.standardProgram("depth", "lit");
    program.students = [](const std::string&) { return false; };
    EXPECT_TRUE(sourceFindings(rulesOf("depth"), program).empty());
}
