#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "math/camera.h"
#include "math/mirror_math.h"

using namespace sl;

namespace {

void expectNear(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

glm::vec3 toNdc(const glm::mat4& m, const glm::vec3& p) {
    glm::vec4 clip = m * glm::vec4(p, 1.0f);
    return glm::vec3(clip) / clip.w;
}

// The slides' practice set-up: a vertical mirror drawn in a top view as the segment p1 -> p2
// (both at the height of its centre), facing the eye.
Mirror mirrorFromTopView(const glm::vec3& p1, const glm::vec3& p2, float height,
                         const glm::vec3& eye) {
    Mirror m;
    m.center = 0.5f * (p1 + p2);
    glm::vec3 along = p2 - p1;
    m.width = glm::length(along);
    m.height = height;
    m.up = {0, 1, 0};
    m.normal = glm::normalize(glm::vec3(along.z, 0, -along.x));
    if (glm::dot(eye - m.center, m.normal) < 0.0f) m.normal = -m.normal;
    return m;
}

// A deliberately untidy mirror: tilted, non-unit normal, up not perpendicular to it.
Mirror untidyMirror() {
    Mirror m;
    m.center = {0.3f, 1.2f, -1.5f};
    m.normal = {0.6f, 0.3f, 2.0f};
    m.up = {0.1f, 2.0f, 0.4f};
    m.width = 1.6f;
    m.height = 0.9f;
    return m;
}

struct Configuration {
    Mirror mirror;
    glm::vec3 eye;
};

std::vector<Configuration> configurations() {
    Mirror wall;  // the default mirror: at the origin facing +z
    wall.width = 2.0f;
    wall.height = 1.5f;
    return {
        {mirrorFromTopView({-1, 0, -2}, {1, 0, -2}, 2.0f, {0.5f, 0, 1}), {0.5f, 0, 1}},
        {mirrorFromTopView({1, 0.5f, 0}, {0, 0.5f, 1}, 1.0f, {0, 0, 0}), {0, 0, 0}},
        {mirrorFromTopView({-2, 1, -1}, {-1, 1, -3}, 1.2f, {1, 1.7f, 2}), {1, 1.7f, 2}},
        {wall, {3, 0.4f, 0.2f}},  // very oblique view
        {untidyMirror(), {-0.5f, 1.6f, 2.5f}},
    };
}

// The mirror's corners with its frame made orthonormal, in mirrorCorners' order.
MirrorCorners orthonormalCorners(Mirror m) {
    m.normal = glm::normalize(m.normal);
    m.up = glm::normalize(m.up - glm::dot(m.up, m.normal) * m.normal);
    return mirrorCorners(m);
}

template <class T>
bool allFinite(const T& v, int n) {
    for (int i = 0; i < n; ++i)
        if (!std::isfinite(v[i])) return false;
    return true;
}

bool allFinite(const MirrorCamera& c) {
    bool ok = allFinite(c.eye, 3) && allFinite(c.at, 3) && allFinite(c.up, 3);
    for (float f : {c.left, c.right, c.bottom, c.top, c.zNear, c.zFar}) ok = ok && std::isfinite(f);
    for (int i = 0; i < 4; ++i)
        ok = ok && allFinite(c.view[i], 4) && allFinite(c.projection[i], 4) &&
             allFinite(c.cornerUv[i], 2);
    return ok;
}

}  // namespace

// ---- reflecting points --------------------------------------------------------------------------

TEST(MirrorMath, ReflectPointMirrorsAcrossThePlane) {
    expectNear(reflectPoint({1, 2, 3}, {0, 0, 0}, {0, 0, 1}), {1, 2, -3});
    expectNear(reflectPoint({1, 2, 3}, {5, 7, 1}, {0, 0, 4}), {1, 2, -1});  // normal of any length
    expectNear(reflectPoint({5, 7, 1}, {5, 7, 1}, {1, 1, 0}), {5, 7, 1});   // on the plane
    glm::vec3 p(0.3f, -2, 1.7f), q(1, 1, 1), n(1, -2, 0.5f);
    expectNear(reflectPoint(reflectPoint(p, q, n), q, n), p);
}

TEST(MirrorMath, ReflectionMatrixIsAnInvolutionWithDeterminantMinusOne) {
    glm::vec3 q(0.3f, 1.2f, -1.5f), n(0.6f, 0.3f, 2.0f);
    glm::mat4 m = reflectionMatrix(q, n);
    glm::mat4 mm = m * m;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(mm[c][r], c == r ? 1.0f : 0.0f, 1e-5);
    EXPECT_NEAR(glm::determinant(m), -1.0f, 1e-5);
    // Points of the plane stay put; any point goes where reflectPoint sends it.
    glm::vec3 inPlane1 = glm::normalize(glm::cross(n, glm::vec3(0, 1, 0)));
    glm::vec3 inPlane2 = glm::normalize(glm::cross(n, inPlane1));
    for (float s : {-1.0f, 0.0f, 2.5f})
        for (float t : {-3.0f, 0.5f}) {
            glm::vec3 p = q + s * inPlane1 + t * inPlane2;
            expectNear(glm::vec3(m * glm::vec4(p, 1)), p);
        }
    for (glm::vec3 p : {glm::vec3(1, 2, 3), glm::vec3(-4, 0, 0.5f)})
        expectNear(glm::vec3(m * glm::vec4(p, 1)), reflectPoint(p, q, n));
    // Directions (w = 0) reflect without the translation.
    expectNear(glm::vec3(m * glm::vec4(glm::normalize(n), 0)), -glm::normalize(n));
}

TEST(MirrorMath, SlidesConstructionOfTheReflectedEyeEqualsReflectPoint) {
    for (const Configuration& c : configurations()) {
        glm::vec3 expected = reflectPoint(c.eye, c.mirror.center, c.mirror.normal);
        expectNear(reflectedEyeSlides(c.eye, c.mirror.center, c.mirror.normal), expected);
        // Any point of the mirror plane gives the same eye', not only the centre.
        for (const glm::vec3& corner : orthonormalCorners(c.mirror).corner)
            expectNear(reflectedEyeSlides(c.eye, corner, c.mirror.normal), expected, 1e-4f);
    }
    // The eye on the point itself is its own image rather than NaN.
    EXPECT_EQ(reflectedEyeSlides({1, 2, 3}, {1, 2, 3}, {0, 0, 1}), glm::vec3(1, 2, 3));
}

// ---- the slides' practice exercise, worked
// -------------------------------------------------------

TEST(MirrorMath, PracticeExerciseMirrorAlongXSeenFromInFront) {
    // Top view: p1 = (-1, 0, -2), p2 = (1, 0, -2), mirror 2 high; eye (0.5, 0, 1) looks at
    // at = (0, 0, -2), the mirror's centre. at does not enter: the reflected camera always looks
    // perpendicular to the mirror, whatever the viewer looks at.
    const glm::vec3 eye(0.5f, 0, 1), at(0, 0, -2);
    Mirror m = mirrorFromTopView({-1, 0, -2}, {1, 0, -2}, 2.0f, eye);
    EXPECT_EQ(m.normal, glm::vec3(0, 0, 1));
    MirrorCamera c = mirrorCamera(m, eye, 10.0f);
    ASSERT_TRUE(c.valid) << c.reason;
    expectNear(c.eye, {0.5f, 0, -5});  // 3 in front -> 3 behind
    expectNear(c.at, {0.5f, 0, -4});
    expectNear(c.up, {0, 1, 0});
    // Looking along +z the camera's right is world -x: world x = 1 is at view x = -0.5.
    EXPECT_NEAR(c.left, -0.5f, 1e-5);
    EXPECT_NEAR(c.right, 1.5f, 1e-5);
    EXPECT_NEAR(c.bottom, -1.0f, 1e-5);
    EXPECT_NEAR(c.top, 1.0f, 1e-5);
    EXPECT_NEAR(c.zNear, 3.0f, 1e-5);
    EXPECT_NEAR(c.zFar, 13.0f, 1e-5);
    Camera viewer;
    viewer.eye = eye;
    viewer.at = at;
    glm::ivec2 footprint = mirrorFootprintPixels(m, viewer, 640, 480);
    EXPECT_GT(footprint.x, 0);
    EXPECT_GT(footprint.y, 0);
}

TEST(MirrorMath, PracticeExerciseDiagonalMirror) {
    // Top view: p1 = (1, 0.5, 0), p2 = (0, 0.5, 1), the eye at the origin: the plane x + z = 1
    // reflects the origin to (1, 0, 1), straight behind the mirror's centre.
    const glm::vec3 eye(0, 0, 0);
    Mirror m = mirrorFromTopView({1, 0.5f, 0}, {0, 0.5f, 1}, 1.0f, eye);
    MirrorCamera c = mirrorCamera(m, eye, 5.0f);
    ASSERT_TRUE(c.valid) << c.reason;
    const float h = std::sqrt(0.5f);
    expectNear(c.eye, {1, 0, 1});
    expectNear(c.at, {1 - h, 0, 1 - h});
    EXPECT_NEAR(c.zNear, h, 1e-5);  // distance from the origin to x + z = 1
    EXPECT_NEAR(c.left, -h, 1e-5);  // width sqrt(2), centred on the axis
    EXPECT_NEAR(c.right, h, 1e-5);
    EXPECT_NEAR(c.bottom, 0.0f, 1e-5);  // the mirror spans y 0..1, the eye' is at y = 0
    EXPECT_NEAR(c.top, 1.0f, 1e-5);
}

// ---- the mirror camera's frustum
// -----------------------------------------------------------------

TEST(MirrorMath, MirrorCornersAreTheNearWindowOfTheReflectedCamera) {
    for (const Configuration& config : configurations()) {
        MirrorCamera c = mirrorCamera(config.mirror, config.eye, 8.0f);
        ASSERT_TRUE(c.valid) << c.reason;
        MirrorCorners corners = orthonormalCorners(config.mirror);
        glm::mat4 viewProjection = c.projection * c.view;
        bool seen[2][2] = {{false, false}, {false, false}};
        for (const glm::vec3& corner : corners.corner) {
            glm::vec3 v = glm::vec3(c.view * glm::vec4(corner, 1));
            EXPECT_NEAR(-v.z, c.zNear, 1e-4);
            glm::vec3 ndc = toNdc(viewProjection, corner);
            EXPECT_NEAR(std::abs(ndc.x), 1.0f, 1e-5);
            EXPECT_NEAR(std::abs(ndc.y), 1.0f, 1e-5);
            EXPECT_NEAR(ndc.z, -1.0f, 1e-5);
            seen[ndc.x > 0][ndc.y > 0] = true;
        }
        EXPECT_TRUE(seen[0][0] && seen[0][1] && seen[1][0] && seen[1][1]);
        EXPECT_NEAR(c.zFar - c.zNear, 8.0f, 1e-4);
        expectNear(c.at - c.eye, glm::normalize(config.mirror.normal));
        EXPECT_NEAR(glm::dot(c.up, c.at - c.eye), 0.0f, 1e-6);
    }
}

TEST(MirrorMath, CornerUvFlipsLeftAndRight) {
    for (const Configuration& config : configurations()) {
        MirrorCamera c = mirrorCamera(config.mirror, config.eye, 8.0f);
        ASSERT_TRUE(c.valid) << c.reason;
        // bottom-left, bottom-right, top-right, top-left as seen from the front
        const glm::vec2 expected[4] = {{1, 0}, {0, 0}, {0, 1}, {1, 1}};
        for (int i = 0; i < 4; ++i) {
            EXPECT_NEAR(c.cornerUv[i].x, expected[i].x, 1e-5) << "corner " << i;
            EXPECT_NEAR(c.cornerUv[i].y, expected[i].y, 1e-5) << "corner " << i;
        }
    }
}

TEST(MirrorMath, TextureLookupOnTheMirrorShowsWhatTheViewerSeesReflected) {
    // A scene point P appears in the mirror where the line eye' -> P crosses the mirror. The
    // mirror camera's image of P must sit at that crossing's texture coordinate, interpolated
    // from cornerUv the way the mirror quad is textured.
    for (const Configuration& config : configurations()) {
        MirrorCamera c = mirrorCamera(config.mirror, config.eye, 20.0f);
        ASSERT_TRUE(c.valid) << c.reason;
        MirrorCorners k = orthonormalCorners(config.mirror);
        glm::vec3 n = glm::normalize(config.mirror.normal);
        glm::vec3 across = k.corner[1] - k.corner[0], upward = k.corner[3] - k.corner[0];
        for (glm::vec2 st : {glm::vec2(0.5f), glm::vec2(0.2f, 0.7f), glm::vec2(0.9f, 0.1f)}) {
            glm::vec3 onMirror = k.corner[0] + st.x * across + st.y * upward;
            glm::vec3 p = c.eye + 1.7f * (onMirror - c.eye);  // in front of the mirror
            ASSERT_GT(glm::dot(p - config.mirror.center, n), 0.0f);
            glm::vec3 ndc = toNdc(c.projection * c.view, p);
            glm::vec2 uvOfP = 0.5f * (glm::vec2(ndc) + 1.0f);
            glm::vec2 uvOnQuad = c.cornerUv[0] + st.x * (c.cornerUv[1] - c.cornerUv[0]) +
                                 st.y * (c.cornerUv[3] - c.cornerUv[0]);
            EXPECT_NEAR(uvOfP.x, uvOnQuad.x, 1e-4);
            EXPECT_NEAR(uvOfP.y, uvOnQuad.y, 1e-4);
            EXPECT_GT(ndc.z, -1.0f);
            EXPECT_LT(ndc.z, 1.0f);
        }
    }
}

TEST(MirrorMath, UntidyNormalAndUpGiveTheSameCameraAsTidyOnes) {
    Mirror untidy = untidyMirror();
    Mirror tidy = untidy;
    tidy.normal = glm::normalize(untidy.normal);
    tidy.up = glm::normalize(untidy.up - glm::dot(untidy.up, tidy.normal) * tidy.normal);
    glm::vec3 eye(-0.5f, 1.6f, 2.5f);
    MirrorCamera a = mirrorCamera(untidy, eye, 6.0f), b = mirrorCamera(tidy, eye, 6.0f);
    ASSERT_TRUE(a.valid && b.valid);
    expectNear(a.eye, b.eye);
    expectNear(a.up, b.up);
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row)
            EXPECT_NEAR(a.projection[col][row], b.projection[col][row], 1e-5);
    EXPECT_NEAR(glm::length(a.up), 1.0f, 1e-6);
}

TEST(MirrorMath, DegenerateInputsGiveAnInvalidCameraWithAReasonAndNoNaN) {
    Mirror wall;
    const float nan = std::nanf("");
    struct Case {
        const char* what;
        Mirror mirror;
        glm::vec3 eye;
        float radius;
        const char* reasonWord;
    };
    Mirror zeroWidth = wall, zeroHeight = wall, nanNormal = wall, upAlongNormal = wall,
           zeroNormal = wall, infCenter = wall;
    zeroWidth.width = 0.0f;
    zeroHeight.height = 0.0f;
    nanNormal.normal.x = nan;
    upAlongNormal.up = {0, 0, -3};
    zeroNormal.normal = glm::vec3(0);
    infCenter.center.y = INFINITY;
    const Case cases[] = {
        {"behind", wall, {0.2f, 0.1f, -2}, 5, "behind"},
        {"on the plane", wall, {3, 0, 0}, 5, "plane"},
        {"zero width", zeroWidth, {0, 0, 2}, 5, "width"},
        {"zero height", zeroHeight, {0, 0, 2}, 5, "height"},
        {"NaN eye", wall, {nan, 0, 2}, 5, "finite"},
        {"NaN normal", nanNormal, {0, 0, 2}, 5, "finite"},
        {"infinite centre", infCenter, {0, 0, 2}, 5, "finite"},
        {"zero normal", zeroNormal, {0, 0, 2}, 5, "normal"},
        {"up along normal", upAlongNormal, {0, 0, 2}, 5, "parallel"},
        {"zero radius", wall, {0, 0, 2}, 0, "radius"},
        {"NaN radius", wall, {0, 0, 2}, nan, "radius"},
    };
    for (const Case& k : cases) {
        MirrorCamera c = mirrorCamera(k.mirror, k.eye, k.radius);
        EXPECT_FALSE(c.valid) << k.what;
        EXPECT_NE(c.reason.find(k.reasonWord), std::string::npos) << k.what << ": " << c.reason;
        EXPECT_TRUE(allFinite(c)) << k.what;
    }
    // Just in front is fine, if extreme.
    MirrorCamera close = mirrorCamera(wall, {0, 0, 1e-3f}, 5);
    EXPECT_TRUE(close.valid) << close.reason;
    EXPECT_TRUE(allFinite(close));
}

// ---- Lengyel's oblique near plane ---------------------------------------------------------------

namespace {

// A view-space plane through `point` whose normal points away from the camera.
glm::vec4 planeThrough(const glm::vec3& point, const glm::vec3& awayFromCamera) {
    glm::vec3 n = glm::normalize(awayFromCamera);
    return {n, -glm::dot(n, point)};
}

float ndcZ(const glm::mat4& projection, const glm::vec3& viewPoint) {
    glm::vec4 clip = projection * glm::vec4(viewPoint, 1.0f);
    return clip.z / clip.w;
}

}  // namespace

TEST(MirrorMath, ObliqueNearPlaneMapsThePlaneToNdcMinusOne) {
    glm::mat4 p = glm::perspective(glm::radians(60.0f), 1.3f, 0.1f, 50.0f);
    glm::vec4 plane = planeThrough({0, 0, -5}, {0.3f, 0.2f, -1});
    glm::mat4 oblique = obliqueNearPlane(p, plane);
    glm::vec3 n(plane), a = glm::normalize(glm::cross(n, glm::vec3(0, 1, 0))), b = glm::cross(n, a);
    for (float s : {-1.0f, 0.0f, 1.5f})
        for (float t : {-1.0f, 0.7f}) {
            glm::vec3 onPlane = glm::vec3(0, 0, -5) + s * a + t * b;
            EXPECT_NEAR(ndcZ(oblique, onPlane), -1.0f, 1e-4) << s << " " << t;
        }
    // x, y and w are untouched: the image is the same, only depth changes.
    for (int col = 0; col < 4; ++col)
        for (int row : {0, 1, 3}) EXPECT_EQ(oblique[col][row], p[col][row]);
}

TEST(MirrorMath, ObliqueNearPlaneClipsWhatIsBetweenTheCameraAndThePlane) {
    glm::mat4 p = glm::perspective(glm::radians(60.0f), 1.3f, 0.1f, 50.0f);
    glm::mat4 oblique = obliqueNearPlane(p, planeThrough({0, 0, -5}, {0.3f, 0.2f, -1}));
    for (glm::vec3 q :
         {glm::vec3(0, 0, -2), glm::vec3(0.5f, -0.3f, -4.5f), glm::vec3(0, 0, -0.5f)}) {
        EXPECT_GT(ndcZ(p, q), -1.0f);               // inside the original frustum...
        EXPECT_LT(ndcZ(oblique, q), -1.0f) << q.z;  // ...clipped by the new near plane
    }
}

TEST(MirrorMath, ObliqueNearPlaneKeepsTheOriginalFrustumOnTheKeptSide) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    for (glm::vec3 normal :
         {glm::vec3(0.3f, 0.2f, -1), glm::vec3(-0.8f, 0.1f, -0.5f), glm::vec3(0, -0.9f, -0.3f)}) {
        glm::mat4 p = glm::perspective(glm::radians(60.0f), 1.3f, 0.1f, 50.0f);
        glm::vec4 plane = planeThrough({0.2f, -0.1f, -3}, normal);
        glm::mat4 oblique = obliqueNearPlane(p, plane);
        glm::mat4 inverse = glm::inverse(p);
        int kept = 0;
        for (int i = 0; i < 4000; ++i) {
            glm::vec4 v = inverse * glm::vec4(unit(rng), unit(rng), unit(rng), 1.0f);
            v /= v.w;
            if (glm::dot(plane, v) < 0.0f) continue;
            ++kept;
            float z = ndcZ(oblique, glm::vec3(v));
            EXPECT_GE(z, -1.0f - 1e-4f);
            EXPECT_LE(z, 1.0f + 1e-4f);
        }
        EXPECT_GT(kept, 100);
    }
}

TEST(MirrorMath, ObliqueNearPlaneWithTheNearPlaneItselfChangesNothing) {
    // Also for the mirror camera's off-axis frustum: the mirror's plane is its near plane.
    MirrorCamera c = mirrorCamera(untidyMirror(), {-0.5f, 1.6f, 2.5f}, 6.0f);
    ASSERT_TRUE(c.valid);
    glm::vec4 mirrorPlaneInView(0, 0, -1, -c.zNear);
    for (glm::vec4 plane : {mirrorPlaneInView, -mirrorPlaneInView}) {  // either orientation
        glm::mat4 oblique = obliqueNearPlane(c.projection, plane);
        for (int col = 0; col < 4; ++col)
            for (int row = 0; row < 4; ++row)
                EXPECT_NEAR(oblique[col][row], c.projection[col][row],
                            1e-4f * std::max(1.0f, std::abs(c.projection[col][row])));
    }
}

TEST(MirrorMath, ObliqueNearPlaneLeavesTheProjectionAloneWhenItCannotWork) {
    glm::mat4 p = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 50.0f);
    EXPECT_EQ(obliqueNearPlane(p, {0, 0, -1, 0}), p);    // through the camera
    EXPECT_EQ(obliqueNearPlane(p, {0, 0, -1, -80}), p);  // beyond the far plane
    EXPECT_EQ(obliqueNearPlane(p, {std::nanf(""), 0, -1, -2}), p);
}

// ---- footprint on screen
// --------------------------------------------------------------------------

TEST(MirrorMath, FootprintOfAMirrorFillingTheScreenIsTheImage) {
    Camera viewer;
    viewer.eye = {0, 0, 3};
    viewer.at = {0, 0, 0};
    Mirror m;  // at the origin, facing the viewer
    float halfHeight = 3.0f * std::tan(glm::radians(viewer.fovyDegrees) * 0.5f);
    m.height = 2.0f * halfHeight;
    m.width = m.height * 640.0f / 480.0f;
    glm::ivec2 exact = mirrorFootprintPixels(m, viewer, 640, 480);
    EXPECT_NEAR(exact.x, 640, 1);
    EXPECT_NEAR(exact.y, 480, 1);
    m.width *= 3.0f;
    m.height *= 3.0f;
    EXPECT_EQ(mirrorFootprintPixels(m, viewer, 640, 480), glm::ivec2(640, 480));
    m.width /= 6.0f;  // half the screen's width, three times its height
    glm::ivec2 half = mirrorFootprintPixels(m, viewer, 640, 480);
    EXPECT_NEAR(half.x, 320, 1);
    EXPECT_EQ(half.y, 480);
}

TEST(MirrorMath, FootprintIsZeroWhenTheMirrorCannotBeSeen) {
    Camera viewer;
    viewer.eye = {0, 0, 3};
    viewer.at = {0, 0, 6};  // looking away: the mirror at the origin is behind the camera
    Mirror m;
    EXPECT_EQ(mirrorFootprintPixels(m, viewer, 640, 480), glm::ivec2(0, 0));
    viewer.at = {0, 0, 0};
    viewer.eye = {0, 0, -3};  // behind the mirror: its back reflects nothing
    EXPECT_EQ(mirrorFootprintPixels(m, viewer, 640, 480), glm::ivec2(0, 0));
    viewer.eye = {0, 0, 3};
    viewer.at = {10, 0, 3};  // looking sideways, the mirror is outside the frustum
    EXPECT_EQ(mirrorFootprintPixels(m, viewer, 640, 480), glm::ivec2(0, 0));
    viewer.at = {0, 0, 0};
    m.width = 0.0f;
    EXPECT_EQ(mirrorFootprintPixels(m, viewer, 640, 480), glm::ivec2(0, 0));
    m.width = 1.0f;
    EXPECT_EQ(mirrorFootprintPixels(m, viewer, 0, 480), glm::ivec2(0, 0));
    m.center.z = -30.0f;  // beyond the far plane (20)
    EXPECT_EQ(mirrorFootprintPixels(m, viewer, 640, 480), glm::ivec2(0, 0));
}

TEST(MirrorMath, FootprintOfAMirrorReachingBehindTheCameraIsClippedNotGarbage) {
    // A long floor mirror running under the viewer: two corners are behind the camera.
    Camera viewer;
    viewer.eye = {0, 1, 0};
    viewer.at = {0, 0.5f, -3};
    Mirror floor;
    floor.center = {0, 0, 0};
    floor.normal = {0, 1, 0};
    floor.up = {0, 0, -1};
    floor.width = 2.0f;
    floor.height = 10.0f;
    glm::ivec2 size = mirrorFootprintPixels(floor, viewer, 640, 480);
    EXPECT_EQ(size.x, 640);  // the near part is wider than the screen
    EXPECT_GT(size.y, 100);
    EXPECT_LE(size.y, 480);
}

TEST(MirrorMath, FootprintOfASmallMirrorMatchesItsProjectedCorners) {
    Camera viewer;
    viewer.eye = {0.4f, 0.3f, 4};
    viewer.at = {0, 0, 0};
    Mirror m;
    m.width = 0.8f;
    m.height = 0.5f;
    glm::vec2 lo(1e9f), hi(-1e9f);
    for (const glm::vec3& corner : mirrorCorners(m).corner) {
        glm::vec2 px;
        ASSERT_TRUE(projectToPixel(viewer, 640, 480, corner, px));
        lo = glm::min(lo, px);
        hi = glm::max(hi, px);
    }
    glm::ivec2 size = mirrorFootprintPixels(m, viewer, 640, 480);
    EXPECT_EQ(size.x, int(std::ceil(hi.x)) - int(std::floor(lo.x)));
    EXPECT_EQ(size.y, int(std::ceil(hi.y)) - int(std::floor(lo.y)));
}
