// An 8-bit RGBA image in memory, row 0 at the top (as PNG stores it).
#pragma once

#include <cstdint>
#include <vector>

namespace sl {

// Rec. 601 luma of one RGBA8 pixel in [0, 255].
inline float rec601Luma(const std::uint8_t* rgba) {
    return 0.299f * rgba[0] + 0.587f * rgba[1] + 0.114f * rgba[2];
}

struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;  // width * height * 4, row 0 = top

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgba(std::size_t(w) * h * 4, 0) {}
    std::uint8_t* at(int i, int j) { return &rgba[(std::size_t(j) * width + i) * 4]; }
    const std::uint8_t* at(int i, int j) const { return &rgba[(std::size_t(j) * width + i) * 4]; }
    // Rec. 601 luma of pixel (i, j) in [0, 255].
    float luma(int i, int j) const { return rec601Luma(at(i, j)); }
};

}  // namespace sl
