// The browser's loop budget as text (src/gl/loop_guard.cpp), no GL context: SPIRV-Cross's ESSL
// (the text below is `spirv-cross --es --version 300` of a shader with for, while, do-while and
// for (;;) loops) gets one budget step at the top of every loop body, main answers the probe,
// and a shader without loops is left as it was. That the guarded page draws our looping shaders
// as native does, and stops one that never ends, is tested in the browser (tests/web).
#include <gtest/gtest.h>

#include <string>

#include "gl/loop_guard.h"

using namespace sl;

namespace {

const std::string kLooping = R"(#version 300 es
precision mediump float;
precision highp int;

uniform highp sampler2D m;
uniform int n;

in highp vec2 uv;
layout(location = 0) out highp vec4 c;

highp float f(int k)
{
    highp float s = 0.0;
    int i = 0;
    while (i < k)
    {
        s += float(i);
        i++;
    }
    return s;
}

void main()
{
    highp float lit = 0.0;
    for (int x = -1; x <= 1; x++)
    {
        for (int y = -1; y <= 1; y--)
        {
            lit += texture(m, uv + vec2(float(x), float(y))).x;
        }
    }
    int j = 0;
    do
    {
        j++;
    } while (j < n);
    for (;;)
    {
        if (lit > 1.0)
        {
            break;
        }
        lit += 0.100000001490116119384765625;
        continue;
    }
    c = vec4(lit + f(n));
}
)";

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

}  // namespace

TEST(LoopGuard, EveryLoopBodyOpensWithABudgetStep) {
    const std::string guarded = guardLoops(kLooping, true, "me/depth/lit.frag");
    EXPECT_EQ(count(guarded, "if (sl_loopSpent()) break;"), 5u);  // while, 2 for, do, for (;;)
    EXPECT_NE(guarded.find("        {\n            if (sl_loopSpent()) break;\n"),
              std::string::npos);  // the inner for's body, indented as the body is
    EXPECT_NE(guarded.find("    do\n    {\n        if (sl_loopSpent()) break;\n        j++;"),
              std::string::npos);
    EXPECT_NE(guarded.find("return sl_loops > " + std::to_string(kLoopBudget) + ";"),
              std::string::npos);
    EXPECT_NE(guarded.find(std::string(kLoopGuardLine) + "me/depth/lit.frag\n"), std::string::npos);
    // Declared after the header lines, before the first function that steps it.
    EXPECT_LT(guarded.find("precision highp int;"), guarded.find("highp int sl_loops = 0;"));
    EXPECT_LT(guarded.find("bool sl_loopSpent()"), guarded.find("highp float f(int k)"));
}

TEST(LoopGuard, FragmentMainAnswersTheProbe) {
    const std::string guarded = guardLoops(kLooping, true, "me/depth/lit.frag");
    EXPECT_EQ(count(guarded, "void main()"), 1u);
    EXPECT_NE(guarded.find("void sl_studentMain()\n{\n    highp float lit"), std::string::npos);
    EXPECT_NE(guarded.find(std::string("uniform bool ") + kLoopProbe + ";"), std::string::npos);
    const std::string probe =
        "void main()\n{\n    sl_studentMain();\n    if (sl_loopProbe)\n"
        "    {\n        if (sl_loops <= " +
        std::to_string(kLoopBudget) + ") discard;\n        c = vec4(1.0);\n    }\n}\n";
    EXPECT_NE(guarded.find(probe), std::string::npos) << guarded;
}

TEST(LoopGuard, WithoutAnOutputTheProbeDeclaresOne) {
    std::string depthOnly = kLooping;
    depthOnly.replace(depthOnly.find("layout(location = 0) out highp vec4 c;"), 39, "");
    depthOnly.replace(depthOnly.find("c = vec4(lit + f(n));"), 21, "gl_FragDepth = lit;");
    const std::string guarded = guardLoops(depthOnly, true, "f");
    EXPECT_NE(guarded.find("layout(location = 0) out highp vec4 sl_loopMarker;"),
              std::string::npos);
    EXPECT_NE(guarded.find("sl_loopMarker = vec4(1.0);"), std::string::npos);
}

TEST(LoopGuard, AnIntegerOutputGetsTheBudgetButNoProbe) {
    std::string integer = kLooping;
    integer.replace(integer.find("out highp vec4 c;"), 17, "out highp ivec4 c;");
    const std::string guarded = guardLoops(integer, true, "f");
    EXPECT_EQ(count(guarded, "if (sl_loopSpent()) break;"), 5u);
    EXPECT_EQ(guarded.find(kLoopProbe), std::string::npos);
}

TEST(LoopGuard, VertexShadersGetTheBudgetOnly) {
    const std::string guarded = guardLoops(kLooping, false, "v");
    EXPECT_EQ(count(guarded, "if (sl_loopSpent()) break;"), 5u);
    EXPECT_EQ(guarded.find("sl_studentMain"), std::string::npos);
    EXPECT_EQ(guarded.find(kLoopProbe), std::string::npos);
}

TEST(LoopGuard, AShaderWithoutLoopsIsLeftAsItWas) {
    const std::string plain =
        "#version 300 es\nprecision mediump float;\n\n"
        "layout(location = 0) out highp vec4 c;\n\nvoid main()\n{\n"
        "    c = vec4(1.0);\n}\n";
    EXPECT_EQ(guardLoops(plain, true, "f"), plain);
    EXPECT_EQ(guardLoops(plain, false, "f"), plain);
}

TEST(LoopGuard, ALoopWhoseBodyDoesNotOpenOnTheNextLineIsRefused) {
    const std::string odd = "#version 300 es\nvoid main()\n{\n    for (;;) { }\n}\n";
    EXPECT_THROW(guardLoops(odd, true, "f"), std::runtime_error);
}

TEST(LoopGuard, TheMessageNamesTheFileAndTheBudget) {
    const std::string said = LoopBudgetSpent("me/depth/lit.frag").what();
    EXPECT_EQ(said.rfind("me/depth/lit.frag: error: a loop ran past " +
                             std::to_string(kLoopBudget) + " iterations",
                         0),
              0u);
}
