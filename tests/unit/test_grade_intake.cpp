// Intake (src/grade/intake.h): what a submission folder replaces, its notes and its snapshot.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "grade/intake.h"

namespace fs = std::filesystem;
using namespace sl;

namespace {

const std::set<std::string> kShipped = {
    "margin/lit.frag", "margin/lit.vert", "margin/shadow.frag", "margin/shadow.vert",
    "depth/lit.frag",  "depth/lit.vert",  "rgb/shadow.frag",    "common/phong.glsl"};

struct Folder {
    PrivateDir dir{"sl-intake-test"};
    std::string put(const std::string& rel, const std::string& text = "void main() {}\n") {
        fs::path p = fs::path(dir.path()) / rel;
        fs::create_directories(p.parent_path());
        std::ofstream(p) << text;
        return p.string();
    }
    std::string path() const { return dir.path(); }
};

Submission take(const Folder& f, const std::vector<std::string>& stages = {}) {
    static int n = 0;
    static std::vector<std::unique_ptr<PrivateDir>> keep;  // snapshots live to the test's end
    keep.push_back(std::make_unique<PrivateDir>("sl-intake-snap" + std::to_string(++n)));
    return takeSubmission(f.path(), keep.back()->path(), kShipped, stages);
}

bool hasNote(const Submission& s, const std::string& part) {
    for (const auto& n : s.notes)
        if (n.find(part) != std::string::npos) return true;
    return false;
}

std::string intakeError(const Folder& f) {
    try {
        take(f);
    } catch (const IntakeError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(Intake, PlainOverlayIsCopiedAndReplacesItsStage) {
    Folder f;
    f.put("margin/lit.frag", "// mine\n");
    f.put("margin/helpers.glsl");
    Submission s = take(f);
    EXPECT_EQ(s.files, (std::vector<std::string>{"margin/helpers.glsl", "margin/lit.frag"}));
    EXPECT_TRUE(s.notes.empty());
    std::ifstream copy(s.root + "/margin/lit.frag");
    std::string text((std::istreambuf_iterator<char>(copy)), {});
    EXPECT_EQ(text, "// mine\n");
    EXPECT_EQ(stageFiles(s, "margin", kShipped), (std::vector<std::string>{"margin/lit.frag"}));
    EXPECT_TRUE(stageFiles(s, "depth", kShipped).empty());
    EXPECT_EQ(expectedFiles("depth", kShipped),
              (std::vector<std::string>{"depth/lit.frag", "depth/lit.vert"}));
}

TEST(Intake, LoneWrapperFolderIsDescendedWithANote) {
    Folder f;
    f.put("jdoe_lab4/margin/lit.frag");
    f.put("__MACOSX/jdoe_lab4/margin/._lit.frag");
    f.put(".DS_Store");
    Submission s = take(f);
    EXPECT_EQ(s.files, (std::vector<std::string>{"margin/lit.frag"}));
    EXPECT_TRUE(hasNote(s, "one folder, `jdoe_lab4/`"));
    EXPECT_EQ(s.folder, f.path() + "/jdoe_lab4");
}

TEST(Intake, AStageFolderAloneIsNotAWrapper) {
    Folder f;
    f.put("margin/lit.frag");
    Submission s = take(f);
    EXPECT_EQ(s.folder, f.path());
    EXPECT_TRUE(s.notes.empty());
}

TEST(Intake, JunkIsLeftOutSilently) {
    Folder f;
    f.put("margin/lit.frag");
    f.put("margin/lit.frag~");
    f.put("margin/.lit.frag.swp");
    f.put("margin/#lit.frag#");
    f.put("__MACOSX/margin/._lit.frag");
    Submission s = take(f);
    EXPECT_EQ(s.files, (std::vector<std::string>{"margin/lit.frag"}));
    EXPECT_TRUE(s.notes.empty());
}

TEST(Intake, NearMissesAreNamed) {
    Folder f;
    f.put("depth/lit.frag");  // something real, so intake goes on
    f.put("Margin/lit.vert");
    f.put("margin/shadow.fs");
    f.put("lit.frag");
    f.put("shaders_core/rgb/shadow.frag");
    Submission s = take(f, {"margin", "rgb"});
    EXPECT_TRUE(hasNote(s, "`Margin/lit.vert` was not used: did you mean `margin/lit.vert`?"));
    EXPECT_TRUE(hasNote(s, "`margin/shadow.fs` was not used: did you mean `margin/shadow.frag`?"));
    EXPECT_TRUE(hasNote(s, "`lit.frag` was not used: did you mean `margin/lit.frag`?"));
    EXPECT_TRUE(hasNote(s,
                        "`shaders_core/rgb/shadow.frag` was not used: did you mean "
                        "`rgb/shadow.frag`?"));
    EXPECT_TRUE(stageFiles(s, "margin", kShipped).empty());
    EXPECT_TRUE(stageFiles(s, "rgb", kShipped).empty());
}

// An assignment grading margin only: no hint sends the student to another stage's folder.
TEST(Intake, NearMissesNameOnlyTheStagesGraded) {
    Folder f;
    f.put("margin/lit.frag");
    f.put("Depth/lit.frag");
    f.put("shadow.frag");
    f.put("shaders_core/rgb/shadow.frag");
    Submission s = take(f, {"margin"});
    EXPECT_TRUE(hasNote(s, "`shadow.frag` was not used: did you mean `margin/shadow.frag`?"));
    for (const std::string& n : s.notes) {
        EXPECT_EQ(n.find("did you mean `depth/"), std::string::npos) << n;
        EXPECT_EQ(n.find("did you mean `rgb/"), std::string::npos) << n;
    }
}

TEST(Intake, NothingReplacedIsOneLineNamingTheNearMiss) {
    Folder empty;
    EXPECT_NE(intakeError(empty).find("no file replaces a shipped shader"), std::string::npos);
    Folder top;
    top.put("lit.frag");
    std::string e = intakeError(top);
    EXPECT_NE(e.find("`lit.frag` was not used: did you mean `"), std::string::npos) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos);
    Folder readme;
    readme.put("README.md");
    EXPECT_NE(intakeError(readme).find("no file replaces"), std::string::npos);
    Folder copied;  // a tree path beside something else: not a wrapper, a near miss
    copied.put("shaders_legacy/margin/lit.frag");
    copied.put("README.md");
    EXPECT_NE(intakeError(copied).find("did you mean `margin/lit.frag`?"), std::string::npos);
}

// A hand-in that is a copy of the whole shipped tree (`lab4-lee/shaders_core/margin/...`) is
// graded from inside it, not MISSING: a lone tree folder is a wrapper like any other.
TEST(Intake, LoneShippedTreeFolderIsAWrapper) {
    for (const char* tree : {"shaders_core", "shaders_legacy"}) {
        Folder f;
        f.put(std::string("lab4-lee/") + tree + "/margin/lit.frag");
        f.put(std::string("lab4-lee/") + tree + "/margin/lit.vert");
        f.put(std::string("lab4-lee/") + tree + "/depth/lit.frag");
        Submission s = take(f, {"margin", "depth"});
        EXPECT_EQ(stageFiles(s, "margin", kShipped),
                  (std::vector<std::string>{"margin/lit.frag", "margin/lit.vert"}))
            << tree;
        EXPECT_EQ(stageFiles(s, "depth", kShipped), (std::vector<std::string>{"depth/lit.frag"}))
            << tree;
        EXPECT_TRUE(hasNote(s, "one folder, `lab4-lee/`")) << tree;
        EXPECT_TRUE(hasNote(
            s, std::string("one folder, `") + tree + "/` (a copy of the shipped shader tree)"))
            << tree;
        EXPECT_EQ(s.folder, f.path() + "/lab4-lee/" + tree);
    }
}

TEST(Intake, LinksAndSpecialFilesAreNotFollowed) {
    Folder secret;
    std::string target = secret.put("secret.txt", "the answer\n");
    Folder f;
    f.put("margin/lit.frag");
    fs::create_symlink(target, f.path() + "/margin/lit.vert");
    fs::create_directory_symlink(secret.path(), f.path() + "/depth");
    Submission s = take(f);
    EXPECT_EQ(s.files, (std::vector<std::string>{"margin/lit.frag"}));
    EXPECT_TRUE(hasNote(s, "`margin/lit.vert` was not used: a symbolic link"));
    EXPECT_TRUE(hasNote(s, "`depth` was not used: a symbolic link"));
    EXPECT_FALSE(fs::exists(s.root + "/margin/lit.vert"));
}

TEST(Intake, HardLinksAreRefused) {
    Folder secret;
    std::string target = secret.put("secret.txt", "the answer\n");
    Folder f;
    f.put("margin/lit.frag");
    fs::create_directories(f.path() + "/common");
    fs::create_hard_link(target, f.path() + "/common/extra.glsl");
    Submission s = take(f);
    EXPECT_EQ(s.files, (std::vector<std::string>{"margin/lit.frag"}));
    EXPECT_TRUE(hasNote(s, "`common/extra.glsl` was not used: it has 2 hard links"));
    fs::create_hard_link(target, f.path() + "/margin/lit.vert");  // a shader's own name
    EXPECT_NE(intakeError(f).find("margin/lit.vert: has 3 hard links"), std::string::npos);
}

TEST(Intake, BoundsAreOneLine) {
    Folder big;
    big.put("margin/lit.frag", std::string((1u << 20) + 1, 'x'));
    EXPECT_NE(intakeError(big).find("a shader file holds at most"), std::string::npos);
    Folder many;
    many.put("margin/lit.frag");
    for (int i = 0; i < 2100; ++i) many.put("margin/junkfile" + std::to_string(i));
    EXPECT_NE(intakeError(many).find("more than 2048 files"), std::string::npos);
    Folder notAFolder;
    std::string file = notAFolder.put("x.frag");
    EXPECT_THROW(takeSubmission(file, notAFolder.path(), kShipped), IntakeError);
    EXPECT_THROW(takeSubmission("", notAFolder.path(), kShipped), IntakeError);
}

TEST(Intake, PrivateDirIsRemovedWithItsContents) {
    std::string path;
    {
        PrivateDir d("sl-intake-rm");
        path = d.path();
        std::ofstream(path + "/x") << "x";
        EXPECT_EQ(fs::status(path).permissions() & fs::perms::others_all, fs::perms::none);
    }
    EXPECT_FALSE(fs::exists(path));
}

// A stray top-level lit.frag is named whatever else was handed in (issue 39): the graded stages
// whose file it may be and that the hand-in lacks, in the assignment's order; when every one
// was handed in, where a stage's file goes.
TEST(Intake, TopLevelFileNamesTheStagesItMayBelongTo) {
    Folder one;
    one.put("margin/lit.frag");
    one.put("lit.frag");
    EXPECT_TRUE(hasNote(take(one, {"margin", "depth"}),
                        "`lit.frag` was not used: did you mean `depth/lit.frag`?"));
    Folder two;
    two.put("rgb/shadow.frag");
    two.put("lit.frag");
    EXPECT_TRUE(hasNote(take(two, {"rgb", "depth", "margin"}),
                        "`lit.frag` was not used: did you mean `depth/lit.frag` or "
                        "`margin/lit.frag`?"));
    Folder all;
    all.put("margin/lit.frag");
    all.put("depth/lit.frag");
    all.put("lit.frag");
    EXPECT_TRUE(hasNote(take(all, {"margin", "depth"}),
                        "`lit.frag` was not used: a stage's files go in its folder, and "
                        "`margin/lit.frag` and `depth/lit.frag` are handed in already"));
    Folder listed;  // an assignment grading depth/lit.vert alone: depth/lit.frag is no hint
    listed.put("margin/lit.frag");
    listed.put("lit.frag");
    PrivateDir snapshot("sl-intake-listed");
    Submission s = takeSubmission(listed.path(), snapshot.path(), kShipped, {"margin", "depth"},
                                  {"margin/lit.frag", "depth/lit.vert"});
    EXPECT_TRUE(hasNote(s,
                        "`lit.frag` was not used: a stage's files go in its folder, and "
                        "`margin/lit.frag` is handed in already"));
    Folder deeper;  // a misspelt path of a file handed in: nothing to say
    deeper.put("margin/lit.frag");
    deeper.put("Margin/lit.frag");
    for (const std::string& n : take(deeper, {"margin"}).notes)
        EXPECT_EQ(n.find("Margin/lit.frag"), std::string::npos) << n;
}
