// The browser edition's PNG files (cmake/web.cmake): Debian's libpng is not built for
// WebAssembly, stb's single-header coder is (header-only, libstb-dev). The page writes its
// check pictures into its own memory and shows them (it reads none back); the desktop keeps libpng
// (io/png.cpp, 4-5x faster, where a class writes three pictures a row).
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

#include <vector>

#include "io/files.h"
#include "io/png.h"

namespace sl {

namespace {

void appendBytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<unsigned char>*>(context);
    auto* bytes = static_cast<unsigned char*>(data);
    out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

std::string writePng(const std::string& path, const Image& image) {
    if (image.width <= 0 || image.height <= 0) return "cannot write '" + path + "': empty image";
    std::vector<unsigned char> png;
    if (!stbi_write_png_to_func(appendBytes, &png, image.width, image.height, 4, image.rgba.data(),
                                image.width * 4))
        return "cannot write '" + path + "': PNG encoding failed";
    return writeFileAtomically(path, png.data(), png.size());
}

}  // namespace sl
