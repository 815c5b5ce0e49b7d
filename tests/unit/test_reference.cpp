#include <gtest/gtest.h>

#include <cmath>

#include "math/camera.h"
#include "metrics/shadow_metrics.h"
#include "reference/raytracer.h"

using namespace sl;

namespace {

constexpr int kWidth = 640, kHeight = 480;

Object box(const char* name, glm::vec3 center, glm::vec3 size, glm::vec3 color = glm::vec3(0.8f)) {
    Object o;
    o.name = name;
    o.kind = PrimitiveKind::Box;
    o.center = center;
    o.size = size;
    o.color = color;
    return o;
}

Object sphere(const char* name, glm::vec3 center, float radius) {
    Object o;
    o.name = name;
    o.kind = PrimitiveKind::Sphere;
    o.center = center;
    o.radius = radius;
    return o;
}

Object quad(const char* name, glm::vec3 center, glm::vec3 normal, glm::vec3 up, float w, float h) {
    Object o;
    o.name = name;
    o.kind = PrimitiveKind::Quad;
    o.center = center;
    o.normal = normal;
    o.up = up;
    o.width = w;
    o.height = h;
    return o;
}

// The lecture scene. Ids: floor 1, floating cube 2, standing cube 3, sphere 4.
Scene lectureScene() {
    Scene s;
    s.name = "lecture";
    s.objects = {box("floor", {0, -0.05f, 0}, {3, 0.1f, 3}, glm::vec3(0.8f)),
                 box("floating cube", {-0.5f, 0.35f, 0}, glm::vec3(0.5f)),
                 box("standing cube", {0.5f, 0.25f, 0.25f}, glm::vec3(0.5f)),
                 sphere("sphere", {0.5f, 0.4f, -0.5f}, 0.4f)};
    s.light.position = {2, 1, 0};
    s.camera.eye = {0, 2.5f, 4.5f};
    s.camera.at = {0, 0, 0};
    s.camera.fovyDegrees = 45;
    return s;
}

// The pixel whose footprint contains the projection of `world`.
void pixelOf(const Camera& c, const glm::vec3& world, int& i, int& j) {
    glm::vec2 px;
    ASSERT_TRUE(projectToPixel(c, kWidth, kHeight, world, px));
    i = int(std::floor(px.x));
    j = int(std::floor(px.y));
    ASSERT_TRUE(i >= 0 && j >= 0 && i < kWidth && j < kHeight);
}

// Traces the single pixel that sees `world` (a 640x480 image, but only what the test looks at).
ReferencePixel traceAt(const Scene& s, const Camera& c, const glm::vec3& light,
                       const glm::vec3& world) {
    int i = -1, j = -1;
    pixelOf(c, world, i, j);
    ReferenceImage image = traceReference(s, c, light, kWidth, kHeight, 2);
    return i < 0 ? ReferencePixel{} : image.at(i, j);
}

// A pixel is 2 * 4.5 * tan(22.5 deg) / 480 ~ 0.008 world units wide near the lecture stage.
constexpr float kFootprint = 0.02f;

void expectVec(const glm::vec3& a, const glm::vec3& b, float tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

bool samePixel(const ReferencePixel& a, const ReferencePixel& b) {
    return a.objectId == b.objectId && a.position == b.position && a.normal == b.normal &&
           a.facesLight == b.facesLight && a.blocked == b.blocked &&
           a.bounceObjectId == b.bounceObjectId && a.bounceBlocked == b.bounceBlocked &&
           a.bounceFacesLight == b.bounceFacesLight && a.bouncePosition == b.bouncePosition &&
           a.bounceNormal == b.bounceNormal;
}

// A small stage for the mirror: the mirror at the origin facing +z, the camera off to the right,
// so the mirror's centre reflects the view towards (-2, 0, 4) where a sphere waits.
Scene mirrorScene() {
    Scene s;
    s.objects = {sphere("seen in the mirror", {-2, 0, 4}, 0.5f)};
    Mirror m;
    m.center = {0, 0, 0};
    m.normal = {0, 0, 1};
    m.up = {0, 1, 0};
    m.width = 2;
    m.height = 2;
    s.mirror = m;
    s.camera.eye = {2, 0, 4};
    s.camera.at = {0, 0, 0};
    s.light.position = {0, 5, 1};
    return s;
}

}  // namespace

TEST(Reference, PixelRayHitsTheTopFaceOfTheFloatingCube) {
    Scene s = lectureScene();
    glm::vec3 target(-0.5f, 0.6f, 0.0f);  // centre of the top face: y = 0.35 + 0.25
    ReferencePixel p = traceAt(s, s.camera, s.light.position, target);
    EXPECT_EQ(p.objectId, objectId(1));
    EXPECT_EQ(p.normal, glm::vec3(0, 1, 0));
    EXPECT_NEAR(p.position.y, 0.6f, 1e-5f);
    expectVec(p.position, target, kFootprint);
    // Light at (2, 1, 0) is above the face, and nothing is higher: lit.
    EXPECT_TRUE(p.facesLight);
    EXPECT_FALSE(p.blocked);
    EXPECT_EQ(p.bounceObjectId, -1);
}

TEST(Reference, PixelRayHitsTheFrontFaceOfTheStandingCube) {
    Scene s = lectureScene();
    glm::vec3 target(0.5f, 0.25f, 0.5f);  // centre of the +z face: z = 0.25 + 0.25
    ReferencePixel p = traceAt(s, s.camera, s.light.position, target);
    EXPECT_EQ(p.objectId, objectId(2));
    EXPECT_EQ(p.normal, glm::vec3(0, 0, 1));
    EXPECT_NEAR(p.position.z, 0.5f, 1e-5f);
    expectVec(p.position, target, kFootprint);
    // The light sits at z = 0, behind the plane z = 0.5 of this face.
    EXPECT_FALSE(p.facesLight);
}

TEST(Reference, PixelRayHitsTheSphereOnItsSurface) {
    Scene s = lectureScene();
    glm::vec3 c(0.5f, 0.4f, -0.5f);
    glm::vec3 target = c + 0.4f * glm::normalize(s.camera.eye - c);  // the point nearest the eye
    ReferencePixel p = traceAt(s, s.camera, s.light.position, target);
    EXPECT_EQ(p.objectId, objectId(3));
    EXPECT_NEAR(glm::length(p.position - c), 0.4f, 1e-5f);
    expectVec(p.normal, (p.position - c) / 0.4f, 1e-4f);
    EXPECT_NEAR(glm::length(p.normal), 1.0f, 1e-5f);
    expectVec(p.position, target, kFootprint);
}

TEST(Reference, TopLeftPixelMissesEverything) {
    // The top edge of the view is 29 - 22.5 = 6.5 degrees below the horizon: it passes high over
    // the 3 x 3 floor.
    Scene s = lectureScene();
    ReferenceImage image = traceReference(s, s.camera, s.light.position, kWidth, kHeight, 1);
    const ReferencePixel& p = image.at(0, 0);
    EXPECT_EQ(p.objectId, 0);
    EXPECT_FALSE(p.blocked);
    EXPECT_FALSE(p.facesLight);
    EXPECT_EQ(p.bounceObjectId, -1);
}

TEST(Reference, FloorBehindTheFloatingCubeIsInItsShadow) {
    // The segment from (-1, 0, -0.1) to the light (2, 1, 0) is (-1 + 3s, s, -0.1 + 0.1s): it is
    // inside the floating cube for s in [1/12, 1/4] (x in [-0.75, -0.25], y up to 0.25 >= 0.1);
    // it stays at z < 0 so it misses the standing cube, and it passes 0.459 > 0.4 from the
    // sphere's centre.
    Scene s = lectureScene();
    glm::vec3 target(-1.0f, 0.0f, -0.1f);
    ReferencePixel p = traceAt(s, s.camera, s.light.position, target);
    EXPECT_EQ(p.objectId, objectId(0));
    EXPECT_EQ(p.normal, glm::vec3(0, 1, 0));
    EXPECT_NEAR(p.position.y, 0.0f, 1e-5f);
    expectVec(p.position, target, kFootprint);
    EXPECT_TRUE(p.facesLight);
    EXPECT_TRUE(p.blocked);

    // It is the floating cube that blocks: once it casts no shadow, the point is lit.
    s.objects[1].castsShadow = false;
    ReferencePixel unblocked = traceAt(s, s.camera, s.light.position, target);
    EXPECT_EQ(unblocked.objectId, objectId(0));
    EXPECT_FALSE(unblocked.blocked);
}

TEST(Reference, OpenFloorNearTheLightIsLit) {
    Scene s = lectureScene();
    glm::vec3 target(1.2f, 0.0f, 1.2f);  // x from 1.2 to 2 on the way to the light: nothing there
    ReferencePixel p = traceAt(s, s.camera, s.light.position, target);
    EXPECT_EQ(p.objectId, objectId(0));
    EXPECT_TRUE(p.facesLight);
    EXPECT_FALSE(p.blocked);
}

TEST(Reference, QuadSeenFromBehindKeepsItsDeclaredNormal) {
    Scene s;
    s.objects = {quad("floor tile", {0, 0, 0}, {0, 1, 0}, {0, 0, -1}, 2, 2)};
    Camera below;
    below.eye = {0, -3, 1};
    below.at = {0, 0, 0};
    glm::vec3 light(0, 3, 0);
    ReferencePixel p = traceAt(s, below, light, {0, 0, 0});
    EXPECT_EQ(p.objectId, objectId(0));
    EXPECT_EQ(p.normal, glm::vec3(0, 1, 0));
    EXPECT_NEAR(p.position.y, 0.0f, 1e-5f);
    EXPECT_TRUE(p.facesLight);  // by its declared normal, the light is on its lit side
    // Outside the 2 x 2 rectangle the plane is not there.
    ReferencePixel outside = traceAt(s, below, light, {1.5f, 0, 0});
    EXPECT_EQ(outside.objectId, 0);
}

TEST(Reference, MirrorCentreReflectsTheViewOntoTheSphere) {
    // Incoming (-2, 0, -4) reflects about +z to (-2, 0, 4): straight at the sphere's centre.
    Scene s = mirrorScene();
    ReferencePixel p = traceAt(s, s.camera, s.light.position, {0, 0, 0});
    EXPECT_EQ(p.objectId, mirrorId(s));
    EXPECT_EQ(p.objectId, 2);
    EXPECT_EQ(p.normal, glm::vec3(0, 0, 1));
    EXPECT_NEAR(p.position.z, 0.0f, 1e-5f);
    EXPECT_EQ(p.bounceObjectId, objectId(0));
    glm::vec3 c(-2, 0, 4);
    glm::vec3 expectedBounce = c + 0.5f * glm::normalize(glm::vec3(2, 0, -4));
    expectVec(p.bouncePosition, expectedBounce, kFootprint);
    EXPECT_NEAR(glm::length(p.bouncePosition - c), 0.5f, 1e-5f);
    // Light (0, 5, 1) minus the bounce point (-1.78, 0, 3.55) is (1.78, 5, -2.55): the sphere's
    // normal there (0.45, 0, -0.89) has a positive dot product with it (3.08).
    EXPECT_TRUE(p.bounceFacesLight);
    EXPECT_FALSE(p.bounceBlocked);

    // A box half-way between the bounce point and the light shadows the reflected point only.
    s.objects.push_back(box("blocker", {-0.9f, 2.5f, 2.3f}, glm::vec3(0.6f)));
    ReferencePixel shadowed = traceAt(s, s.camera, s.light.position, {0, 0, 0});
    EXPECT_EQ(shadowed.objectId, mirrorId(s));
    EXPECT_EQ(shadowed.bounceObjectId, objectId(0));
    EXPECT_TRUE(shadowed.bounceBlocked);
    EXPECT_FALSE(shadowed.blocked);
}

TEST(Reference, MirrorCornerReflectsNothing) {
    // From (0.8, 0.8, 0) the reflected ray (-1.2, 0.8, 4) passes 2.26 from the sphere's centre.
    Scene s = mirrorScene();
    ReferencePixel p = traceAt(s, s.camera, s.light.position, {0.8f, 0.8f, 0});
    EXPECT_EQ(p.objectId, mirrorId(s));
    EXPECT_EQ(p.bounceObjectId, 0);
}

TEST(Reference, MirrorBackIsOpaqueAndHasNoBounce) {
    Scene s = mirrorScene();
    Camera behind;
    behind.eye = {1, 0, -4};
    behind.at = {0, 0, 0};
    ReferencePixel p = traceAt(s, behind, s.light.position, {0, 0, 0});
    EXPECT_EQ(p.objectId, mirrorId(s));
    EXPECT_EQ(p.normal, glm::vec3(0, 0, -1));
    EXPECT_EQ(p.bounceObjectId, -1);
}

TEST(Reference, MirrorDoesNotBlockLight) {
    // The segment from (0, -1, -2) to the light (0, 0, 3) crosses z = 0 at y = -0.6: inside the
    // 2 x 2 mirror.
    Scene s = mirrorScene();
    glm::vec3 point(0, -1, -2), up(0, 1, 0), light(0, 0, 3);
    EXPECT_FALSE(shadowRayBlocked(s, point, up, light));
    // The same rectangle as an ordinary object does block.
    s.objects.push_back(quad("not a mirror", {0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 2, 2));
    EXPECT_TRUE(shadowRayBlocked(s, point, up, light));
}

TEST(Reference, ObjectsThatCastNoShadowDoNotBlock) {
    Scene s;
    s.objects = {box("ghost", {0, 1, 0}, glm::vec3(0.5f))};
    glm::vec3 floorPoint(0, 0, 0), up(0, 1, 0), light(0, 3, 0);
    EXPECT_TRUE(shadowRayBlocked(s, floorPoint, up, light));
    s.objects[0].castsShadow = false;
    EXPECT_FALSE(shadowRayBlocked(s, floorPoint, up, light));
    // A light closer than the box: the box lies beyond the segment.
    s.objects[0].castsShadow = true;
    EXPECT_FALSE(shadowRayBlocked(s, floorPoint, up, {0, 0.5f, 0}));
}

TEST(Reference, RunsAreDeterministicAndIndependentOfThreads) {
    Scene s = lectureScene();
    Mirror m;
    m.center = {0, 0.75f, -1.4f};
    m.width = 2.5f;
    m.height = 1.5f;
    s.mirror = m;
    const int w = 160, h = 120;
    ReferenceImage one = traceReference(s, s.camera, s.light.position, w, h, 1);
    ReferenceImage again = traceReference(s, s.camera, s.light.position, w, h, 1);
    ReferenceImage two = traceReference(s, s.camera, s.light.position, w, h, 2);
    ReferenceImage three = traceReference(s, s.camera, s.light.position, w, h, 3);
    ASSERT_EQ(one.pixels.size(), std::size_t(w * h));
    int mirrorPixels = 0, differing = 0;
    for (std::size_t k = 0; k < one.pixels.size(); ++k) {
        mirrorPixels += one.pixels[k].objectId == mirrorId(s);
        differing += !samePixel(one.pixels[k], again.pixels[k]) +
                     !samePixel(one.pixels[k], two.pixels[k]) +
                     !samePixel(one.pixels[k], three.pixels[k]);
    }
    EXPECT_EQ(differing, 0);
    EXPECT_GT(mirrorPixels, 100);  // the comparison did cover mirror pixels
    EXPECT_EQ(shadeReference(s, s.camera, one, s.light.position).rgba,
              shadeReference(s, s.camera, two, s.light.position).rgba);
}

TEST(Reference, ShadingFollowsPhongRules) {
    Scene s = lectureScene();
    ReferenceImage ref = traceReference(s, s.camera, s.light.position, kWidth, kHeight, 2);
    Image image = shadeReference(s, s.camera, ref, s.light.position);
    ASSERT_EQ(image.width, kWidth);
    ASSERT_EQ(image.height, kHeight);

    // Background: 0.1, 0.1, 0.15 -> 26, 26, 38.
    const std::uint8_t* bg = image.at(0, 0);
    EXPECT_EQ(bg[0], 26);
    EXPECT_EQ(bg[1], 26);
    EXPECT_EQ(bg[2], 38);
    EXPECT_EQ(bg[3], 255);

    // In shadow only ambient remains: 0.2 * 0.8 * 255 = 40.8 -> 41.
    int i, j;
    pixelOf(s.camera, {-1.0f, 0.0f, -0.1f}, i, j);
    ASSERT_TRUE(ref.at(i, j).blocked);
    EXPECT_EQ(image.at(i, j)[0], 41);
    EXPECT_EQ(image.at(i, j)[1], 41);
    EXPECT_EQ(image.at(i, j)[2], 41);

    // A lit floor point, (1.2, 0, 1.2): L = (0.8, 1, -1.2) / 1.755, N.L = 0.570;
    // R = reflect(-L, N) = (-0.456, 0.570, 0.684); V = (-1.2, 2.5, 3.3) / 4.31, R.V = 0.981.
    // 0.2 * 0.8 + 0.8 * 0.8 * 0.570 + 0.5 * 0.981^32 = 0.525 + 0.269 = 0.794 -> 202.
    pixelOf(s.camera, {1.2f, 0.0f, 1.2f}, i, j);
    EXPECT_NEAR(image.at(i, j)[0], 202, 3);
}

TEST(Reference, MirrorPixelsShowTheBounceSlightlyDarkened) {
    Scene s = mirrorScene();
    s.background = {0.5f, 0.25f, 1.0f};
    ReferenceImage ref = traceReference(s, s.camera, s.light.position, kWidth, kHeight, 2);
    Image image = shadeReference(s, s.camera, ref, s.light.position);
    int i, j;
    pixelOf(s.camera, {0.8f, 0.8f, 0}, i, j);  // the reflection misses everything
    ASSERT_EQ(ref.at(i, j).bounceObjectId, 0);
    // 0.9 * (0.5, 0.25, 1.0) * 255 = (114.75, 57.4, 229.5) -> (115, 57, 230)
    EXPECT_EQ(image.at(i, j)[0], 115);
    EXPECT_EQ(image.at(i, j)[1], 57);
    EXPECT_EQ(image.at(i, j)[2], 230);

    // Where the sphere is seen: its point faces the mirror along its normal, so V = N and
    // R.V = N.L = 3.08 / 5.89 = 0.522 (specular 0.522^32, nothing). Grey 0.8 gives
    // 0.9 * (0.2 * 0.8 + 0.8 * 0.8 * 0.522) = 0.445 -> 113.
    pixelOf(s.camera, {0, 0, 0}, i, j);
    ASSERT_EQ(ref.at(i, j).bounceObjectId, 1);
    const std::uint8_t* p = image.at(i, j);
    EXPECT_NEAR(p[0], 113, 1);
    EXPECT_EQ(p[0], p[1]);
    EXPECT_EQ(p[0], p[2]);
}

// Near a terminator the light adds too little for a shadow to show: a floor lit from 1 degree
// above the horizon looks the same shadowed or not, so no pixel of it can be judged; lit from
// above, every pixel can.
TEST(Reference, ShadowsAreVisibleOnlyWhereTheLightAddsEnough) {
    Scene s;
    s.objects = {box("floor", {0, -0.05f, 0}, {3, 0.1f, 3})};
    s.camera.eye = {0, 4, 0.01f};
    s.camera.at = {0, 0, 0};
    s.camera.fovyDegrees = 30;
    auto visibleAtCentre = [&](const glm::vec3& light) {
        ReferenceImage ref = traceReference(s, s.camera, light, 64, 48, 1);
        EXPECT_EQ(ref.at(32, 24).objectId, objectId(0));
        EXPECT_TRUE(ref.at(32, 24).facesLight);
        return shadowVisiblePixels(
                   referenceShades(s, s.camera, ref, light))[std::size_t(24) * 64 + 32] != 0;
    };
    EXPECT_FALSE(visibleAtCentre({100, 1.7f, 0}));  // N.L = 0.017
    EXPECT_TRUE(visibleAtCentre({0, 5, 0}));        // N.L = 1
    EXPECT_TRUE(visibleAtCentre({4, 1, 0}));        // N.L = 0.24, as the lecture's far floor
}

// The lecture's grazing view: the standing cube's top edge throws its shadow exactly onto the
// floor's far-left edge (x = -1.5), where the floor meets the background. Continued past that
// silhouette (a few pixels at most: seen this flat, the full tangent-plane continuation lands
// metres away, in the floating cube's shadow) the floor is lit, so the boundary is a shadow
// edge there. Pixels inside the floor are never marked.
TEST(Reference, ShadowEdgeOnTheFloorsFarEdgeSeenNearGrazing) {
    Scene s = lectureScene();
    Camera grazing;
    grazing.eye = {2.6f, 0.35f, 1.2f};
    grazing.at = {0, 0.3f, 0};
    grazing.fovyDegrees = 45;
    ReferenceImage ref = traceReference(s, grazing, s.light.position, kWidth, kHeight, 2);
    int farEdge = 0, marked = 0, markedInside = 0;
    for (int j = 1; j < kHeight - 1; ++j)
        for (int i = 1; i < kWidth - 1; ++i) {
            const ReferencePixel& p = ref.at(i, j);
            if (p.objectId != objectId(0) || p.normal.y < 0.5f) continue;
            const bool silhouette = ref.at(i, j - 1).objectId == 0;
            if (silhouette && p.blocked && p.position.x < -1.49f) {
                ++farEdge;
                marked += p.shadowEdgeAtSilhouette;
            }
            bool inside = true;
            for (auto [di, dj] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}})
                inside = inside && ref.at(i + di, j + dj).objectId == objectId(0);
            markedInside += inside && p.shadowEdgeAtSilhouette;
        }
    EXPECT_GE(farEdge, 10);
    EXPECT_GE(marked, 10) << "of " << farEdge;
    EXPECT_EQ(markedInside, 0);
}

TEST(Reference, RejectsAnEmptyImage) {
    Scene s = lectureScene();
    EXPECT_THROW(traceReference(s, s.camera, s.light.position, 0, 10), std::invalid_argument);
}
