// Acceptance by the standard (src/gl/glsl_standard.cpp) with the real glslang, no GL context:
// our shipped trees validate clean, and what the standard forbids (though NVIDIA's compiler takes
// it) is a ShaderError naming the student's file and line with glslang's own message.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "gl/glsl_standard.h"
#include "gl/shader_library.h"
#include "gl/source_rules.h"
#include "stages/request.h"

namespace fs = std::filesystem;
using namespace sl;

namespace {

// A student's overlay in a fresh temporary folder, removed at the end of the test.
class Overlay {
  public:
    Overlay() {
        char name[] = "/tmp/sl-glsl-XXXXXX";
        dir_ = ::mkdtemp(name);
    }
    ~Overlay() { fs::remove_all(dir_); }
    Overlay& file(const std::string& relative, const std::string& text) {
        fs::create_directories(fs::path(dir_ + "/" + relative).parent_path());
        std::ofstream(dir_ + "/" + relative) << text;
        return *this;
    }
    const std::string& dir() const { return dir_; }

  private:
    std::string dir_;
};

// The message of the ShaderError that checking stage/pass throws ("" when it passes).
std::string refusal(GlslTree tree, const Overlay& overlay, const std::string& stage,
                    const std::string& pass) {
    ShaderLibrary lib(tree, shaderTreeRoot(tree), overlay.dir());
    try {
        lib.standardProgram(stage, pass);
    } catch (const ShaderError& e) {
        return e.what();
    }
    return {};
}

const char* kLegacyVert =
    "#version 120\n"
    "attribute vec3 position;\n"
    "attribute vec3 normal;\n"
    "uniform mat4 model, view, projection;\n"
    "varying vec3 worldNormal;\n"
    "void main()\n"
    "{\n"
    "    worldNormal = normal;\n"
    "    gl_Position = projection * view * model * vec4(position, 1.0);\n"
    "}\n";

std::string legacyFrag(const std::string& body, const std::string& declarations = "") {
    return "#version 120\n"
           "varying vec3 worldNormal;\n"
           "uniform sampler2D shadowMap;\n" +
           declarations +
           "void main()\n"
           "{\n" +
           body + "}\n";
}

}  // namespace

TEST(GlslStandard, ShippedTreesValidateClean) {
    for (GlslTree tree : {GlslTree::Core, GlslTree::Legacy}) {
        ShaderLibrary lib(tree, shaderTreeRoot(tree), "");
        int programs = 0;
        for (const auto& folder : fs::directory_iterator(shaderTreeRoot(tree))) {
            for (const auto& file : fs::directory_iterator(folder.path())) {
                if (file.path().extension() != ".vert") continue;
                fs::path frag = file.path();
                frag.replace_extension(".frag");
                if (!fs::exists(frag)) continue;
                std::string stage = folder.path().filename(), pass = file.path().stem();
                EXPECT_NO_THROW(lib.standardProgram(stage, pass))
                    << treeName(tree) << " " << stage << "/" << pass;
                ++programs;
            }
        }
        EXPECT_GE(programs, 20) << treeName(tree);  // every stage's passes, hud, common
    }
}

TEST(GlslStandard, DeprecatedButLegalGlsl120IsAccepted) {
    Overlay o;
    o.file("phong/lit.vert", kLegacyVert)
        .file("phong/lit.frag",
              legacyFrag("    vec4 c = texture2D(shadowMap, worldNormal.xy);\n"
                         "    gl_FragColor = c * shadow2DProj(depthMap, vec4(worldNormal, 1.0));\n",
                         "uniform sampler2DShadow depthMap;\n"));
    EXPECT_EQ(refusal(GlslTree::Legacy, o, "phong", "lit"), "");
}

// NVIDIA's compiler takes each of these; the standard (and glslang) does not.
TEST(GlslStandard, Glsl120InQualifierIsRefused) {
    Overlay o;
    std::string vert = kLegacyVert;
    vert.replace(vert.find("attribute vec3 position"), 9, "in");
    o.file("phong/lit.vert", vert)
        .file("phong/lit.frag", legacyFrag("    gl_FragColor = vec4(worldNormal, 1.0);\n"));
    std::string e = refusal(GlslTree::Legacy, o, "phong", "lit");
    EXPECT_NE(e.find(o.dir() + "/phong/lit.vert:2: error: 'in for stage inputs' : not supported "
                               "for this version"),
              std::string::npos)
        << e;
}

TEST(GlslStandard, CgSaturateIsRefused) {
    Overlay o;
    o.file("phong/lit.vert", kLegacyVert)
        .file("phong/lit.frag",
              legacyFrag("    gl_FragColor = vec4(saturate(worldNormal), 1.0);\n"));
    std::string e = refusal(GlslTree::Legacy, o, "phong", "lit");
    EXPECT_NE(e.find(o.dir() + "/phong/lit.frag:6: error: 'saturate' : no matching overloaded "
                               "function found"),
              std::string::npos)
        << e;
}

TEST(GlslStandard, Glsl130TextureCallIn120IsRefused) {
    Overlay o;
    o.file("phong/lit.vert", kLegacyVert)
        .file("phong/lit.frag",
              legacyFrag("    gl_FragColor = texture(shadowMap, worldNormal.xy);\n"));
    std::string e = refusal(GlslTree::Legacy, o, "phong", "lit");
    EXPECT_NE(e.find(o.dir() + "/phong/lit.frag:6: error: 'texture' : no matching overloaded"),
              std::string::npos)
        << e;
}

TEST(GlslStandard, ModuloIn120IsRefused) {
    Overlay o;
    o.file("phong/lit.vert", kLegacyVert)
        .file("phong/lit.frag",
              legacyFrag("    int k = 7 % 2;\n    gl_FragColor = vec4(float(k));\n"));
    std::string e = refusal(GlslTree::Legacy, o, "phong", "lit");
    EXPECT_NE(e.find(o.dir() + "/phong/lit.frag:6: error: '%' : not supported for this version"),
              std::string::npos)
        << e;
}

TEST(GlslStandard, VaryingTypeMismatchIsRefusedAtTheFragmentDeclaration) {
    Overlay o;
    o.file("phong/lit.vert", kLegacyVert)
        .file("phong/lit.frag",
              "#version 120\nvarying vec4 worldNormal;\nvoid main()\n{\n"
              "    gl_FragColor = worldNormal;\n}\n");
    std::string e = refusal(GlslTree::Legacy, o, "phong", "lit");
    EXPECT_NE(e.find(o.dir() + "/phong/lit.frag:2: error: Linking vertex and fragment stages: "
                               "Types must match"),
              std::string::npos)
        << e;
}

TEST(GlslStandard, FragmentInputNoVertexOutputFeedsIsRefused) {
    Overlay o;
    o.file("phong/lit.vert", kLegacyVert)
        .file("phong/lit.frag",
              "#version 120\nvarying vec3 worldNormal;\nvarying vec2 uv;\n"
              "void main()\n{\n    gl_FragColor = vec4(worldNormal, uv.x);\n}\n");
    std::string e = refusal(GlslTree::Legacy, o, "phong", "lit");
    EXPECT_NE(e.find(o.dir() + "/phong/lit.frag:6: error: 'uv' : the fragment shader reads this "
                               "input, but the vertex shader"),
              std::string::npos)
        << e;
    // Declared and never read: no error (GLSL allows it).
    o.file("phong/lit.frag",
           "#version 120\nvarying vec3 worldNormal;\nvarying vec2 uv;\n"
           "void main()\n{\n    gl_FragColor = vec4(worldNormal, 1.0);\n}\n");
    EXPECT_EQ(refusal(GlslTree::Legacy, o, "phong", "lit"), "");
}

TEST(GlslStandard, ErrorInAnIncludedFileNamesThatFile) {
    Overlay o;
    o.file("common/phong.glsl",
           "uniform vec3 lightPosition;\nvec4 shade()\n{\n"
           "    return float4(lightPosition, 1.0);\n}\n")
        .file("phong/lit.vert", kLegacyVert)
        .file("phong/lit.frag",
              "#version 120\n#include \"common/phong.glsl\"\n"
              "varying vec3 worldNormal;\nvoid main() { gl_FragColor = shade(); }\n");
    std::string e = refusal(GlslTree::Legacy, o, "phong", "lit");
    EXPECT_NE(e.find(o.dir() + "/common/phong.glsl:4: error: 'float4' : no matching overloaded "
                               "function found"),
              std::string::npos)
        << e;
}

TEST(GlslStandard, VersionBeyondTheTreesContextIsRefused) {
    Overlay o;
    std::string vert = kLegacyVert;
    vert.replace(0, 12, "#version 330");
    o.file("phong/lit.vert", vert)
        .file("phong/lit.frag", legacyFrag("    gl_FragColor = vec4(1.0);\n"));
    std::string e = refusal(GlslTree::Legacy, o, "phong", "lit");
    EXPECT_NE(e.find(o.dir() + "/phong/lit.vert:1: error: #version 330: the legacy tree's "
                               "OpenGL 2.1 context guarantees #version 110 or 120 only"),
              std::string::npos)
        << e;
    Overlay core;
    core.file("phong/lit.frag",
              "// a comment first\n#version 450 core\nout vec4 c;\n"
              "void main() { c = vec4(1.0); }\n");
    e = refusal(GlslTree::Core, core, "phong", "lit");
    EXPECT_NE(e.find(core.dir() + "/phong/lit.frag:2: error: #version 450 core: an OpenGL 3.3 "
                                  "core context guarantees #version 140, 150 or 330 core only"),
              std::string::npos)
        << e;
}

// A UTF-8 byte order mark before #version is named as itself in both trees, not read as a file
// without #version.
TEST(GlslStandard, ByteOrderMarkIsNamed) {
    const std::string bom = "\xEF\xBB\xBF";
    Overlay legacy;
    legacy.file("phong/lit.vert", bom + kLegacyVert)
        .file("phong/lit.frag", legacyFrag("    gl_FragColor = vec4(1.0);\n"));
    Overlay core;
    core.file("phong/lit.frag",
              bom + "#version 330 core\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n");
    const std::pair<GlslTree, const Overlay*> cases[] = {{GlslTree::Legacy, &legacy},
                                                         {GlslTree::Core, &core}};
    for (const auto& [tree, o] : cases) {
        std::string e = refusal(tree, *o, "phong", "lit");
        const std::string file =
            o->dir() + (tree == GlslTree::Core ? "/phong/lit.frag" : "/phong/lit.vert");
        EXPECT_NE(e.find(file + ":1: error: starts with a UTF-8 byte order mark (EF BB BF) before "
                                "#version: save the file without it"),
                  std::string::npos)
            << e;
        EXPECT_EQ(e.find("no #version"), std::string::npos) << e;
    }
}

// A syntax error reads as the README shows it: `file:line: error: message`, without glslang's
// empty token field ("'' :  syntax error") and with the token the student typed, not the
// grammar's name for it ("unexpected SEMICOLON").
TEST(GlslStandard, SyntaxErrorReadsAsTheReadmeShowsIt) {
    Overlay o;
    o.file("phong/lit.vert", kLegacyVert)
        .file("phong/lit.frag", legacyFrag("    gl_FragColor = vec4(1.0) +;\n"));
    const std::string message = refusal(GlslTree::Legacy, o, "phong", "lit");
    const std::string line = o.dir() + "/phong/lit.frag:6: error: syntax error, unexpected ';'";
    EXPECT_NE(message.find(line), std::string::npos) << message;
    EXPECT_EQ(message.find("'' :"), std::string::npos) << message;
}
