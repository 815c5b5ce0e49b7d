#include "stages/drawn_figures.h"

#include <nlohmann/json.hpp>

#include "io/data_paths.h"
#include "stages/expectations.h"

namespace sl {

namespace {

struct Table {
    std::vector<std::uint64_t> seeds;
    std::map<std::string, ShippedDrawn> rows;  // by "stage/tree/row label@seed"
};

std::string keyOf(const std::string& stage, const std::string& tree, const std::string& label,
                  std::uint64_t seed) {
    return stage + "/" + tree + "/" + label + "@" + std::to_string(seed);
}

Table readTable() {
    const std::string path = drawnFiguresPath();
    Table table;
    try {
        nlohmann::json doc = nlohmann::json::parse(readStageData(path));
        for (const auto& s : doc.at("seeds")) table.seeds.push_back(s.get<std::uint64_t>());
        for (const auto& [row, bySeed] : doc.at("rows").items())
            for (const auto& [seed, entry] : bySeed.items()) {
                ShippedDrawn d;
                d.drawn = entry.at("drawn").get<std::string>();
                for (const auto& [figure, value] : entry.at("figures").items())
                    d.figures[figure] = value.get<double>();
                table.rows[row + "@" + seed] = std::move(d);
            }
    } catch (const nlohmann::json::exception& e) {
        throw ExpectationError(path + ": " + e.what());
    }
    return table;
}

const Table& table() {
    static const Table t = readTable();
    return t;
}

}  // namespace

std::string drawnFiguresPath() {
    return dataDir() + "/src/stages/drawn_figures.json";
}

const std::vector<std::uint64_t>& shippedDrawnSeeds() {
    return table().seeds;
}

std::uint64_t shippedDrawnSeed(std::uint64_t seed) {
    const std::vector<std::uint64_t>& seeds = shippedDrawnSeeds();
    if (seeds.empty()) return seed;
    for (std::uint64_t s : seeds)
        if (s == seed) return seed;
    return seeds[seed % seeds.size()];
}

const ShippedDrawn* shippedDrawnOf(const DrawnRow& row, const std::string& tree,
                                   std::uint64_t seed) {
    auto found = table().rows.find(keyOf(row.stage, tree, row.label(), seed));
    return found == table().rows.end() ? nullptr : &found->second;
}

std::string drawnValuesText(const DrawnRow& row, std::uint64_t seed) {
    auto settings = drawnSettings(row, seed);
    std::string text;
    for (std::size_t k = row.set.size(); k < settings.size(); ++k)
        text += (text.empty() ? "" : " ") + settings[k].first + "=" + settings[k].second;
    return text;
}

}  // namespace sl
