// Bounded reads of untrusted files and the output-file checks (src/io/files.h).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "io/files.h"

namespace fs = std::filesystem;
using namespace sl;

namespace {

struct TempDir {
    fs::path path;
    TempDir() {
        char name[] = "/tmp/sl-files-XXXXXX";
        path = ::mkdtemp(name);
    }
    ~TempDir() { fs::remove_all(path); }
    std::string operator/(const std::string& f) const { return (path / f).string(); }
};

void write(const std::string& path, const std::string& text) {
    std::ofstream(path) << text;
}

}  // namespace

TEST(ReadRegularFile, ReadsAFileWithinItsBound) {
    TempDir t;
    write(t / "a.txt", "hello");
    std::string text;
    EXPECT_EQ(readRegularFile(t / "a.txt", 5, text), "");
    EXPECT_EQ(text, "hello");
    EXPECT_NE(readRegularFile(t / "a.txt", 4, text).find("at most 4"), std::string::npos);
    EXPECT_TRUE(text.empty());
}

TEST(ReadRegularFile, RefusesAFifoWithoutBlocking) {
    TempDir t;
    ASSERT_EQ(::mkfifo((t / "pipe").c_str(), 0600), 0);
    std::string text;
    EXPECT_NE(readRegularFile(t / "pipe", 100, text).find("FIFO"), std::string::npos);
}

TEST(ReadRegularFile, RefusesDevicesAndFolders) {
    std::string text;
    EXPECT_NE(readRegularFile("/dev/zero", 100, text).find("device"), std::string::npos);
    EXPECT_NE(readRegularFile("/tmp", 100, text).find("folder"), std::string::npos);
    TempDir t;
    fs::create_symlink("/dev/zero", t / "zero.json");
    EXPECT_NE(readRegularFile(t / "zero.json", 100, text).find("device"), std::string::npos);
}

TEST(ReadRegularFile, NoFollowRefusesASymlink) {
    TempDir t;
    write(t / "real", "x");
    fs::create_symlink(t / "real", t / "link");
    std::string text;
    EXPECT_EQ(readRegularFile(t / "link", 10, text, false), "");
    EXPECT_NE(readRegularFile(t / "link", 10, text, true), "");
}

TEST(OutputPath, RefusesSymlinksReadOnlyFilesFoldersAndMissingFolders) {
    TempDir t;
    EXPECT_EQ(outputPathProblem(t / "new.png"), "");
    write(t / "victim", "v");
    fs::create_symlink(t / "victim", t / "link.png");
    EXPECT_NE(outputPathProblem(t / "link.png").find("symbolic link"), std::string::npos);
    write(t / "ro.png", "r");
    ::chmod((t / "ro.png").c_str(), 0444);
    EXPECT_NE(outputPathProblem(t / "ro.png").find("read-only"), std::string::npos);
    EXPECT_NE(outputPathProblem(t.path.string()).find("folder"), std::string::npos);
    EXPECT_NE(outputPathProblem(t / "no/such.png"), "");
    EXPECT_NE(outputPathProblem("/dev/null").find("not a regular file"), std::string::npos);
}

TEST(WriteFileAtomically, WritesAndLeavesNoTemporary) {
    TempDir t;
    EXPECT_EQ(writeFileAtomically(t / "out.txt", "abc", 3), "");
    std::string text;
    EXPECT_EQ(readRegularFile(t / "out.txt", 10, text), "");
    EXPECT_EQ(text, "abc");
    int entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(t.path)) ++entries;
    EXPECT_EQ(entries, 1);
}

TEST(WriteFileAtomically, NeverWritesThroughALinkAtTheTarget) {
    TempDir t;
    write(t / "victim", "victim");
    fs::create_symlink(t / "victim", t / "out.txt");
    EXPECT_NE(writeFileAtomically(t / "out.txt", "abc", 3), "");
    std::string text;
    readRegularFile(t / "victim", 100, text);
    EXPECT_EQ(text, "victim");
    EXPECT_TRUE(fs::is_symlink(t / "out.txt"));
}

TEST(Text, ValidUtf8ReplacesOnlyBadBytes) {
    EXPECT_EQ(validUtf8("ok \xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80"),
              "ok \xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80");
    EXPECT_EQ(validUtf8("a\xff\xfe"
                        "b"),
              "a??b");
    EXPECT_EQ(validUtf8("\xc3"), "?");            // truncated
    EXPECT_EQ(validUtf8("\xc0\xaf"), "??");       // overlong
    EXPECT_EQ(validUtf8("\xed\xa0\x80"), "???");  // surrogate
}

TEST(Text, PrintableKeepsNewlinesAndTabsOnly) {
    EXPECT_EQ(printable("a\x1b[31mb\tc\nd\r\x7f"), "a?[31mb\tc\nd??");
}

// A name from a student's folder keeps a message on one line: newlines and tabs too.
TEST(Text, PrintableNameHasNoControlCharactersAtAll) {
    EXPECT_EQ(printableName("st\nu\tde\x1b[2Jnt\xff"), "st?u?de?[2Jnt?");
}

// A name as the file system gave it (Latin-1 from an old zip tool) shown escaped, byte by byte:
// two names one byte apart stay two names on a page (issue 39).
TEST(Text, EscapedNameShowsEveryByteThatIsNotUtf8) {
    EXPECT_EQ(escapedName("caf\xe9"), "caf\\xE9");
    EXPECT_NE(escapedName("caf\xe9"), escapedName("caf\xe8"));
    EXPECT_EQ(escapedName("\xc3\xa9t\xc3\xa9"), "\xc3\xa9t\xc3\xa9");  // UTF-8 "été" kept
}

// The file is written unnamed (O_TMPFILE) and linked only when whole: no temporary name ever
// appears in the folder, and a planted file at a likely temporary name is not touched.
TEST(WriteFileAtomically, LeavesPlantedTemporaryNamesAlone) {
    TempDir t;
    write(t / "victim", "victim");
    for (int k = 0; k < 50; ++k)
        fs::create_symlink(t / "victim", t / ("out.txt.tmp" + std::to_string(k)));
    EXPECT_EQ(writeFileAtomically(t / "out.txt", "abc", 3), "");
    std::string text;
    readRegularFile(t / "victim", 100, text);
    EXPECT_EQ(text, "victim");
    int entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(t.path)) ++entries;
    EXPECT_EQ(entries, 52);  // victim, the 50 links, out.txt
}
