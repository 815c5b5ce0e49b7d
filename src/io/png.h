// PNG files of an Image: the check pictures, the truth and the diffs.
#pragma once

#include <string>

#include "io/image.h"

namespace sl {

// Writes a PNG atomically: into a temporary file beside `path`, renamed over it only when
// complete, so a failure never leaves a partial file. Returns an empty string or the error.
std::string writePng(const std::string& path, const Image& image);

// Reads a PNG as RGBA8. Returns an empty string or the error.
std::string readPng(const std::string& path, Image& image);

}  // namespace sl
