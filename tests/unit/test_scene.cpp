#include <gtest/gtest.h>

#include "scene/mesh.h"
#include "scene/scene_json.h"
#include "stages/params.h"

using namespace sl;

namespace {
std::string errorOf(const std::string& text) {
    try {
        parseScene(text, "t.json");
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}
const char* kMinimal = R"({"camera": {"eye": [0, 2, 4], "at": [0, 0, 0]},
  "light": {"position": [2, 1, 0]},
  "objects": [{"type": "sphere", "center": [0, 0.5, 0], "radius": 0.5}]})";
}  // namespace

TEST(Scene, BuiltInSlidesSceneHasTheLectureDimensions) {
    Scene s = loadScene("slides");
    ASSERT_EQ(s.objects.size(), 4u);
    EXPECT_EQ(s.light.position, glm::vec3(2, 1, 0));
    const Object& floor = s.objects[0];
    EXPECT_FLOAT_EQ(floor.center.y + 0.5f * floor.size.y, 0.0f);  // top of the floor at y = 0
    EXPECT_FALSE(floor.castsShadow);
    EXPECT_FLOAT_EQ(s.objects[1].center.y - 0.5f * s.objects[1].size.y, 0.1f);  // floats 0.1 above
    EXPECT_FLOAT_EQ(s.objects[3].radius, 0.4f);
    EXPECT_FALSE(s.mirror.has_value());
}

TEST(Scene, BuiltInLabScene) {
    Scene s = loadScene("lab");
    EXPECT_EQ(s.light.position, glm::vec3(0, 0, 3));
    EXPECT_EQ(s.objects[0].kind, PrimitiveKind::Quad);
}

TEST(Scene, MinimalSceneParses) { EXPECT_EQ(errorOf(kMinimal), ""); }

TEST(Scene, MalformedFilesNameFilePathAndLine) {
    EXPECT_NE(errorOf("{\n  \"camera\": [1,\n").find("line 3"), std::string::npos);
    std::string e = errorOf(R"({"camera": {"eye": [0, 2, 4], "at": [0, 0, 0]}, "light": {"position": [2, 1, 0]},
      "objects": [{"type": "sphere", "center": [0, 0.5, 0], "radius": "big"}]})");
    EXPECT_NE(e.find("t.json: /objects/0/radius: must be a number"), std::string::npos) << e;
    e = errorOf(R"({"camera": {"eye": [0, 2, 4], "at": [0, 0, 0]}, "light": {"position": [2, 1, 0]},
      "objects": [{"type": "cone", "center": [0, 0.5, 0]}]})");
    EXPECT_NE(e.find("unknown primitive 'cone'"), std::string::npos) << e;
    e = errorOf(R"({"camera": {"eye": [0, 2, 4], "at": [0, 0, 0]}, "light": {"position": [0, 0.5, 0]},
      "objects": [{"type": "sphere", "center": [0, 0.5, 0], "radius": 0.5}]})");
    EXPECT_NE(e.find("inside this object"), std::string::npos) << e;
    e = errorOf(R"({"camera": {"eye": [0, 2, 4], "at": [0, 0, 0]}, "light": {"position": [2, 1, 0]}, "objects": []})");
    EXPECT_NE(e.find("/objects: is empty"), std::string::npos) << e;
    e = errorOf(R"({"camera": {"eye": [0, 2, 4], "at": [0, 0, 0]}, "light": {"position": [2, 1, 0], "target": [2, 1, 0]},
      "objects": [{"type": "box", "center": [0, 0, 0], "size": [1, 0, 1]}]})");
    EXPECT_NE(e.find("/light/target"), std::string::npos) << e;
    EXPECT_NE(errorOf(R"({"camera": {"eye": [0, 2, 4], "at": [0, 0, 0]}, "lite": {}})").find("/lite: unknown field"),
              std::string::npos);
}

TEST(Scene, UnknownBuiltInNameListsTheChoices) {
    try {
        loadScene("slidez");
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("slides"), std::string::npos);
    }
}

TEST(Tessellation, SphereSilhouetteWithinHalfAPixel) {
    Scene s = loadScene("slides");
    const Object& sphere = s.objects[3];
    for (int height : {240, 480, 1080}) {
        int n = sphereSegmentsForHalfPixel(sphere, s.camera, height);
        float distance = glm::length(sphere.center - s.camera.eye) - sphere.radius;
        float radiusPx = sphere.radius / distance * 0.5f * height / std::tan(glm::radians(s.camera.fovyDegrees) / 2);
        EXPECT_LE(radiusPx * (1 - std::cos(3.14159265f / n)), 0.5f) << height;
        EXPECT_GT(radiusPx * (1 - std::cos(3.14159265f / (n - 4))), 0.5f * 0.8f) << "not much finer than needed";
    }
}

TEST(Params, SetValidatesAndSuggests) {
    ParamSet p({ParamSpec::number("margin", 0.01, 0, 0.1, 0.001, "m"),
                ParamSpec::choice("filter", {"linear", "nearest"}, "f")});
    EXPECT_EQ(p.set("margin", "0.02"), "");
    EXPECT_DOUBLE_EQ(p.number("margin"), 0.02);
    EXPECT_NE(p.set("margin", "0.5").find("0 to 0.1"), std::string::npos);
    EXPECT_NE(p.set("margin", "nan").find("finite"), std::string::npos);
    EXPECT_NE(p.set("margn", "0.1").find("did you mean 'margin'"), std::string::npos);
    EXPECT_NE(p.set("filter", "cubic").find("linear, nearest"), std::string::npos);
    unsigned g = p.generation();
    p.step("filter", 1);
    EXPECT_EQ(p.choice("filter"), "nearest");
    EXPECT_GT(p.generation(), g);
}
