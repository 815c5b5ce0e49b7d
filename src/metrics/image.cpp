#include "metrics/image.h"

#include <stb_image.h>
#include <stb_image_write.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

namespace sl {

float Image::luma(int i, int j) const {
    const std::uint8_t* p = at(i, j);
    return 0.299f * p[0] + 0.587f * p[1] + 0.114f * p[2];
}

namespace {

std::string temporaryBeside(const std::string& path) {
    return path + ".tmp" + std::to_string(::getpid());
}

std::string commit(const std::string& tmp, const std::string& path) {
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        std::string err = std::strerror(errno);
        std::remove(tmp.c_str());
        return "cannot write '" + path + "': " + err;
    }
    return {};
}

}  // namespace

std::string writePng(const std::string& path, const Image& image) {
    if (image.width <= 0 || image.height <= 0) return "cannot write '" + path + "': empty image";
    std::string tmp = temporaryBeside(path);
    errno = 0;
    int ok = stbi_write_png(tmp.c_str(), image.width, image.height, 4, image.rgba.data(),
                            image.width * 4);
    if (!ok) {
        std::string err = errno ? std::strerror(errno) : "write failed";
        std::remove(tmp.c_str());
        return "cannot write '" + path + "': " + err;
    }
    return commit(tmp, path);
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
    std::string tmp = temporaryBeside(path);
    {
        std::ofstream out(tmp, std::ios::binary);
        if (!out) return "cannot write '" + path + "': " + std::strerror(errno);
        out << text;
        out.flush();
        if (!out) {
            std::remove(tmp.c_str());
            return "cannot write '" + path + "': " + std::strerror(errno);
        }
    }
    return commit(tmp, path);
}

}  // namespace sl
