// What `bench` measures of a stage beyond its defaults: its series, declared by the stage file
// (StageDefinition::benchSeries), so a new stage brings its own and bench/ names no stage.
// A series is a method at given settings (--set values); the bench adds the axis it varies (the
// map size, the light fit) after them. The window group (every stage at its defaults) and the
// phong baseline need no declaration.
#pragma once

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace sl {

// The groups of bench's plan a series can be in (bench writes their names: "map-size", ...).
enum class BenchGroup {
    MapSize,       // the method at maps of 128..4096 (quick: 256, 1024)
    Format,        // storage formats at a 1024 map (a full run only)
    Mirror,        // the mirror's methods and texture sizes, on the stage's own scene
    EqualAccuracy  // each method's cheapest configuration reaching the accuracy bar
};
// The group's name in bench.csv and bench.json ("map-size", "format", "mirror", "equal-accuracy").
inline const char* benchGroupName(BenchGroup group) {
    switch (group) {
        case BenchGroup::MapSize:
            return "map-size";
        case BenchGroup::Format:
            return "format";
        case BenchGroup::Mirror:
            return "mirror";
        case BenchGroup::EqualAccuracy:
            return "equal-accuracy";
    }
    return "";
}

// A speed target read from the summary (never asserted in a test): the series' rows 640 wide
// (and at `mapSize` when it is not 0) at most `atMost` times phong. The summary line is
// "target " + what + each bound's words and "(<= bound: met|MISSED)", joined by "; "; "{ratio}"
// in the words stands for the measured ratio.
struct BenchBound {
    bool moving = false;  // the light moving (every frame re-renders the map) or still
    double atMost = NAN;
    std::string words;  // e.g. "light moving: {ratio}x phong"
};
struct BenchTarget {
    std::string what;  // "hardware, 1024 map, ": the line's start, up to the first bound
    int mapSize = 0;
    std::vector<BenchBound> bounds;  // joined by "; " on one line
};

struct BenchSeries {
    using Settings = std::vector<std::pair<std::string, std::string>>;
    BenchSeries(BenchGroup group, std::string name, Settings sets = {})
        : group(group), name(std::move(name)), sets(std::move(sets)) {}

    BenchGroup group;
    std::string name;     // the stage id, or the stage id + "/" + what differs ("hardware/nearest")
    Settings sets;        // in the order written, before the axis the group varies
    bool inQuick = true;  // also in `bench --quick` (whose plan has no format group at all)
    // Where the series sits in its group's rows: ascending rank, then stage order, then the
    // order declared. Rank 0 unless a series was placed after a later stage's (the published
    // tables keep their row order).
    int rank = 0;
    std::vector<BenchTarget> targets;

    BenchSeries ranked(int r) const {
        return with([&](BenchSeries& s) { s.rank = r; });
    }
    BenchSeries fullRunOnly() const {
        return with([](BenchSeries& s) { s.inQuick = false; });
    }
    BenchSeries withTarget(BenchTarget t) const {
        return with([&](BenchSeries& s) { s.targets.push_back(t); });
    }

  private:
    template <class Change>
    BenchSeries with(Change change) const {
        BenchSeries copy = *this;
        change(copy);
        return copy;
    }
};

}  // namespace sl
