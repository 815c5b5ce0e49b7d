#include "reference/raytracer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>

#include "io/box.h"
#include "reference/object_bvh.h"

namespace sl {

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Slab method: the ray is inside the box where it is inside all three pairs of parallel planes.
// The hit is where it enters (or, when it starts inside, where it leaves); the normal is that of
// the face crossed there, pointing out of the box.
bool intersectBox(const Object& box, const Ray& ray, float tMin, float tMax, float& tHit,
                  glm::vec3& normal) {
    glm::vec3 low = box.center - 0.5f * box.size;
    glm::vec3 high = box.center + 0.5f * box.size;
    float tEnter = -kInfinity, tExit = kInfinity;
    int enterAxis = -1, exitAxis = -1;
    for (int axis = 0; axis < 3; ++axis) {
        float o = ray.origin[axis], d = ray.direction[axis];
        if (std::abs(d) < 1e-12f) {
            // Parallel to this pair of planes: inside the slab for every t, or never.
            if (o < low[axis] || o > high[axis]) return false;
            continue;
        }
        float t0 = (low[axis] - o) / d;
        float t1 = (high[axis] - o) / d;
        if (t0 > t1) std::swap(t0, t1);
        if (t0 > tEnter) {
            tEnter = t0;
            enterAxis = axis;
        }
        if (t1 < tExit) {
            tExit = t1;
            exitAxis = axis;
        }
    }
    if (tEnter > tExit || exitAxis < 0) return false;
    normal = glm::vec3(0.0f);
    if (enterAxis >= 0 && tEnter > tMin && tEnter < tMax) {
        tHit = tEnter;
        // The face we enter through faces against the ray.
        normal[enterAxis] = ray.direction[enterAxis] < 0.0f ? 1.0f : -1.0f;
        return true;
    }
    if (tEnter <= tMin && tExit > tMin && tExit < tMax) {
        tHit = tExit;
        normal[exitAxis] = ray.direction[exitAxis] > 0.0f ? 1.0f : -1.0f;
        return true;
    }
    return false;
}

// |origin + t d - center|^2 = r^2 with a unit d: t^2 + 2 b t + c = 0.
bool intersectSphere(const Object& sphere, const Ray& ray, float tMin, float tMax, float& tHit,
                     glm::vec3& normal) {
    glm::vec3 oc = ray.origin - sphere.center;
    float b = glm::dot(oc, ray.direction);
    float c = glm::dot(oc, oc) - sphere.radius * sphere.radius;
    float discriminant = b * b - c;
    if (discriminant < 0.0f) return false;
    float root = std::sqrt(discriminant);
    float t = -b - root;  // the near root first
    if (!(t > tMin && t < tMax)) {
        t = -b + root;  // the ray starts inside: it leaves through the far side
        if (!(t > tMin && t < tMax)) return false;
    }
    tHit = t;
    normal = glm::normalize(ray.origin + t * ray.direction - sphere.center);
    return true;
}

// A rectangle in the plane through `center` with normal `n`, spanning width along
// right = cross(up, n) and height along up (as mirrorCorners builds it). `front` tells whether
// the ray arrives on the side `n` points to.
bool intersectRectangle(const glm::vec3& center, const glm::vec3& n, const glm::vec3& up,
                        float width, float height, const Ray& ray, float tMin, float tMax,
                        float& tHit, bool& front) {
    float denominator = glm::dot(ray.direction, n);
    if (std::abs(denominator) < 1e-12f) return false;  // parallel to the plane
    float t = glm::dot(center - ray.origin, n) / denominator;
    if (!(t > tMin && t < tMax)) return false;
    glm::vec3 right = glm::normalize(glm::cross(up, n));
    glm::vec3 upInPlane = glm::cross(n, right);  // = normalized up when up is perpendicular to n
    glm::vec3 local = ray.origin + t * ray.direction - center;
    if (std::abs(glm::dot(local, right)) > 0.5f * width) return false;
    if (std::abs(glm::dot(local, upInPlane)) > 0.5f * height) return false;
    tHit = t;
    front = denominator < 0.0f;
    return true;
}

bool intersectObject(const Object& object, const Ray& ray, float tMin, float tMax, float& tHit,
                     glm::vec3& normal) {
    switch (object.kind) {
        case PrimitiveKind::Box:
            return intersectBox(object, ray, tMin, tMax, tHit, normal);
        case PrimitiveKind::Sphere:
            return intersectSphere(object, ray, tMin, tMax, tHit, normal);
        case PrimitiveKind::Quad: {
            glm::vec3 n = glm::normalize(object.normal);
            bool front = false;
            if (!intersectRectangle(object.center, n, object.up, object.width, object.height, ray,
                                    tMin, tMax, tHit, front))
                return false;
            normal = n;  // as declared, from either side: lighting treats quads as one-sided
            return true;
        }
    }
    return false;
}

// The scene with its two hierarchies: every object (what a ray sees) and the shadow casters
// (what blocks the light). Built once per reference image.
struct SceneIndex {
    explicit SceneIndex(const Scene& s)
        : scene(s),
          all(s.objects, [](const Object&) { return true; }),
          casters(s.objects, [](const Object& o) { return o.castsShadow; }) {}
    const Scene& scene;
    ObjectBvh all, casters;
};

bool nearestHit(const SceneIndex& index, const Ray& ray, float tMax, bool includeMirror,
                RayHit& hit);
bool blockedOnTheWay(const SceneIndex& index, const glm::vec3& position, const glm::vec3& normal,
                     const glm::vec3& lightPosition);

ReferencePixel tracePixel(const SceneIndex& index, const Ray& ray, const glm::vec3& light) {
    ReferencePixel pixel;
    RayHit hit;
    if (!nearestHit(index, ray, kInfinity, true, hit)) return pixel;

    pixel.position = ray.origin + hit.t * ray.direction;
    pixel.normal = hit.normal;
    pixel.objectId = hit.mirror ? mirrorId(index.scene) : objectId(std::size_t(hit.objectIndex));
    pixel.facesLight = glm::dot(pixel.normal, light - pixel.position) > 0.0f;
    pixel.blocked = blockedOnTheWay(index, pixel.position, pixel.normal, light);
    if (!hit.mirror || !hit.mirrorFront) return pixel;

    // One bounce off the mirror. The mirror is left out: a plane cannot see itself.
    Ray bounce{pixel.position, glm::reflect(ray.direction, pixel.normal)};
    RayHit seen;
    if (!nearestHit(index, bounce, kInfinity, false, seen)) {
        pixel.bounceObjectId = 0;
        return pixel;
    }
    pixel.bounceObjectId = objectId(std::size_t(seen.objectIndex));
    pixel.bouncePosition = bounce.origin + seen.t * bounce.direction;
    pixel.bounceNormal = seen.normal;
    pixel.bounceFacesLight = glm::dot(seen.normal, light - pixel.bouncePosition) > 0.0f;
    pixel.bounceBlocked = blockedOnTheWay(index, pixel.bouncePosition, seen.normal, light);
    return pixel;
}

// Phong with white light: ambient always; diffuse and specular only for a lit, facing point.
glm::vec3 phong(const Material& m, const glm::vec3& color, const glm::vec3& position,
                const glm::vec3& normal, bool lit, const glm::vec3& eye, const glm::vec3& light) {
    glm::vec3 result = m.ambient * color;
    if (!lit) return result;
    glm::vec3 L = glm::normalize(light - position);
    glm::vec3 V = glm::normalize(eye - position);
    glm::vec3 R = glm::reflect(-L, normal);
    result += m.diffuse * std::max(glm::dot(normal, L), 0.0f) * color;
    result += glm::vec3(m.specular * std::pow(std::max(glm::dot(R, V), 0.0f), m.shininess));
    return result;
}

void storeColor(Image& image, int i, int j, const glm::vec3& c) {
    std::uint8_t* p = image.at(i, j);
    for (int k = 0; k < 3; ++k)
        p[k] = static_cast<std::uint8_t>(std::clamp(c[k], 0.0f, 1.0f) * 255.0f + 0.5f);
    p[3] = 255;
}

const glm::vec3& objectColor(const Scene& scene, int id) {
    if (id < 1 || id > int(scene.objects.size()))
        throw std::invalid_argument("shadeReference: the reference does not match the scene");
    return scene.objects[std::size_t(id) - 1].color;
}

// The mirror has no colour of its own; its back is drawn as a dull grey surface.
const glm::vec3 kMirrorBackColor(0.3f);

}  // namespace

namespace {

bool nearestHit(const SceneIndex& index, const Ray& ray, float tMax, bool includeMirror,
                RayHit& hit) {
    bool found = false;
    float nearest = tMax;
    // The nearest hit; at an equal distance the object listed first, as a plain loop would pick.
    index.all.forEachCandidate(ray, kRayEpsilon, tMax, [&](int k, float& bound) {
        float t;
        glm::vec3 n;
        const float upTo = found ? std::nextafter(nearest, kInfinity) : nearest;
        if (intersectObject(index.scene.objects[std::size_t(k)], ray, kRayEpsilon, upTo, t, n) &&
            (t < nearest || k < hit.objectIndex)) {
            found = true;
            nearest = t;
            bound = t;
            hit = RayHit{t, k, false, false, n};
        }
        return false;
    });
    const Scene& scene = index.scene;
    if (includeMirror && scene.mirror) {
        const Mirror& m = *scene.mirror;
        glm::vec3 n = glm::normalize(m.normal);
        float t;
        bool front = false;
        if (intersectRectangle(m.center, n, m.up, m.width, m.height, ray, kRayEpsilon, nearest, t,
                               front)) {
            found = true;
            // From behind, the mirror is an opaque back whose outward normal is -normal.
            hit = RayHit{t, -1, true, front, front ? n : -n};
        }
    }
    return found;
}

bool blockedOnTheWay(const SceneIndex& index, const glm::vec3& position, const glm::vec3& normal,
                     const glm::vec3& lightPosition) {
    glm::vec3 origin = position + normal * kShadowOffset;
    glm::vec3 toLight = lightPosition - origin;
    float distance = glm::length(toLight);
    if (distance <= kRayEpsilon) return false;
    Ray ray{origin, toLight / distance};
    bool blocked = false;
    index.casters.forEachCandidate(ray, kRayEpsilon, distance, [&](int k, float&) {
        float t;
        glm::vec3 n;
        blocked =
            intersectObject(index.scene.objects[std::size_t(k)], ray, kRayEpsilon, distance, t, n);
        return blocked;  // any caster will do: stop at the first
    });
    return blocked;
}

}  // namespace

bool shadowRayBlocked(const Scene& scene, const glm::vec3& position, const glm::vec3& normal,
                      const glm::vec3& lightPosition) {
    return blockedOnTheWay(SceneIndex(scene), position, normal, lightPosition);
}

namespace {

// Does the surface of pixel k, continued under the ray of pixel (i, j) along its tangent plane,
// change shadow state there? The continuation goes no further than a few pixels' width from the
// hit point, in the direction of that ray's hit: at a sphere's limb, or a floor seen near
// grazing, the tangent plane runs off almost parallel to the ray and the full continuation
// would land far beyond the edge, in some other shadow.
bool shadowChangesBeyond(const SceneIndex& index, const Camera& camera, const PixelRays& rays,
                         const glm::vec3& light, const ReferencePixel& p, int i, int j,
                         int height) {
    Ray ray = rays(i, j);
    float facing = glm::dot(ray.direction, p.normal);
    if (std::abs(facing) < 1e-6f) return false;
    float t = glm::dot(p.position - ray.origin, p.normal) / facing;
    if (t <= 0.0f) return false;
    glm::vec3 beyond = ray.origin + t * ray.direction;
    float pixelWidth = glm::length(p.position - camera.eye) * 2.0f *
                       std::tan(glm::radians(camera.fovyDegrees) * 0.5f) / float(height);
    const float reach = glm::length(beyond - p.position), most = 4.0f * pixelWidth;
    if (reach > most) beyond = p.position + (beyond - p.position) * (most / reach);
    if (glm::dot(p.normal, light - beyond) <= 0.0f) return false;  // continued past the terminator
    return blockedOnTheWay(index, beyond, p.normal, light) != p.blocked;
}

void markSilhouettes(const SceneIndex& index, const Camera& camera, const glm::vec3& lightPosition,
                     ReferenceImage& image) {
    const int w = image.width, h = image.height;
    const PixelRays rays(camera, w, h);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            ReferencePixel& p = image.pixels[std::size_t(j) * w + i];
            if (p.objectId == 0 || p.objectId == image.mirrorObjectId || !p.facesLight) continue;
            const int offsets[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
            for (const auto& o : offsets) {
                int ni = i + o[0], nj = j + o[1];
                if (ni < 0 || nj < 0 || ni >= w || nj >= h) continue;
                const ReferencePixel& n = image.pixels[std::size_t(nj) * w + ni];
                if (n.objectId == p.objectId && n.facesLight) continue;  // not a silhouette
                if (shadowChangesBeyond(index, camera, rays, lightPosition, p, ni, nj, h)) {
                    p.shadowEdgeAtSilhouette = true;
                    break;
                }
            }
        }
}

}  // namespace

ReferenceImage traceReference(const Scene& scene, const Camera& camera,
                              const glm::vec3& lightPosition, int width, int height, int threads) {
    if (width <= 0 || height <= 0) throw std::invalid_argument("traceReference: empty image");
    ReferenceImage image;
    image.width = width;
    image.height = height;
    image.mirrorObjectId = mirrorId(scene);
    image.pixels.resize(std::size_t(width) * height);

    if (threads <= 0) threads = boxCores();  // the CPUs this process may use
    threads = std::min(threads, height);

    const SceneIndex index(scene);
    const PixelRays rays(camera, width, height);
    // Every pixel is computed on its own, so which thread does a row cannot change the result.
    // Rows are dealt out round-robin so each thread gets a share of the busy and the empty rows.
    auto traceRows = [&](int first) {
        for (int j = first; j < height; j += threads)
            for (int i = 0; i < width; ++i)
                image.pixels[std::size_t(j) * width + i] =
                    tracePixel(index, rays(i, j), lightPosition);
    };
    std::vector<std::thread> workers;
    for (int k = 1; k < threads; ++k) workers.emplace_back(traceRows, k);
    traceRows(0);
    for (std::thread& w : workers) w.join();
    markSilhouettes(index, camera, lightPosition, image);
    return image;
}

Image shadeReference(const Scene& scene, const Camera& camera, const ReferenceImage& reference,
                     const glm::vec3& lightPosition, Occlusion occlusion) {
    if (reference.pixels.size() != std::size_t(reference.width) * reference.height)
        throw std::invalid_argument("shadeReference: pixel count does not match the size");
    Image image(reference.width, reference.height);
    const int mirror = mirrorId(scene);
    for (int j = 0; j < reference.height; ++j)
        for (int i = 0; i < reference.width; ++i) {
            const ReferencePixel& p = reference.at(i, j);
            const bool blocked =
                occlusion == Occlusion::AsTraced ? p.blocked : occlusion == Occlusion::AllBlocked;
            glm::vec3 color = scene.background;
            if (p.objectId == mirror && p.bounceObjectId >= 0) {
                // The reflected ray starts at the mirror point, so that is the "eye" of the bounce.
                glm::vec3 seen = scene.background;
                if (p.bounceObjectId > 0)
                    seen = phong(scene.material, objectColor(scene, p.bounceObjectId),
                                 p.bouncePosition, p.bounceNormal,
                                 p.bounceFacesLight && !p.bounceBlocked, p.position, lightPosition);
                color = kMirrorReflectance * seen;
            } else if (p.objectId == mirror) {
                color = phong(scene.material, kMirrorBackColor, p.position, p.normal,
                              p.facesLight && !blocked, camera.eye, lightPosition);
            } else if (p.objectId > 0) {
                color = phong(scene.material, objectColor(scene, p.objectId), p.position, p.normal,
                              p.facesLight && !blocked, camera.eye, lightPosition);
            }
            storeColor(image, i, j, color);
        }
    return image;
}

}  // namespace sl
