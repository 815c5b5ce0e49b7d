// Grading's displaced view: the casters and light move by an amount a seed decides, the same
// on every run, and never back to where they were.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/displace.h"
#include "scene/scene_json.h"

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
    }
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
    EXPECT_EQ(s.camera.eye, d.camera.eye);
}

TEST(Displace, CastersKeepTheirDistancesApartFromTheShift) {
    Scene s = slides();
    Displacement turnOnly = displacementFor(3);
    turnOnly.casterShift = {0, 0};
    Scene d = displacedScene(s, turnOnly);
    EXPECT_NEAR(glm::distance(s.objects[1].center, s.objects[2].center),
                glm::distance(d.objects[1].center, d.objects[2].center), 1e-5);
}

TEST(Displace, AQuadReceiverTurnsCastersAboutItsNormal) {
    Scene lab = loadScene("lab");
    EXPECT_EQ(receiverNormal(lab), glm::vec3(0, 0, 1));
    Scene d = displacedScene(lab, displacementFor(11));
    EXPECT_FLOAT_EQ(lab.objects[1].center.z, d.objects[1].center.z);  // stays above the plane
    EXPECT_FLOAT_EQ(lab.light.position.z, d.light.position.z);
}
