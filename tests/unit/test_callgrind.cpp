#include <gtest/gtest.h>

#include <cmath>

#include "metrics/callgrind.h"

using namespace sl;

TEST(Callgrind, TotalsLineOfADump) {
    const char* dump =
        "# callgrind format\nversion: 1\ncmd: shadowlab bench\npart: 3\n\nevents: Ir\n"
        "fn=(1) sl::countedFrames\n0 12\nsummary: 123456789\n\n\ntotals: 123456789\n";
    EXPECT_EQ(parseCallgrindTotal(dump), 123456789);
}

TEST(Callgrind, NoTotalsIsMinusOne) {
    EXPECT_EQ(parseCallgrindTotal(""), -1);
    EXPECT_EQ(parseCallgrindTotal("events: Ir\nfn=main\n0 5\n"), -1);
    EXPECT_EQ(parseCallgrindTotal("totals: lots\n"), -1);
}

TEST(Callgrind, PerFrame) {
    EXPECT_DOUBLE_EQ(instructionsPerFrame(3000, 3), 1000);
    EXPECT_TRUE(std::isnan(instructionsPerFrame(-1, 3)));
    EXPECT_TRUE(std::isnan(instructionsPerFrame(3000, 0)));
}

TEST(Callgrind, CommandStartsWithoutCollectingAndQuotes) {
    std::string c = callgrindCommand("/opt/it's/shadowlab", "/tmp/o/cg.out", "bench --x");
    EXPECT_NE(c.find("LP_NUM_THREADS=0 valgrind --tool=callgrind --collect-atstart=no"),
              std::string::npos);
    EXPECT_NE(c.find("'/opt/it'\\''s/shadowlab' bench --x"), std::string::npos);
}
