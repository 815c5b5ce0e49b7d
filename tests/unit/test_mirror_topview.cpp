// The geometry `render --figure` draws: the mirror seen from above, eye' and at', and the
// reflected camera's frustum through the mirror's ends.
#include <gtest/gtest.h>

#include "math/mirror_topview.h"
#include "metrics/mirror_figure.h"

using namespace sl;

namespace {

float cross2(const glm::vec2& a, const glm::vec2& b) {
    return a.x * b.y - a.y * b.x;
}

// Everything the construction promises, for any valid view.
void expectConstruction(const MirrorTopView& v) {
    ASSERT_TRUE(v.valid) << v.reason;
    glm::vec2 along = v.p2 - v.p1;
    // eye' is the eye mirrored: same distance to both ends, on the far side of the mirror's line.
    for (const glm::vec2& p : {v.p1, v.p2})
        EXPECT_NEAR(glm::length(v.eyePrime - p), glm::length(v.eye - p), 1e-4f);
    EXPECT_NEAR(glm::dot(v.eye - v.p1, v.normal), -glm::dot(v.eyePrime - v.p1, v.normal), 1e-4f);
    EXPECT_GT(glm::dot(v.eye - v.p1, v.normal), 0.0f) << "the normal faces the eye";
    // at' - eye' is perpendicular to p1 - p2 and not zero.
    EXPECT_NEAR(glm::dot(v.atPrime - v.eyePrime, along), 0.0f, 1e-4f);
    EXPECT_GT(glm::length(v.atPrime - v.eyePrime), 0.5f);
    // near' is the depth of the mirror from eye', far' deeper.
    EXPECT_NEAR(glm::dot(v.p1 - v.eyePrime, v.normal), v.zNear, 1e-4f);
    EXPECT_NEAR(glm::dot(v.p2 - v.eyePrime, v.normal), v.zNear, 1e-4f);
    EXPECT_GT(v.zFar, v.zNear);
    // The frustum's side lines start at eye', pass through the mirror's ends and stop at far'.
    EXPECT_NEAR(cross2(glm::normalize(v.p1 - v.eyePrime), glm::normalize(v.far1 - v.eyePrime)),
                0.0f, 1e-5f);
    EXPECT_NEAR(cross2(glm::normalize(v.p2 - v.eyePrime), glm::normalize(v.far2 - v.eyePrime)),
                0.0f, 1e-5f);
    EXPECT_GT(glm::dot(v.far1 - v.p1, v.p1 - v.eyePrime), 0.0f) << "beyond the mirror, not before";
    EXPECT_NEAR(glm::dot(v.far1 - v.eyePrime, v.normal), v.zFar, 1e-3f);
    EXPECT_NEAR(glm::dot(v.far2 - v.eyePrime, v.normal), v.zFar, 1e-3f);
    // The window at near' is as wide as the mirror.
    EXPECT_NEAR(v.right - v.left, glm::length(along), 1e-4f);
}

}  // namespace

TEST(MirrorTopView, PracticeWithAMirrorAlongX) {
    MirrorTopView v = practiceTopView({-1, 0}, {1, 0}, {0.5f, 2}, {0, 0});
    expectConstruction(v);
    EXPECT_NEAR(v.eyePrime.x, 0.5f, 1e-5f);
    EXPECT_NEAR(v.eyePrime.y, -2.0f, 1e-5f);
    EXPECT_NEAR(v.atPrime.x, 0.5f, 1e-5f);
    EXPECT_NEAR(v.atPrime.y, -1.0f, 1e-5f);
    EXPECT_NEAR(v.zNear, 2.0f, 1e-5f);
    // eye' looks along +z, so its own x runs along world -x: p2 (x = 1) is its left edge, 0.5 to
    // the left of the axis; p1 (x = -1) is 1.5 to the right. The left-right flip, in numbers.
    EXPECT_NEAR(v.left, -0.5f, 1e-5f);
    EXPECT_NEAR(v.right, 1.5f, 1e-5f);
    // The default reach: the farther of eye and at from the middle (|(0.5, 2)| here).
    EXPECT_NEAR(v.zFar, 2.0f + std::sqrt(4.25f), 1e-4f);
}

TEST(MirrorTopView, PracticeWithATiltedMirrorAndTheEyeOnEitherSide) {
    expectConstruction(practiceTopView({0, 0}, {2, 1}, {2, 3}, {1, 0.5f}));
    expectConstruction(practiceTopView({0, 0}, {2, 1}, {1, -3}, {1, 0.5f}, 5.0f));
    MirrorTopView far = practiceTopView({0, 0}, {2, 1}, {1, -3}, {1, 0.5f}, 5.0f);
    EXPECT_NEAR(far.zFar - far.zNear, 5.0f, 1e-4f);
}

TEST(MirrorTopView, EyePrimeIsTheSlidesConstructionFromEitherEnd) {
    glm::vec2 p1(0, 0), p2(2, 1), eye(2, 3);
    MirrorTopView v = practiceTopView(p1, p2, eye, {1, 0.5f});
    ASSERT_TRUE(v.valid);
    glm::vec3 n(v.normal.x, 0.0f, v.normal.y), eye3(eye.x, 0.0f, eye.y);
    for (const glm::vec2& p : {p1, p2}) {
        glm::vec3 slides = reflectedEyeSlides(eye3, glm::vec3(p.x, 0.0f, p.y), n);
        EXPECT_NEAR(slides.x, v.eyePrime.x, 1e-4f);
        EXPECT_NEAR(slides.z, v.eyePrime.y, 1e-4f);
    }
}

TEST(MirrorTopView, ImpossibleSetUpsSayWhy) {
    MirrorTopView same = practiceTopView({1, 1}, {1, 1}, {0, 3}, {0, 0});
    EXPECT_FALSE(same.valid);
    EXPECT_NE(same.reason.find("no width"), std::string::npos) << same.reason;
    MirrorTopView onLine = practiceTopView({-1, 0}, {1, 0}, {3, 0}, {0, 1});
    EXPECT_FALSE(onLine.valid);
    EXPECT_NE(onLine.reason.find("plane"), std::string::npos) << onLine.reason;
    MirrorTopView nan = practiceTopView({-1, 0}, {1, 0}, {NAN, 1}, {0, 1});
    EXPECT_FALSE(nan.valid);
    // The script still draws what there is and says why there is no reflected camera.
    std::string script = mirrorFigureScript(onLine, "/tmp/x.png");
    EXPECT_NE(script.find(onLine.reason), std::string::npos);
    EXPECT_EQ(script.find("eye'\""), std::string::npos);
}

TEST(MirrorTopView, SceneMirrorFromTheReflectedCamera) {
    Mirror m;  // the mirror scene's: z = -1.4 facing +z, 3 wide
    m.center = {0.0f, 0.55f, -1.4f};
    m.width = 3.0f;
    m.height = 1.1f;
    glm::vec3 eye(-0.6f, 2.6f, 3.4f), at(-0.25f, 0.0f, 0.0f);
    MirrorCamera camera = mirrorCamera(m, eye, 3.0f);
    MirrorTopView v = mirrorTopView(m, eye, at, camera);
    expectConstruction(v);
    EXPECT_NEAR(v.p1.x, -1.5f, 1e-5f);  // the left end seen from the front
    EXPECT_NEAR(v.p2.x, 1.5f, 1e-5f);
    EXPECT_NEAR(v.eyePrime.y, -6.2f, 1e-4f);
    EXPECT_NEAR(v.zFar, camera.zFar, 1e-6f);
    EXPECT_FALSE(
        mirrorTopView(m, glm::vec3(0, 1, -3), at, mirrorCamera(m, {0, 1, -3}, 3.0f)).valid);
}

TEST(MirrorTopView, ScriptDrawsEveryPieceAndLabel) {
    MirrorTopView v = practiceTopView({-1, 0}, {1, 0}, {0.5f, 2}, {0, 0});
    std::string script = mirrorFigureScript(v, "/tmp/it's.png");
    EXPECT_NE(script.find("set output '/tmp/it''s.png'"), std::string::npos);
    for (const char* label : {"\"p1\"", "\"p2\"", "\"eye\"", "\"at\"", "\"eye'\"", "\"at'\""})
        EXPECT_NE(script.find(std::string("set label ") + label), std::string::npos) << label;
    for (const char* block : {"$mirror", "$rays", "$frustum", "$clipped", "$viewPrime"})
        EXPECT_NE(script.find(std::string(block) + " << EOD"), std::string::npos) << block;
    // The frustum block runs from the mirror's ends to the far points.
    char far1[64];
    std::snprintf(far1, sizeof far1, "%.4g %.4g", v.far1.x, v.far1.y);
    EXPECT_NE(script.find(far1), std::string::npos) << far1;
    EXPECT_NE(describeTopView(v).find("near' 2"), std::string::npos) << describeTopView(v);
}
