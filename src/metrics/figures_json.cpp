#include "metrics/figures_json.h"

#include "metrics/figures.h"

namespace sl {

namespace {

const char* kindName(FigureKind kind) {
    switch (kind) {
        case FigureKind::Shadow:
            return "shadow";
        case FigureKind::Look:
            return "look";
        case FigureKind::Mirror:
            // not a stage id: the kind of figure (metrics/figures.h), the mirror's measures
            return "mirror";
    }
    return "";
}

}  // namespace

nlohmann::json figureTableJson() {
    nlohmann::json out = nlohmann::json::array();
    for (const FigureInfo& f : figureTable())
        out.push_back({{"name", f.name},
                       {"unit", f.unit},
                       {"better", f.better == Better::Lower ? "lower" : "higher"},
                       {"kind", kindName(f.kind)},
                       {"words", f.words}});
    return out;
}

}  // namespace sl
