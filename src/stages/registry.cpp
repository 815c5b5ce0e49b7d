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

namespace {
const char* const kViewNames[] = {"final", "shadow-map", "light", "visibility", "light-depth"};
}

const char* viewName(ViewMode v) {
    return kViewNames[static_cast<int>(v)];
}

bool parseView(const std::string& text, ViewMode& out) {
    for (int i = 0; i < 5; ++i)
        if (text == kViewNames[i]) {
            out = static_cast<ViewMode>(i);
            return true;
        }
    return false;
}

std::vector<std::string> allViewNames() {
    return {std::begin(kViewNames), std::end(kViewNames)};
}

}  // namespace sl
