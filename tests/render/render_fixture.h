// Helpers for render tests: real OSMesa contexts in process, and the real binary for CLI tests.
#pragma once

#include <string>

#include "metrics/image.h"
#include "render/request.h"

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

// A fresh, empty temporary folder.
std::string tempDir(const std::string& tag);

}  // namespace sl::test
