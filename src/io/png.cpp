#include "io/png.h"

#include <png.h>
#include <stb_image.h>

#include <cstring>

#include "io/files.h"

namespace sl {

namespace {

std::string failure(const std::string& path, const std::string& why) {
    return "cannot write '" + path + "': " + why;
}

}  // namespace

namespace {

// libpng's write callbacks: into a byte vector (encoded in memory first, so a failed write is
// writeFileAtomically's to report, and a full disk never leaves a truncated PNG).
void appendBytes(png_structp png, png_bytep data, png_size_t size) {
    auto* out = static_cast<std::vector<unsigned char>*>(png_get_io_ptr(png));
    out->insert(out->end(), data, data + size);
}
void noFlush(png_structp) {}

// Encodes without C++ objects in the frame that longjmp leaves (libpng's error path).
bool encodePng(const Image& image, std::vector<unsigned char>& out) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    if (!png) return false;
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, info ? &info : nullptr);
        return false;
    }
    png_set_write_fn(png, &out, appendBytes, noFlush);
    // zlib's default level, no row filter: a 640x480 check picture in 6-9 ms and 20-30 KB, where
    // stb_image_write (five filters tried a row, its own deflate) took 29-43 ms for 30-45 KB;
    // grading writes three pictures a row (docs/results-class.md).
    png_set_compression_level(png, 6);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
    png_set_IHDR(png, info, png_uint_32(image.width), png_uint_32(image.height), 8,
                 PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE,
                 PNG_FILTER_TYPE_BASE);
    png_write_info(png, info);
    for (int j = 0; j < image.height; ++j)
        png_write_row(png,
                      const_cast<png_bytep>(image.rgba.data() + std::size_t(j) * image.width * 4));
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return true;
}

}  // namespace

std::string writePng(const std::string& path, const Image& image) {
    if (image.width <= 0 || image.height <= 0) return failure(path, "empty image");
    std::vector<unsigned char> png;
    png.reserve(image.rgba.size() / 8);
    if (!encodePng(image, png)) return failure(path, "PNG encoding failed");
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

}  // namespace sl
