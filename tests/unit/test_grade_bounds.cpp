// Bounds on grading's texts (src/grade/bounds.h) and messages naming a snapshot by the
// student's folder (io/files.h showFolderAs).
#include <gtest/gtest.h>

#include "grade/bounds.h"
#include "io/files.h"

using namespace sl;

TEST(Capped, ShortTextIsWhole) {
    EXPECT_EQ(capped("abc", 3), "abc");
}

TEST(Capped, LongTextSaysHowMuchWasCut) {
    std::string text(10000, 'x');
    std::string out = capped(text, 4096);
    EXPECT_EQ(out, std::string(4096, 'x') + " [... 5904 bytes cut]");
}

TEST(Capped, NeverSplitsAUtf8Character) {
    std::string text =
        "ab\xC3\xA9"
        "cd";                           // "abécd": é is two bytes at 2..3
    std::string out = capped(text, 3);  // a cut at 3 would split é
    EXPECT_EQ(out, "ab [... 4 bytes cut]");
}

TEST(CappedList, NamesHowManyMore) {
    std::vector<std::string> files(40, "margin/lit.frag");
    std::vector<std::string> out = cappedList(files);
    ASSERT_EQ(out.size(), kMaxListedFiles + 1);
    EXPECT_EQ(out.back(), "... and 8 more");
}

TEST(ShowFolderAs, MessagesNameTheStudentsFolder) {
    showFolderAs("/tmp/shadowlab-submission-abc", "/home/ta/jdoe");
    EXPECT_EQ(printableName("/tmp/shadowlab-submission-abc/margin/lit.frag"),
              "/home/ta/jdoe/margin/lit.frag");
    EXPECT_EQ(
        withShownFolders("a /tmp/shadowlab-submission-abc/x + /tmp/shadowlab-submission-abc/y"),
        "a /home/ta/jdoe/x + /home/ta/jdoe/y");
    EXPECT_EQ(printableName("/elsewhere/lit.frag"), "/elsewhere/lit.frag");
    showFolderAs("", "");
    EXPECT_EQ(printableName("/tmp/shadowlab-submission-abc/a"), "/tmp/shadowlab-submission-abc/a");
}
