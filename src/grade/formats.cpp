#include "grade/formats.h"

namespace sl {

void requireFormat(const nlohmann::json& j, const Format& want, const char* nameKey,
                   const char* versionKey, const std::string& what) {
    const std::string reads =
        ", reads " + std::string(want.name) + " version " + std::to_string(want.version);
    if (!j.is_object()) throw FormatError(what + ": got " + j.type_name() + reads, false);
    if (!j.contains(nameKey))
        throw FormatError(what + ": got no \"" + nameKey + "\" (an older shadowlab's)" + reads,
                          true);
    const nlohmann::json& name = j[nameKey];
    const nlohmann::json& version = j.contains(versionKey) ? j[versionKey] : nlohmann::json();
    const bool sameName = name.is_string() && name.get<std::string>() == want.name;
    if (sameName && version.is_number_integer() && version.get<long long>() == want.version) return;
    const bool older =
        sameName && version.is_number_integer() && version.get<long long>() < want.version;
    throw FormatError(what + ": got " + name.dump() + " version " + version.dump() + reads, older);
}

}  // namespace sl
