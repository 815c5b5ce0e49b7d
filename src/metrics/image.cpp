#include "metrics/image.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <cstring>

#include "io/files.h"

namespace sl {

namespace {

std::string failure(const std::string& path, const std::string& why) {
    return "cannot write '" + path + "': " + why;
}

}  // namespace

std::string writePng(const std::string& path, const Image& image) {
    if (image.width <= 0 || image.height <= 0) return failure(path, "empty image");
    // Encode in memory first: stbi_write_png to a file does not report a failed fwrite.
    std::vector<unsigned char> png;
    auto append = [](void* context, void* data, int size) {
        auto* bytes = static_cast<unsigned char*>(data);
        static_cast<std::vector<unsigned char>*>(context)->insert(
            static_cast<std::vector<unsigned char>*>(context)->end(), bytes, bytes + size);
    };
    if (!stbi_write_png_to_func(append, &png, image.width, image.height, 4, image.rgba.data(),
                                image.width * 4))
        return failure(path, "PNG encoding failed");
    return writeFileAtomically(path, png.data(), png.size());
}

std::string readPng(const std::string& path, Image& image) {
    int w = 0, h = 0, n = 0;
    unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, 4);
    if (!data) return "cannot read '" + path + "': " + stbi_failure_reason();
    image = Image(w, h);
    std::memcpy(image.rgba.data(), data, image.rgba.size());
    stbi_image_free(data);
    return {};
}

std::string writeTextFile(const std::string& path, const std::string& text) {
    return writeFileAtomically(path, text.data(), text.size());
}

}  // namespace sl
