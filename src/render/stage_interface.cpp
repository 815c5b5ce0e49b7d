#include "render/stage_interface.h"

#include <iterator>

namespace sl {

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
