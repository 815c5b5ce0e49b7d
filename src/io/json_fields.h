// Validating untrusted JSON objects (scene and assignment files): both name a field they do not
// know, and what is allowed, the same way.
#pragma once

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

namespace sl {

// The first key of `obj` (an object) that is not in `allowed`, or "" when every key is known.
std::string unknownKey(const nlohmann::json& obj, const std::set<std::string>& allowed);

// "a, b, c": the names a validator allows (or any list of names, in its order), for messages.
template <class Names>
std::string commaList(const Names& names) {
    std::string list;
    for (const std::string& k : names) list += (list.empty() ? "" : ", ") + k;
    return list;
}

// "unknown field (allowed: a, b, c)": the message for such a key.
std::string unknownFieldMessage(const std::set<std::string>& allowed);

// A vector as JSON [x, y, z] and back (`vec3FromJson` throws nlohmann::json::exception on
// anything else): the reports' cameras and lights and the browser's views.
nlohmann::json vec3Json(const glm::vec3& v);
glm::vec3 vec3FromJson(const nlohmann::json& v);

}  // namespace sl
