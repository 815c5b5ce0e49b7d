// The roster's CSV (gradebook/roster.h): RFC 4180 fields, a byte order mark, errors with their
// line.
#include <gtest/gtest.h>

#include "gradebook/roster.h"
#include "io/usage_error.h"

namespace sl {
namespace {

std::string errorOf(const std::string& text) {
    try {
        parseRoster(text, "r.csv");
    } catch (const UsageError& e) {
        return e.what();
    }
    return "";
}

// Hand-ins the roster does not list are named as every other output names them (issue 39 item
// 13): a name that is not UTF-8 escaped byte by byte, so two such names stay two, never '?'.
TEST(Roster, HandInsNotOnItAreNamedEscaped) {
    EXPECT_EQ(notOnRosterLine({"zed"}), "1 hand-in not on the roster: zed");
    EXPECT_EQ(notOnRosterLine({"gus",
                               "\xFE\xFF"
                               "cd",
                               "\xFF\xFE"
                               "ab"}),
              "3 hand-ins not on the roster: gus \\xFE\\xFFcd \\xFF\\xFEab");
}

TEST(Roster, QuotedFieldsBomAndLineEnds) {
    Roster r = parseRoster(
        "\xEF\xBB\xBFId,Name,E-mail,Hand-in\r\n"
        "1,\"Ng, Ann\",a@x,ann\r\n\r\n"
        "2,\"two\nlines \"\"q\"\"\",b@x,bo\n"
        "3,C,c@x,  cy  \n",
        "r.csv");
    ASSERT_EQ(r.entries.size(), 3u);
    EXPECT_EQ(r.entries[0].who.name, "Ng, Ann");
    EXPECT_EQ(r.entries[1].who.name, "two\nlines \"q\"");
    EXPECT_EQ(r.entries[1].line, 4);
    EXPECT_EQ(r.entries[2].line, 6);  // after the quoted line break
    EXPECT_EQ(r.entries[2].handIn, "cy");
    ASSERT_NE(r.find("bo"), nullptr);
    EXPECT_EQ(r.find("bo")->who.id, "2");
    EXPECT_EQ(r.find("nobody"), nullptr);
}

TEST(Roster, MalformedNamesTheLine) {
    const std::string head = "id,name,email,hand-in\n";
    EXPECT_EQ(errorOf(""),
              "r.csv: line 1: empty: give a header row id,name,email,hand-in and a "
              "student per row");
    EXPECT_EQ(errorOf("id,name,email\n"),
              "r.csv: line 1: the header must be id,name,email,hand-in");
    EXPECT_EQ(errorOf(head + "1,a,b,c,d\n"),
              "r.csv: line 2: 5 fields, expected 4 (id,name,email,hand-in; a field holding a "
              "comma is quoted)");
    EXPECT_EQ(errorOf(head + "1,\"a\"b,c,d\n"),
              "r.csv: line 2: text after a closing quote (a quote inside a field is doubled)");
    EXPECT_EQ(errorOf(head + "1,a,b,c\n2,\"open\n"),
              "r.csv: line 3: a quoted field is never closed");
    EXPECT_EQ(errorOf(head + ",a,b,c\n"), "r.csv: line 2: no id");
    EXPECT_EQ(errorOf(head + "1,a,b,\n"), "r.csv: line 2: no hand-in name");
    EXPECT_EQ(errorOf(head + "1,a,b,c\n1,d,e,f\n"), "r.csv: line 3: id '1' is already on line 2");
    EXPECT_EQ(errorOf(head + "1,a,b,c\n2,B\xE9,e,f\n"),
              "r.csv: line 3: not UTF-8 (save the file as UTF-8)");
}

// The limit stated exactly (issue 38): 100,000 students, the error on the first row past it.
TEST(Roster, TheLimitIsStatedInStudents) {
    std::string text = "id,name,email,hand-in\n";
    for (int k = 0; k <= 100000; ++k) {
        std::string n = std::to_string(k);
        text += n + ",S" + n + ",s" + n + "@x.org,h" + n + "\n";
    }
    try {
        parseRoster(text, "r.csv");
        FAIL() << "100,001 students accepted";
    } catch (const UsageError& e) {
        EXPECT_STREQ(e.what(), "r.csv: line 100002: more than 100000 students (the limit)");
    }
}

// A field is bounded: a name of a million bytes is refused naming the line, in one line.
TEST(Roster, AHugeFieldIsRefused) {
    const std::string text = "id,name,email,hand-in\n1," + std::string(1000000, 'n') + ",a@b,h\n";
    try {
        parseRoster(text, "r.csv");
        FAIL() << "accepted";
    } catch (const UsageError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "r.csv: line 2: a field of 1000000 bytes; at most 4096 are allowed");
    }
}

}  // namespace
}  // namespace sl
