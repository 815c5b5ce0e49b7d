// Copy flags (course/copy_flags.h) on the shipped margin/lit.frag: a renamed, recommented copy
// of the solution and two reformatted identical hand-ins are flagged; an independent solution
// (another structure) and the starter everyone was given are not.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "course/copy_flags.h"
#include "course/release.h"
#include "stages/request.h"

namespace sl {
namespace {

std::string shipped(const std::string& rel) {
    std::ifstream in(shaderTreeRoot(GlslTree::Core) + "/" + rel);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// `text` with its comments replaced, names renamed and the layout changed: what a student who
// copied it and tried to hide it would hand in.
std::string disguised(std::string text) {
    text = std::regex_replace(text, std::regex("//[^\n]*"), "// my own work");
    for (const auto& [from, to] :
         std::vector<std::pair<std::string, std::string>>{{"cosTheta", "c"},
                                                          {"tanTheta", "t"},
                                                          {"visibility", "vis"},
                                                          {"marginFor", "mf"},
                                                          {"shadowCoord", "sc"}})
        text = std::regex_replace(text, std::regex("\\b" + from + "\\b"), to);
    text = std::regex_replace(text, std::regex("    "), "\t");
    text = std::regex_replace(text, std::regex(" \\* "), "*");
    return "/* lab 4, margin */\n" + text;
}

std::vector<std::string> flagsOf(const std::vector<CopyFlag>& flags, const std::string& who) {
    std::vector<std::string> out;
    for (const CopyFlag& f : flags)
        if (f.student == who) out.push_back(f.other.empty() ? "solution" : f.other);
    return out;
}

TEST(CopyFlags, NamesAndLayoutAreSetAside) {
    EXPECT_EQ(normalizedTokens("float a = b*2.0; // x\n/* y */ a += b;"),
              normalizedTokens("float  zz=q * 2.0;\n\tzz+=q;"));
    EXPECT_NE(normalizedTokens("float a = max(b, 1e-3);"),
              normalizedTokens("float a = min(b, 1e-3);"));
    EXPECT_EQ(normalizedTokens("x = 1e-3;").size(), 4u);  // x = 1e-3 ;
}

TEST(CopyFlags, CopiesFlaggedIndependentWorkAndTheStarterNot) {
    const std::string file = "margin/lit.frag";
    const std::string solution = shipped(file);
    ASSERT_NE(solution.find("BEGIN SOLUTION"), std::string::npos);
    const std::string starter = stripSolutions(solution, file);
    // An independent solution: the same result written another way.
    std::string own = solution;
    own = std::regex_replace(
        own,
        std::regex("shadowCoord\\.z <= texture\\(shadowMap, shadowCoord\\.xy\\)\\.r \\+ "
                   "marginFor\\(N, L\\) \\? 1\\.0 : 0\\.0"),
        "step(shadowCoord.z - marginFor(N, L), texture(shadowMap, shadowCoord.xy).r)");
    ASSERT_NE(own, solution) << "the shipped solution changed: update this test's edit";
    std::string friendA = std::regex_replace(starter, std::regex("return 0\\.0;"),
                                             "return 0.004 * (1.0 - dot(N, L));");
    ASSERT_NE(friendA, starter);
    std::string friendB = disguised(friendA);
    std::vector<HandInFiles> handIns = {{"copier", {{file, disguised(solution)}}},
                                        {"ann", {{file, friendA}}},
                                        {"bo", {{file, friendB}}},
                                        {"cy", {{file, own}}},
                                        {"dee", {{file, starter}}},
                                        {"eve", {{file, starter}}}};
    std::vector<CopyFlag> flags = findCopies(handIns, {{file, solution}}, {{file, starter}});
    EXPECT_EQ(flagsOf(flags, "copier"), std::vector<std::string>{"solution"});
    EXPECT_EQ(flagsOf(flags, "ann"), std::vector<std::string>{"bo"});
    EXPECT_EQ(flagsOf(flags, "bo"), std::vector<std::string>{"ann"});
    EXPECT_TRUE(flagsOf(flags, "cy").empty());
    EXPECT_TRUE(flagsOf(flags, "dee").empty());  // the starter, identical for everyone
    EXPECT_TRUE(flagsOf(flags, "eve").empty());
    for (const CopyFlag& f : flags) EXPECT_EQ(f.file, file);
}

}  // namespace
}  // namespace sl
