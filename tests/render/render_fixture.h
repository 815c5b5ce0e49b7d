// Helpers for render tests: real OSMesa contexts in process, and the real binary for CLI tests.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "io/image.h"
#include "stages/request.h"

namespace sl::test {

struct Rendered {
    Image image;
    RenderStats stats;
    std::string explain;
    int glErrors = 0;
};

// Renders one frame headless through OSMesa. `allLit` forces the shadow map to "everything lit".
Rendered renderHeadless(const RenderRequest& request, bool allLit = false);

// Runs the shadowlab binary with arguments (a shell fragment); returns its exit code and puts
// stdout+stderr into `output`.
int runShadowlab(const std::string& arguments, std::string* output = nullptr);

// The pixel of the image where a world point lands for the request's camera.
bool pixelOf(const RenderRequest& request, const glm::vec3& world, int& i, int& j);

// The shadow tests' probes on the slides scene (light at (2,1,0)), at 320x240.
using Settings = std::vector<std::pair<std::string, std::string>>;
RenderRequest smallRequest(const std::string& stage, GlslTree tree, Settings sets = {});

// Floor points deep inside each caster's shadow (found with the reference geometry: the segment
// to the light crosses the caster well inside its outline): floating cube, standing cube, sphere
// (visible past the floating cube).
inline const glm::vec3 kDeepShadow[] = {
    {-1.2f, 0.0f, 0.0f}, {-0.1f, 0.0f, 0.25f}, {0.0f, 0.0f, -0.667f}};
// Floor points clearly lit: between the light and the casters, or off to the side.
inline const glm::vec3 kClearlyLit[] = {
    {1.2f, 0.0f, 0.6f}, {1.2f, 0.0f, -1.2f}, {-0.5f, 0.0f, 1.3f}};

// Luma of the pixel where a world point lands (a failed expectation if it is off screen).
float lumaAt(const Image& image, const RenderRequest& request, glm::vec3 world);

// Share of the open floor near the light (where nothing casts a shadow) rendered darker than
// phong: acne, or a broken map.
double darkenedNearLightShare(const Image& stage, const Image& phong, const RenderRequest& request);

// A fresh, empty temporary folder.
std::string tempDir(const std::string& tag);

}  // namespace sl::test
