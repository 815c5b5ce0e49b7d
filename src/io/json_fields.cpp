#include "io/json_fields.h"

namespace sl {

std::string unknownKey(const nlohmann::json& obj, const std::set<std::string>& allowed) {
    for (auto it = obj.begin(); it != obj.end(); ++it)
        if (!allowed.count(it.key())) return it.key();
    return "";
}

std::string unknownFieldMessage(const std::set<std::string>& allowed) {
    return "unknown field (allowed: " + commaList(allowed) + ")";
}

}  // namespace sl
