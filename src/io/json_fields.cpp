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

nlohmann::json vec3Json(const glm::vec3& v) {
    return {v.x, v.y, v.z};
}

glm::vec3 vec3FromJson(const nlohmann::json& v) {
    return {v.at(0).get<float>(), v.at(1).get<float>(), v.at(2).get<float>()};
}

}  // namespace sl
