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

TEST(Scene, MinimalSceneParses) {
    EXPECT_EQ(errorOf(kMinimal), "");
}

TEST(Scene, MalformedFilesNameFilePathAndLine) {
    EXPECT_NE(errorOf("{\n  \"camera\": [1,\n").find("line 3"), std::string::npos);
    std::string e =
        errorOf(R"({"camera": {"eye": [0, 2, 4], "at": [0, 0, 0]}, "light": {"position": [2, 1, 0]},
      "objects": [{"type": "sphere", "center": [0, 0.5, 0], "radius": "big"}]})");
    EXPECT_NE(e.find("t.json: /objects/0/radius: must be a number"), std::string::npos) << e;
    e = errorOf(R"({"camera": {"eye": [0, 2, 4], "at": [0, 0, 0]}, "light": {"position": [2, 1, 0]},
      "objects": [{"type": "cone", "center": [0, 0.5, 0]}]})");
    EXPECT_NE(e.find("unknown primitive 'cone'"), std::string::npos) << e;
    e = errorOf(
        R"({"camera": {"eye": [0, 2, 4], "at": [0, 0, 0]}, "light": {"position": [0, 0.5, 0]},
      "objects": [{"type": "sphere", "center": [0, 0.5, 0], "radius": 0.5}]})");
    EXPECT_NE(e.find("inside this object"), std::string::npos) << e;
    e = errorOf(
        R"({"camera": {"eye": [0, 2, 4], "at": [0, 0, 0]}, "light": {"position": [2, 1, 0]}, "objects": []})");
    EXPECT_NE(e.find("/objects: is empty"), std::string::npos) << e;
    e = errorOf(
        R"({"camera": {"eye": [0, 2, 4], "at": [0, 0, 0]}, "light": {"position": [2, 1, 0], "target": [2, 1, 0]},
      "objects": [{"type": "box", "center": [0, 0, 0], "size": [1, 0, 1]}]})");
    EXPECT_NE(e.find("/light/target"), std::string::npos) << e;
    EXPECT_NE(errorOf(R"({"camera": {"eye": [0, 2, 4], "at": [0, 0, 0]}, "lite": {}})")
                  .find("/lite: unknown field"),
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
        float radiusPx = sphere.radius / distance * 0.5f * height /
                         std::tan(glm::radians(s.camera.fovyDegrees) / 2);
        EXPECT_LE(radiusPx * (1 - std::cos(3.14159265f / n)), 0.5f) << height;
        EXPECT_GT(radiusPx * (1 - std::cos(3.14159265f / (n - 4))), 0.5f * 0.8f)
            << "not much finer than needed";
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

TEST(Tessellation, ManyLargeSpheresStayWithinTheVertexBudget) {
    // 4000 spheres that each fill most of the view would ask for 100+ segments (5000+ vertices)
    // apiece, 20M vertices in all (and 512 segments, 2 GB, closer up): the budget coarsens all.
    Scene s = loadScene("slides");
    s.objects.clear();
    Object sphere;
    sphere.kind = PrimitiveKind::Sphere;
    sphere.radius = 5.0f;
    for (int k = 0; k < 4000; ++k) {
        sphere.center = glm::vec3(0.001f * k, 0, 0);
        s.objects.push_back(sphere);
    }
    s.camera.eye = glm::vec3(0, 8, 8);
    ASSERT_GE(sphereSegmentsForHalfPixel(s.objects[0], s.camera, 1080), 100);
    SceneMesh mesh = tessellate(s, s.camera, 1080);
    EXPECT_LE(mesh.vertices.size(), kSphereVertexBudget + 100);
    ASSERT_EQ(mesh.sphereSegments.size(), s.objects.size());
    for (int n : mesh.sphereSegments) EXPECT_GE(n, 12);
}

TEST(Tessellation, FewSpheresKeepTheirHalfPixelSegments) {
    Scene s = loadScene("slides");
    SceneMesh mesh = tessellate(s, s.camera, 480);
    EXPECT_EQ(mesh.sphereSegments[3], sphereSegmentsForHalfPixel(s.objects[3], s.camera, 480));
}

TEST(Scene, NumberBeyondDoubleIsASceneError) {
    // nlohmann throws out_of_range (not parse_error) for 1e999; found by the fuzzer.
    std::string e = errorOf(R"({"camera": {"eye": [0, 1e999, 4], "at": [0, 0, 0]}})");
    EXPECT_NE(e.find("t.json: not valid JSON: number overflow parsing '1e999'"), std::string::npos)
        << e;
}

TEST(Scene, MirrorOfZeroSizeIsRejected) {
    std::string e = errorOf(R"({"camera": {"eye": [0, 2, 4], "at": [0, 0, 0]},
      "light": {"position": [2, 1, 0]},
      "objects": [{"type": "sphere", "center": [0, 0.5, 0], "radius": 0.5}],
      "mirror": {"center": [0, 0.5, -1], "width": 0, "height": 1}})");
    EXPECT_NE(e.find("/mirror/width: must be a number in"), std::string::npos) << e;
}
