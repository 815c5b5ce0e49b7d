// Grading's displaced view: the casters, the light and the camera move by an amount a seed
// decides, the same on every run, and never back to where they were.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "math/camera.h"
#include "reference/raytracer.h"
#include "scene/displace.h"
#include "scene/scene_json.h"
#include "stages/expectations.h"

using namespace sl;

namespace {

Scene slides() {
    return loadScene("slides");
}

}  // namespace

TEST(Displace, TheSameSeedGivesTheSameViewAndAnotherSeedAnother) {
    Displacement a = displacementFor(42), b = displacementFor(42), c = displacementFor(43);
    EXPECT_EQ(a.casterTurnDegrees, b.casterTurnDegrees);
    EXPECT_EQ(a.casterShift, b.casterShift);
    EXPECT_EQ(a.lightTurnDegrees, b.lightTurnDegrees);
    EXPECT_NE(a.casterTurnDegrees, c.casterTurnDegrees);
}

TEST(Displace, EverySeedStaysInItsRanges) {
    for (std::uint64_t seed = 0; seed < 2000; ++seed) {
        Displacement d = displacementFor(seed);
        EXPECT_GE(d.casterTurnDegrees, 40.0f);
        EXPECT_LE(d.casterTurnDegrees, 320.0f);
        EXPECT_LE(std::abs(d.casterShift.x), 0.15f);
        EXPECT_LE(std::abs(d.casterShift.y), 0.15f);
        EXPECT_GE(std::abs(d.lightTurnDegrees), 10.0f);
        EXPECT_LE(std::abs(d.lightTurnDegrees), 20.0f);
        EXPECT_GE(d.cameraTurnDegrees, 50.0f);
        EXPECT_LE(d.cameraTurnDegrees, 310.0f);
        EXPECT_LE(std::abs(d.cameraElevationDegrees), 10.0f);
        EXPECT_GE(d.cameraDistanceScale, 0.85f);
        EXPECT_LE(d.cameraDistanceScale, 1.15f);
    }
}

// The camera's draws come after the casters' and the light's: a seed moves those as it did
// before the camera moved (seed 42's numbers from the build that kept the camera).
TEST(Displace, TheCameraDrawsLeaveTheCastersAndLightsOfASeedAsTheyWere) {
    Displacement d = displacementFor(42);
    std::mt19937_64 g(42);
    auto unit = [&] { return double(g() >> 11) * (1.0 / 9007199254740992.0); };
    EXPECT_FLOAT_EQ(d.casterTurnDegrees, float(40.0 + 280.0 * unit()));
    EXPECT_FLOAT_EQ(d.casterShift.x, float(0.3 * unit() - 0.15));
}

TEST(Displace, CastersAndLightMoveReceiversStay) {
    Scene s = slides();
    Scene d = displacedScene(s, displacementFor(7));
    ASSERT_EQ(s.objects.size(), d.objects.size());
    EXPECT_EQ(receiverNormal(s), glm::vec3(0, 1, 0));  // the floor box's thinnest side
    for (std::size_t i = 0; i < s.objects.size(); ++i) {
        const Object &before = s.objects[i], &after = d.objects[i];
        if (!before.castsShadow) {
            EXPECT_EQ(before.center, after.center) << before.name;
            continue;
        }
        EXPECT_GT(glm::distance(before.center, after.center), 0.05f) << before.name;
        EXPECT_FLOAT_EQ(before.center.y, after.center.y) << before.name;  // turned about +Y
    }
    // The light turns about its target: same height, same distance, elsewhere.
    EXPECT_FLOAT_EQ(s.light.position.y, d.light.position.y);
    EXPECT_NEAR(glm::distance(s.light.position, s.light.target),
                glm::distance(d.light.position, d.light.target), 1e-5);
    EXPECT_GT(glm::distance(s.light.position, d.light.position), 0.3f);
    EXPECT_GT(glm::distance(s.camera.eye, d.camera.eye), 0.5f) << "the camera moves too";
}

namespace {

float elevationDegrees(const Camera& c, const glm::vec3& normal) {
    glm::vec3 offset = c.eye - c.at;
    return glm::degrees(std::asin(glm::dot(offset, normal) / glm::length(offset)));
}

}  // namespace

// The camera a shader might recognise (issue 25: a margin used only when eyePosition is one of
// the graded cameras) is never one of them: over 2000 seeds the displaced eye keeps away from
// every fixed view's eye, stays above the floor at 15-75 degrees, 0.85-1.15 times as far from
// its target, and the target moves with the casters.
TEST(Displace, TheCameraMovesAboveTheReceiverAwayFromEveryGradedEye) {
    Scene s = slides();
    std::vector<glm::vec3> graded;
    for (const GradingView& v : gradingViews("slides"))
        graded.push_back(v.eye.value_or(s.camera.eye));
    ASSERT_EQ(graded.size(), 5u);
    const float distance = glm::distance(s.camera.eye, s.camera.at);
    float nearest = 1e9f;
    for (std::uint64_t seed = 0; seed < 2000; ++seed) {
        Scene d = displacedScene(s, displacementFor(seed));
        const Camera& c = d.camera;
        for (const glm::vec3& eye : graded) nearest = std::min(nearest, glm::distance(eye, c.eye));
        float e = elevationDegrees(c, {0, 1, 0});
        EXPECT_GE(e, 15.0f - 1e-3f) << seed;
        EXPECT_LE(e, 75.0f + 1e-3f) << seed;
        EXPECT_GT(c.eye.y, 1.0f) << seed << ": the eye must stay well above the floor";
        float r = glm::distance(c.eye, c.at) / distance;
        EXPECT_GE(r, 0.85f - 1e-4f) << seed;
        EXPECT_LE(r, 1.15f + 1e-4f) << seed;
        EXPECT_NEAR(c.at.y, s.camera.at.y, 1e-5f) << seed;  // the target turns with the casters
    }
    // A shader comparing eyePosition with the graded eyes (to any tolerance under this) cannot
    // take the displaced camera for one of them. Measured: 0.20 over these 2000 seeds (seed 173).
    EXPECT_GT(nearest, 0.1f);
}

// The displaced picture is a sensible view (traced exactly, 160x120): every caster's centre in
// frame, the floor filling a good part of it, and real shadow on screen, for each of 200 seeds.
// Measured over those seeds: the floor at least 17.8 % of the picture and at least 2.7 % truly
// shadowed (the lecture's own camera: 32.6 % and 12.2 %); before the camera kept off the
// light's side, 11 of the 200 fell under 2 % shadowed.
TEST(Displace, EveryDisplacedViewShowsTheCastersAndTheirShadows) {
    Scene s = slides();
    for (std::uint64_t seed = 0; seed < 200; ++seed) {
        Scene d = displacedScene(s, displacementFor(seed));
        ReferenceImage ref = traceReference(d, d.camera, d.light.position, 160, 120);
        int floor = 0, shadow = 0;
        for (const ReferencePixel& p : ref.pixels) {
            floor += p.objectId == objectId(0);
            shadow += p.objectId > 0 && p.facesLight && p.blocked;
        }
        for (const Object& o : d.objects) {
            glm::vec2 px;
            EXPECT_TRUE(o.castsShadow ? projectToPixel(d.camera, 160, 120, o.center, px) &&
                                            px.x >= 0 && px.y >= 0 && px.x < 160 && px.y < 120
                                      : true)
                << "seed " << seed << ": " << o.name << " out of frame";
        }
        EXPECT_GT(floor, 160 * 120 * 15 / 100) << "seed " << seed << ": the floor under 15 % of it";
        EXPECT_GT(shadow, 160 * 120 / 50) << "seed " << seed << ": under 2 % of it in shadow";
    }
}
