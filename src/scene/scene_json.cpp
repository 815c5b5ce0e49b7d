#include "scene/scene_json.h"

#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "io/data_paths.h"
#include "io/files.h"
#include "io/json_fields.h"

namespace sl {

using nlohmann::json;

namespace {

constexpr std::size_t kMaxObjects = 4096;          // far beyond any teaching scene; guards memory
constexpr std::size_t kMaxSceneBytes = 16u << 20;  // 4096 objects take well under 1 MB

bool fileExists(const std::string& path) {
    struct stat st;
    return ::lstat(path.c_str(), &st) == 0;
}

class Reader {
  public:
    explicit Reader(std::string origin) : origin_(std::move(origin)) {}

    [[noreturn]] void fail(const std::string& path, const std::string& what) const {
        throw SceneError(origin_ + ": " + (path.empty() ? "/" : path) + ": " + what);
    }

    void allowKeys(const json& obj, const std::string& path, std::set<std::string> keys) const {
        if (!obj.is_object()) fail(path, "must be an object");
        std::string unknown = unknownKey(obj, keys);
        if (!unknown.empty()) fail(path + "/" + unknown, unknownFieldMessage(keys));
    }

    const json* field(const json& obj, const std::string& key) const {
        auto it = obj.find(key);
        return it == obj.end() ? nullptr : &*it;
    }

    float number(const json& obj, const std::string& path, const std::string& key,
                 std::optional<float> fallback, float lo, float hi) const {
        const json* v = field(obj, key);
        std::string p = path + "/" + key;
        if (!v) {
            if (fallback) return *fallback;
            fail(p, "missing (a number is required)");
        }
        if (!v->is_number()) fail(p, "must be a number, got " + std::string(v->type_name()));
        double d = v->get<double>();
        if (!std::isfinite(d) || d < lo || d > hi) {
            std::ostringstream s;
            s << "must be a number in [" << lo << ", " << hi << "], got " << d;
            fail(p, s.str());
        }
        return static_cast<float>(d);
    }

    glm::vec3 vec3(const json& obj, const std::string& path, const std::string& key,
                   std::optional<glm::vec3> fallback, float lo = -1e4f, float hi = 1e4f) const {
        const json* v = field(obj, key);
        std::string p = path + "/" + key;
        if (!v) {
            if (fallback) return *fallback;
            fail(p, "missing (an array of 3 numbers is required)");
        }
        if (!v->is_array() || v->size() != 3) fail(p, "must be an array of 3 numbers");
        glm::vec3 r;
        for (int i = 0; i < 3; ++i) {
            const json& e = (*v)[i];
            if (!e.is_number()) fail(p + "/" + std::to_string(i), "must be a number");
            double d = e.get<double>();
            if (!std::isfinite(d) || d < lo || d > hi)
                fail(p + "/" + std::to_string(i), "must be a finite number in [" +
                                                      std::to_string(lo) + ", " +
                                                      std::to_string(hi) + "]");
            r[i] = static_cast<float>(d);
        }
        return r;
    }

    glm::vec3 direction(const json& obj, const std::string& path, const std::string& key,
                        glm::vec3 fallback) const {
        glm::vec3 d = vec3(obj, path, key, fallback);
        if (glm::length(d) < 1e-6f) fail(path + "/" + key, "must be a non-zero direction");
        return glm::normalize(d);
    }

  private:
    std::string origin_;
};

}  // namespace

Scene parseScene(const std::string& text, const std::string& origin) {
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::parse_error& e) {
        // nlohmann's message carries "at line L, column C"; keep that part.
        std::string what = e.what();
        auto pos = what.find("parse error");
        throw SceneError(
            origin + ": not valid JSON: " + (pos == std::string::npos ? what : what.substr(pos)));
    } catch (const json::exception& e) {
        // e.g. out_of_range 406 for 1e999: a number beyond double (found by the fuzzer; it used
        // to escape as an unknown exception, exit code 3).
        std::string what = e.what();
        auto pos = what.find("] ");
        throw SceneError(origin + ": not valid JSON: " +
                         (pos == std::string::npos ? what : what.substr(pos + 2)));
    }
    Reader r(origin);
    const std::set<std::string> keys = {
        "name",  "description", "background", "camera",
        "light", "material",    "objects",    "mirror"};  // not a stage id: the scene's mirror
    r.allowKeys(doc, "", keys);
    Scene s;
    if (const json* n = r.field(doc, "name")) {
        if (!n->is_string()) r.fail("/name", "must be a string");
        s.name = n->get<std::string>();
    }
    s.background = r.vec3(doc, "", "background", s.background, 0.0f, 1.0f);

    const json* cam = r.field(doc, "camera");
    if (!cam) r.fail("/camera", "missing (eye, at, fovy)");
    r.allowKeys(*cam, "/camera", {"eye", "at", "fovy", "near", "far"});
    s.camera.eye = r.vec3(*cam, "/camera", "eye", std::nullopt);
    s.camera.at = r.vec3(*cam, "/camera", "at", std::nullopt);
    s.camera.fovyDegrees = r.number(*cam, "/camera", "fovy", 45.0f, 1.0f, 170.0f);
    s.camera.zNear = r.number(*cam, "/camera", "near", 0.1f, 1e-4f, 1e3f);
    s.camera.zFar = r.number(*cam, "/camera", "far", 50.0f, 1e-3f, 1e6f);
    if (s.camera.zFar <= s.camera.zNear) r.fail("/camera/far", "must be greater than near");
    if (glm::length(s.camera.at - s.camera.eye) < 1e-6f)
        r.fail("/camera/at", "must differ from the eye");

    const json* light = r.field(doc, "light");
    if (!light) r.fail("/light", "missing (position, target)");
    r.allowKeys(*light, "/light", {"position", "target"});
    s.light.position = r.vec3(*light, "/light", "position", std::nullopt);
    s.light.target = r.vec3(*light, "/light", "target", glm::vec3(0.0f));
    if (glm::length(s.light.target - s.light.position) < 1e-6f)
        r.fail("/light/target", "must differ from the light position");

    if (const json* m = r.field(doc, "material")) {
        r.allowKeys(*m, "/material", {"ambient", "diffuse", "specular", "shininess"});
        s.material.ambient = r.number(*m, "/material", "ambient", s.material.ambient, 0, 1);
        s.material.diffuse = r.number(*m, "/material", "diffuse", s.material.diffuse, 0, 1);
        s.material.specular = r.number(*m, "/material", "specular", s.material.specular, 0, 1);
        s.material.shininess = r.number(*m, "/material", "shininess", s.material.shininess, 1, 512);
    }

    const json* objects = r.field(doc, "objects");
    if (!objects || !objects->is_array()) r.fail("/objects", "missing (an array of objects)");
    if (objects->empty()) r.fail("/objects", "is empty: a scene needs at least one object");
    if (objects->size() > kMaxObjects)
        r.fail("/objects", "has " + std::to_string(objects->size()) + " objects; at most " +
                               std::to_string(kMaxObjects) + " are allowed");
    for (std::size_t i = 0; i < objects->size(); ++i) {
        const json& o = (*objects)[i];
        std::string p = "/objects/" + std::to_string(i);
        if (!o.is_object()) r.fail(p, "must be an object");
        const json* type = r.field(o, "type");
        if (!type || !type->is_string()) r.fail(p + "/type", "missing (box, sphere or quad)");
        std::string t = type->get<std::string>();
        Object obj;
        obj.name = t + std::to_string(i);
        if (const json* n = r.field(o, "name")) {
            if (!n->is_string()) r.fail(p + "/name", "must be a string");
            obj.name = n->get<std::string>();
        }
        obj.color = r.vec3(o, p, "color", glm::vec3(0.8f), 0.0f, 1.0f);
        if (const json* c = r.field(o, "casts_shadow")) {
            if (!c->is_boolean()) r.fail(p + "/casts_shadow", "must be true or false");
            obj.castsShadow = c->get<bool>();
        }
        obj.center = r.vec3(o, p, "center", std::nullopt);
        if (t == "box") {
            r.allowKeys(o, p, {"type", "name", "color", "casts_shadow", "center", "size"});
            obj.kind = PrimitiveKind::Box;
            obj.size = r.vec3(o, p, "size", std::nullopt, 1e-4f, 1e4f);
        } else if (t == "sphere") {
            r.allowKeys(o, p, {"type", "name", "color", "casts_shadow", "center", "radius"});
            obj.kind = PrimitiveKind::Sphere;
            obj.radius = r.number(o, p, "radius", std::nullopt, 1e-4f, 1e4f);
        } else if (t == "quad") {
            r.allowKeys(o, p,
                        {"type", "name", "color", "casts_shadow", "center", "normal", "up", "width",
                         "height"});
            obj.kind = PrimitiveKind::Quad;
            obj.normal = r.direction(o, p, "normal", {0, 1, 0});
            glm::vec3 up = r.direction(o, p, "up", {0, 0, -1});
            up -= glm::dot(up, obj.normal) * obj.normal;
            if (glm::length(up) < 1e-4f) r.fail(p + "/up", "must not be parallel to the normal");
            obj.up = glm::normalize(up);
            obj.width = r.number(o, p, "width", std::nullopt, 1e-4f, 1e4f);
            obj.height = r.number(o, p, "height", std::nullopt, 1e-4f, 1e4f);
        } else {
            r.fail(p + "/type", "unknown primitive '" + t + "' (allowed: box, sphere, quad)");
        }
        if (pointInside(obj, s.light.position))
            r.fail(p, "the light at /light/position is inside this object");
        s.objects.push_back(obj);
    }

    // not a stage id: the scene file's "mirror" field
    if (const json* m = r.field(doc, "mirror")) {
        r.allowKeys(*m, "/mirror", {"center", "normal", "up", "width", "height"});
        Mirror mirror;
        mirror.center = r.vec3(*m, "/mirror", "center", std::nullopt);
        mirror.normal = r.direction(*m, "/mirror", "normal", {0, 0, 1});
        glm::vec3 up = r.direction(*m, "/mirror", "up", {0, 1, 0});
        up -= glm::dot(up, mirror.normal) * mirror.normal;
        if (glm::length(up) < 1e-4f) r.fail("/mirror/up", "must not be parallel to the normal");
        mirror.up = glm::normalize(up);
        mirror.width = r.number(*m, "/mirror", "width", std::nullopt, 1e-4f, 1e4f);
        mirror.height = r.number(*m, "/mirror", "height", std::nullopt, 1e-4f, 1e4f);
        s.mirror = mirror;
    }
    return s;
}

std::vector<std::string> builtInScenes() {
    std::vector<std::string> names;
    std::string dir = dataDir() + "/scenes";
    if (DIR* d = ::opendir(dir.c_str())) {
        while (dirent* e = ::readdir(d)) {
            std::string f = e->d_name;
            if (f.size() > 5 && f.compare(f.size() - 5, 5, ".json") == 0)
                names.push_back(f.substr(0, f.size() - 5));
        }
        ::closedir(d);
    }
    std::sort(names.begin(), names.end());
    return names;
}

Scene loadScene(const std::string& nameOrPath) {
    bool isPath = nameOrPath.find('/') != std::string::npos ||
                  (nameOrPath.size() > 5 && nameOrPath.rfind(".json") == nameOrPath.size() - 5);
    std::string path = isPath ? nameOrPath : dataDir() + "/scenes/" + nameOrPath + ".json";
    std::string text;
    if (!isPath && !fileExists(path)) {
        std::string names;
        for (const auto& n : builtInScenes()) names += (names.empty() ? "" : ", ") + n;
        throw SceneError("unknown scene '" + nameOrPath + "' (built-in: " + names +
                         "; or give a path to a .json file)");
    }
    // A scene may be a FIFO or a link to /dev/zero: only a regular file, read with a bound.
    std::string why = readRegularFile(path, kMaxSceneBytes, text);
    if (!why.empty()) throw SceneError(nameOrPath + ": cannot read scene file: " + why);
    Scene s = parseScene(text, isPath ? nameOrPath : "scene '" + nameOrPath + "'");
    if (s.name.empty()) s.name = nameOrPath;
    return s;
}

}  // namespace sl
