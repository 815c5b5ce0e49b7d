#include "stages/registry.h"

#include <algorithm>

#include "stages/stage.h"

namespace sl {

#define SL_STAGE(id) StageDefinition id##Stage();
#include "stages/stage_list.h"
#undef SL_STAGE

const std::vector<StageDefinition>& stageRegistry() {
    static const std::vector<StageDefinition> stages = {
#define SL_STAGE(id) id##Stage(),
#include "stages/stage_list.h"
#undef SL_STAGE
    };
    return stages;
}

const StageDefinition* findStage(const std::string& id) {
    for (const auto& s : stageRegistry())
        if (s.id == id) return &s;
    return nullptr;
}

std::vector<std::string> stageIds() {
    std::vector<std::string> ids;
    for (const auto& s : stageRegistry()) ids.push_back(s.id);
    return ids;
}

const StageDefinition& lightingStage() {
    return stageRegistry().front();
}

bool stageNeedsMirror(const std::string& id) {
    const StageDefinition* s = findStage(id);
    return s && s->needsMirror;
}

std::vector<const StageInfo*> stageInfos() {
    std::vector<const StageInfo*> infos;
    for (const auto& s : stageRegistry()) infos.push_back(&s);
    return infos;
}

std::vector<StageSeries> benchSeriesIn(BenchGroup group) {
    std::vector<StageSeries> out;
    for (const auto& s : stageRegistry())
        for (const BenchSeries& b : s.benchSeries)
            if (b.group == group) out.push_back({&s, &b});
    // Stage order and each stage's own order are the registry's: a stable sort keeps them.
    std::stable_sort(out.begin(), out.end(), [](const StageSeries& a, const StageSeries& b) {
        return a.series->rank < b.series->rank;
    });
    return out;
}

}  // namespace sl
