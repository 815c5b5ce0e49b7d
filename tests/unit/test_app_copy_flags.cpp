// Copy flags (class/copy_flags.h) on the shipped margin/lit.frag: a renamed, recommented copy
// of the solution and two reformatted identical hand-ins are flagged; an independent solution
// (another structure) and the starter everyone was given are not.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "class/copy_flags.h"
#include "class/copy_pairs.h"
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

// Every shipped core file with a solution region: the due code of a course that assigns them all.
std::map<std::string, std::string> solutionFiles() {
    std::map<std::string, std::string> out;
    const std::string root = shaderTreeRoot(GlslTree::Core);
    for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
        if (!e.is_regular_file()) continue;
        const std::string rel = e.path().string().substr(root.size() + 1);
        const std::string text = shipped(rel);
        if (text.find("BEGIN SOLUTION") != std::string::npos) out[rel] = text;
    }
    return out;
}

// lab4's due files (assignments/lab4.json), the shipped example assignment.
std::map<std::string, std::string> lab4Files(const std::map<std::string, std::string>& all) {
    std::ifstream in(std::string(SHADOWLAB_SOURCE_DIR) + "/assignments/lab4.json");
    const nlohmann::json lab = nlohmann::json::parse(in);
    std::map<std::string, std::string> out;
    for (const auto& st : lab.at("stages"))
        if (st.value("due", true))
            for (const auto& f : st.at("files"))
                if (all.count(f.get<std::string>())) out[f] = all.at(f);
    return out;
}

// Two students who each wrote every solution region of `solutions` and have exactly one file
// the same token for token: the largest share of such a pair, each file's printed.
double largestOneFileShare(const std::map<std::string, std::string>& solutions,
                           const std::map<std::string, std::string>& starters) {
    double largest = 0;
    for (const auto& [same, unused] : solutions) {
        HandInFiles a{"a", solutions}, b{"b", solutions};
        for (auto& [f, text] : b.files)  // b's own version of every other file: one more line
            if (f != same) text += "\nfloat myOwnConstant = 1.0;\n";
        std::vector<CopyPair> pairs = copyPairs({a, b}, starters);
        EXPECT_EQ(pairs.size(), 1u);
        if (pairs.size() != 1) continue;
        EXPECT_EQ(pairs[0].files, std::vector<std::string>{same});
        std::printf("  one file in common: %-30s %3zu written tokens, share %.3f\n", same.c_str(),
                    pairs[0].commonTokens, pairs[0].share);
        EXPECT_TRUE(flagsOf(findCopies({a, b}, {}, starters), "a").empty() ||
                    pairs[0].share >= kCopyShareFlagged);
        largest = std::max(largest, pairs[0].share);
    }
    return largest;
}

// The threshold from measurement (docs/assignment.md "Copy flags"): a pair of honest students
// who wrote the same natural code in one file, whichever file, stays under kCopyShareFlagged,
// both in a course that assigns every stage and in lab4 (4 due files); a whole copy is 100 %.
TEST(CopyPairs, OneFileInCommonStaysUnderTheThresholdAWholeCopyIsOver) {
    const std::map<std::string, std::string> all = solutionFiles();
    ASSERT_GE(all.size(), 4u);
    std::map<std::string, std::string> starters;
    for (const auto& [f, text] : all) starters[f] = stripSolutions(text, f);
    const std::map<std::string, std::string> lab4 = lab4Files(all);
    ASSERT_EQ(lab4.size(), 4u);
    for (const auto* course : {&all, &lab4}) {
        std::printf("%zu due files:\n", course->size());
        const double largest = largestOneFileShare(*course, starters);
        std::printf("  largest share of one file in common: %.3f (threshold %.2f)\n", largest,
                    kCopyShareFlagged);
        EXPECT_LT(largest, kCopyShareFlagged);
        HandInFiles a{"a", *course}, copy{"copy", *course};
        std::vector<CopyPair> whole = copyPairs({a, copy}, starters);
        ASSERT_EQ(whole.size(), 1u);
        EXPECT_DOUBLE_EQ(whole[0].share, 1.0);
        EXPECT_EQ(whole[0].files.size(), course->size());
        EXPECT_EQ(flagsOf(findCopies({a, copy}, {}, starters), "a").size(), course->size());
    }
}

// A classmate whose hand-in's name is not UTF-8 is named in a flag as every output names them,
// escaped byte by byte ("\xFE\xFFcd"), never as replacement characters that two names share.
TEST(CopyFlags, AClassmateNamedInAnyBytesIsNamedEscaped) {
    const std::string f = "f.frag", starter = "void main() { }";
    const std::string copy = "void main() { float a = 1.0; gl_FragColor = vec4(a * 2.0); }";
    const std::string one =
                          "\xFE\xFF"
                          "cd",
                      two =
                          "\xFF\xFE"
                          "ab";
    const std::vector<CopyFlag> flags =
        findCopies({{one, {{f, copy}}}, {two, {{f, copy}}}}, {}, {{f, starter}});
    EXPECT_EQ(flagsOf(flags, two), std::vector<std::string>{"\\xFE\\xFFcd"});
    EXPECT_EQ(flagsOf(flags, one), std::vector<std::string>{"\\xFF\\xFEab"});
}

// Pairs are ranked by their share, largest first; a starter-only file is in no pair.
TEST(CopyPairs, RankedByShareStarterNeverCounted) {
    const std::string f1 = "f1.frag", f2 = "f2.frag";
    const std::string starter = "void main() { }";
    const std::string big =
        "void main() { float a = 1.0; float b = a * 2.0; gl_FragColor = vec4(b); }";
    const std::string small = "void main() { gl_FragColor = vec4(1.0); }";
    const std::string other = "void main() { float q = 3.0; gl_FragColor = vec4(q, q, q, 1.0); }";
    std::vector<HandInFiles> handIns = {{"copier", {{f1, big}, {f2, small}}},
                                        {"source", {{f1, big}, {f2, small}}},
                                        {"honest", {{f1, other}, {f2, small}}},
                                        {"given", {{f1, starter}, {f2, starter}}}};
    std::vector<CopyPair> pairs = copyPairs(handIns, {{f1, starter}, {f2, starter}});
    ASSERT_EQ(pairs.size(), 3u);  // copier-source, and each with honest over f2
    EXPECT_EQ(pairs[0].a + "-" + pairs[0].b, "copier-source");
    EXPECT_DOUBLE_EQ(pairs[0].share, 1.0);
    EXPECT_EQ(pairs[0].files, (std::vector<std::string>{f1, f2}));
    for (std::size_t k = 1; k < pairs.size(); ++k) {
        EXPECT_LT(pairs[k].share, pairs[0].share);
        EXPECT_EQ(pairs[k].files, std::vector<std::string>{f2});
        EXPECT_TRUE(pairs[k].a == "honest" || pairs[k].b == "honest");
    }
    EXPECT_EQ(writtenTokens(normalizedTokens(small), normalizedTokens(starter)), 7u);
}

}  // namespace
}  // namespace sl
