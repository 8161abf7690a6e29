#include "ui/screenshot.h"

#include "core/errors.h"
#include "ui/gl.h"

// The implementation comes from libstb (linked through pkg-config), not from a
// STB_IMAGE_WRITE_IMPLEMENTATION here: defining it would duplicate symbols libstb exports.
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <vector>

namespace sylva::studio {

void save_back_buffer_png(const std::string& path, int width, int height) {
    save_back_buffer_png(path, 0, 0, width, height);
}

void save_back_buffer_png(const std::string& path, int x, int y0, int width, int height) {
    const auto row_bytes = static_cast<std::size_t>(width) * 3;
    std::vector<unsigned char> pixels(row_bytes * static_cast<std::size_t>(height));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);  // rows of RGB bytes are not 4-aligned in general
    glReadBuffer(GL_BACK);
    glReadPixels(x, y0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());

    // GL's first row is the bottom one; PNG's is the top one.
    for (int y = 0; y < height / 2; ++y) {
        auto top = pixels.begin() + static_cast<std::ptrdiff_t>(row_bytes) * y;
        auto bottom = pixels.begin() + static_cast<std::ptrdiff_t>(row_bytes) * (height - 1 - y);
        std::swap_ranges(top, top + static_cast<std::ptrdiff_t>(row_bytes), bottom);
    }

    errno = 0;
    if (stbi_write_png(path.c_str(), width, height, 3, pixels.data(),
                       static_cast<int>(row_bytes)) == 0) {
        std::string reason = errno != 0 ? std::strerror(errno) : "write failed";
        throw IoError("cannot write screenshot '" + path + "': " + reason, path);
    }
}

}  // namespace sylva::studio
