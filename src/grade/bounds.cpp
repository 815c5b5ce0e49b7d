#include "grade/bounds.h"

namespace sl {

std::vector<std::string> cappedList(const std::vector<std::string>& files) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < files.size() && i < kMaxListedFiles; ++i)
        out.push_back(capped(files[i], 256));
    if (files.size() > kMaxListedFiles)
        out.push_back("... and " + std::to_string(files.size() - kMaxListedFiles) + " more");
    return out;
}

}  // namespace sl
