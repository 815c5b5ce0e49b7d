#include "platform/headless.h"

#include <algorithm>

namespace sl {

Image HeadlessContext::read() const {
    Image img(width_, height_);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    std::vector<std::uint8_t> bottomUp(img.rgba.size());
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
    std::size_t row = std::size_t(width_) * 4;
    for (int j = 0; j < height_; ++j)  // GL's row 0 is the bottom; PNG's is the top
        std::copy_n(&bottomUp[std::size_t(height_ - 1 - j) * row], row,
                    &img.rgba[std::size_t(j) * row]);
    return img;
}

}  // namespace sl
