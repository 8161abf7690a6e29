// Checks that a sylva-studio screenshot shows a tree and not a blank or broken frame.
//
// usage: check_screenshot IMAGE.png WIDTH HEIGHT
//
// The criterion relies only on colours the studio guarantees: the background and the ground
// grid are grey-blue (blue >= red) and the ImGui theme is blue-grey, while lit or shadowed
// bark is warm (red clearly above blue). So a "bark pixel" is one with red > blue + 20 and
// red >= green and red > 40. The image passes when
//   - it has the expected size,
//   - bark pixels cover between 0.5% and 60% of it: a bare tree of thin branches fills only
//     1-3% of a 1280x800 frame (about 25,000 pixels), a blank or tree-less frame has none,
//     and a frame filled by a too-close camera has more than 60%,
//   - all four corners are dark grey-blue backdrop (not a uniform fill, not a tree filling
//     the window, not a black or white frame),
//   - the bark pixels' centroid lies in the middle half of the width (the tree is framed).
// Any uniform image fails: without bark on the coverage test, with bark on the corner test.
//
// The implementation comes from libstb (pkg-config stb), so STB_IMAGE_IMPLEMENTATION is not
// defined here: it would duplicate the symbols libstb exports.
#include <stb/stb_image.h>

#include <cstdio>
#include <cstdlib>
#include <memory>

namespace {

struct Rgb {
    int r, g, b;
};

bool is_bark(Rgb c) {
    return c.r > c.b + 20 && c.r >= c.g && c.r > 40;
}

// The backdrop is dark grey-blue: every channel low, blue not below red.
bool is_backdrop_like(Rgb c) {
    return c.r < 90 && c.g < 90 && c.b < 100 && c.b >= c.r;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: check_screenshot IMAGE.png WIDTH HEIGHT\n");
        return 2;
    }
    const char* path = argv[1];
    const int expected_width = std::atoi(argv[2]);
    const int expected_height = std::atoi(argv[3]);

    int width = 0, height = 0, channels = 0;
    std::unique_ptr<unsigned char, void (*)(void*)> pixels(
        stbi_load(path, &width, &height, &channels, 3), stbi_image_free);
    if (!pixels) {
        std::fprintf(stderr, "FAIL: cannot load '%s': %s\n", path, stbi_failure_reason());
        return 1;
    }
    auto at = [&](int x, int y) {
        const unsigned char* p = pixels.get() + 3 * (static_cast<long>(y) * width + x);
        return Rgb{p[0], p[1], p[2]};
    };

    bool ok = true;
    if (width != expected_width || height != expected_height) {
        std::fprintf(stderr, "FAIL: size %dx%d, expected %dx%d\n", width, height, expected_width,
                     expected_height);
        return 1;
    }

    long bark = 0;
    double sum_x = 0, sum_y = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            if (is_bark(at(x, y))) {
                ++bark;
                sum_x += x;
                sum_y += y;
            }
        }
    }
    const double total = static_cast<double>(width) * height;
    const double fraction = bark / total;
    std::printf("%s: %dx%d, bark pixels %.2f%%", path, width, height, 100.0 * fraction);
    if (bark > 0) {
        std::printf(", centroid (%.0f, %.0f)", sum_x / bark, sum_y / bark);
    }
    std::printf("\n");

    if (fraction < 0.005) {
        std::fprintf(stderr, "FAIL: bark colour covers %.2f%% of the image, expected > 0.5%%\n",
                     100.0 * fraction);
        ok = false;
    }
    if (fraction > 0.60) {
        std::fprintf(stderr, "FAIL: bark colour covers %.2f%% of the image, expected < 60%%\n",
                     100.0 * fraction);
        ok = false;
    }
    const Rgb corners[] = {at(0, 0), at(width - 1, 0), at(0, height - 1),
                           at(width - 1, height - 1)};
    for (const Rgb& c : corners) {
        if (is_bark(c) || !is_backdrop_like(c)) {
            std::fprintf(stderr, "FAIL: corner pixel (%d, %d, %d) is not backdrop grey-blue\n", c.r,
                         c.g, c.b);
            ok = false;
        }
    }
    if (bark > 0) {
        const double cx = sum_x / bark;
        if (cx < 0.25 * width || cx > 0.75 * width) {
            std::fprintf(stderr, "FAIL: the tree's centroid x = %.0f is outside the middle half\n",
                         cx);
            ok = false;
        }
    }
    std::printf(ok ? "PASS\n" : "FAIL\n");
    return ok ? 0 : 1;
}
