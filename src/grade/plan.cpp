#include "grade/plan.h"

#include <algorithm>

namespace sl {

bool StudentWork::has(const std::string& rel) const {
    return std::find(files.begin(), files.end(), rel) != files.end();
}

}  // namespace sl
