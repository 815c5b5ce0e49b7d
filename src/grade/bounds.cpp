#include "grade/bounds.h"

namespace sl {

std::string capped(const std::string& text, std::size_t maxBytes) {
    if (text.size() <= maxBytes) return text;
    std::size_t keep = maxBytes;
    // Back up over continuation bytes (10xxxxxx) so the cut falls between characters.
    while (keep > 0 && (static_cast<unsigned char>(text[keep]) & 0xC0) == 0x80) --keep;
    return text.substr(0, keep) + " [... " + std::to_string(text.size() - keep) + " bytes cut]";
}

std::vector<std::string> cappedList(const std::vector<std::string>& files) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < files.size() && i < kMaxListedFiles; ++i)
        out.push_back(capped(files[i], 256));
    if (files.size() > kMaxListedFiles)
        out.push_back("... and " + std::to_string(files.size() - kMaxListedFiles) + " more");
    return out;
}

}  // namespace sl
