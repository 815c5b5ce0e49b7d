// The figure table (metrics/figures.h) as JSON: what `stages --figures --json` prints and what
// `bench` writes into bench.json, so the pages made from them (scripts/results_md.py) name each
// figure's column from the table, not from words of their own.
#pragma once

#include <nlohmann/json.hpp>

namespace sl {

// [{"name", "unit", "better" ("lower" | "higher"), "kind" ("shadow" | "look" | "mirror"),
// "words"}], in the table's order.
nlohmann::json figureTableJson();

}  // namespace sl
