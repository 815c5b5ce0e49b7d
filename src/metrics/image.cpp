#include "metrics/image.h"

#include <fcntl.h>
#include <stb_image.h>
#include <stb_image_write.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace sl {

float Image::luma(int i, int j) const {
    const std::uint8_t* p = at(i, j);
    return 0.299f * p[0] + 0.587f * p[1] + 0.114f * p[2];
}

namespace {

std::string temporaryBeside(const std::string& path) {
    return path + ".tmp" + std::to_string(::getpid());
}

std::string failure(const std::string& path, const std::string& why) {
    return "cannot write '" + path + "': " + why;
}

// Renaming over a device or a folder would replace it (we may run as root): refuse both.
std::string checkTarget(const std::string& path) {
    struct stat st;
    if (::stat(path.c_str(), &st) != 0) return {};  // a new file
    if (S_ISDIR(st.st_mode)) return failure(path, "it is a folder; give a file name");
    if (!S_ISREG(st.st_mode)) return failure(path, "it is not a regular file (a device?)");
    return {};
}

// Writes every byte into a temporary file beside `path`, checking each step (a full disk shows
// up in write or close), then renames it over `path`. On failure nothing is left.
std::string writeAtomically(const std::string& path, const void* data, std::size_t size) {
    if (std::string err = checkTarget(path); !err.empty()) return err;
    std::string tmp = temporaryBeside(path);
    int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) return failure(path, std::strerror(errno));
    const char* p = static_cast<const char*>(data);
    std::size_t left = size;
    int error = 0;
    while (left > 0 && !error) {
        ssize_t n = ::write(fd, p, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0)
            error = n < 0 ? errno : ENOSPC;
        else {
            p += n;
            left -= std::size_t(n);
        }
    }
    if (::close(fd) != 0 && !error) error = errno;
    if (!error && std::rename(tmp.c_str(), path.c_str()) != 0) error = errno;
    if (error) {
        std::remove(tmp.c_str());
        return failure(path, std::strerror(error));
    }
    return {};
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
    return writeAtomically(path, png.data(), png.size());
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
    return writeAtomically(path, text.data(), text.size());
}

}  // namespace sl
