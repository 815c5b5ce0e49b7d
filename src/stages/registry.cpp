#include <algorithm>

#include "stages/stage.h"

namespace sl {

#define SL_STAGE(id) StageInfo id##Stage();
#include "stages/stage_list.h"
#undef SL_STAGE

const std::vector<StageInfo>& stageRegistry() {
    static const std::vector<StageInfo> stages = {
#define SL_STAGE(id) id##Stage(),
#include "stages/stage_list.h"
#undef SL_STAGE
    };
    return stages;
}

const StageInfo* findStage(const std::string& id) {
    for (const auto& s : stageRegistry())
        if (s.id == id) return &s;
    return nullptr;
}

std::vector<std::string> stageIds() {
    std::vector<std::string> ids;
    for (const auto& s : stageRegistry()) ids.push_back(s.id);
    return ids;
}

}  // namespace sl
