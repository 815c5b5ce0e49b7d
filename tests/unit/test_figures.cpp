// The one figure table (metrics/figures.h): every judged figure of Accuracy is in it once, its
// unit is what its name ends in, and the lists that used to be copies (the figure names a limit
// may use, bench's and sweep's columns) are read from it.
#include <gtest/gtest.h>

#include <set>

#include "metrics/figures.h"
#include "stages/expectations.h"

namespace sl {
namespace {

TEST(Figures, EveryAccuracyFigureOnceErrorPctAside) {
    std::set<std::string> names;
    std::vector<double Accuracy::*> fields;
    for (const FigureInfo& f : figureTable()) {
        EXPECT_TRUE(names.insert(f.name).second) << f.name << " twice";
        for (double Accuracy::*seen : fields)
            EXPECT_NE(seen, f.field) << f.name << " reads a field another reads";
        fields.push_back(f.field);
        EXPECT_NE(f.field, &Accuracy::errorPct) << f.name << ": error % is the charts', unjudged";
    }
    // Accuracy is doubles only: one per table row, and errorPct. A figure added to Accuracy and
    // not to the table fails here.
    EXPECT_EQ(sizeof(Accuracy), (figureTable().size() + 1) * sizeof(double));
}

TEST(Figures, UnitIsTheNamesSuffix) {
    const std::pair<std::string, std::string> suffixes[] = {
        {"_pct", "%"}, {"_px", "px"}, {"_db", "dB"}};
    for (const FigureInfo& f : figureTable()) {
        std::string name = f.name, unit;
        for (const auto& [suffix, u] : suffixes)
            if (name.size() > suffix.size() &&
                name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
                unit = u;
        EXPECT_EQ(unit, f.unit) << name;
        EXPECT_FALSE(std::string(f.words).empty()) << name;
    }
}

TEST(Figures, ReadsAndWritesTheNamedField) {
    Accuracy a;
    for (const FigureInfo& f : figureTable()) a.*f.field = static_cast<double>(f.name[0]);
    EXPECT_EQ(a.falseShadowPct, 'f');
    EXPECT_EQ(a.mirrorPsnrDb, 'm');
    EXPECT_TRUE(std::isnan(a.errorPct));
    EXPECT_EQ(findFigure("mirror_psnr_db")->field, &Accuracy::mirrorPsnrDb);
    EXPECT_EQ(findFigure("mirror_psnr_db")->better, Better::Higher);
    EXPECT_EQ(findFigure("false_lit_pct")->better, Better::Lower);
    EXPECT_EQ(findFigure("no_such_figure"), nullptr);
}

TEST(Figures, LimitNamesAreTheTables) {
    std::vector<std::string> table;
    for (const FigureInfo& f : figureTable()) table.push_back(f.name);
    EXPECT_EQ(figureNames(), table);
    std::vector<std::string> kinds;
    for (FigureKind k : {FigureKind::Shadow, FigureKind::Look, FigureKind::Mirror})
        for (const std::string& n : figureNamesOf(k)) kinds.push_back(n);
    EXPECT_EQ(std::set<std::string>(kinds.begin(), kinds.end()),
              std::set<std::string>(table.begin(), table.end()));
    EXPECT_EQ(kinds.size(), table.size());
}

}  // namespace
}  // namespace sl
