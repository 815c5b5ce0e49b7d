#include "stages/displaced_bounds.h"

#include <nlohmann/json.hpp>

#include "io/data_paths.h"
#include "stages/expectations.h"

namespace sl {

namespace {

using Table = std::map<std::string, DisplacedFigures>;  // by "stage/tree/lesson"

Table readTable() {
    const std::string path = displacedBoundsPath();
    Table table;
    try {
        nlohmann::json doc = nlohmann::json::parse(readStageData(path));
        for (const auto& [key, figures] : doc.at("lessons").items())
            for (const auto& [figure, range] : figures.items())
                table[key][figure] = {range.at(0).get<double>(), range.at(1).get<double>()};
    } catch (const nlohmann::json::exception& e) {
        throw ExpectationError(path + ": " + e.what());
    }
    return table;
}

}  // namespace

std::string displacedBoundsPath() {
    return dataDir() + "/src/stages/displaced_bounds.json";
}

const DisplacedFigures* displacedFiguresOf(const std::string& stage, const std::string& tree,
                                           const std::string& lesson) {
    static const Table table = readTable();
    auto found = table.find(stage + "/" + tree + "/" + lesson);
    return found == table.end() ? nullptr : &found->second;
}

}  // namespace sl
