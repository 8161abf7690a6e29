// Checks that a sylva-studio screenshot shows a tree and not a blank or broken frame.
//
// usage: check_screenshot IMAGE.png WIDTH HEIGHT
//
// The criterion relies only on colours the studio guarantees: the background, the ground
// grid and the ImGui panels are grey or grey-blue (blue >= green, blue >= red), while a tree
// is bark (warm: red clearly above blue) or foliage (green clearly above red and blue). So a
// "tree pixel" is one with
//   bark:    red > blue + 20 and red >= green and red > 40, or
//   foliage: green > red + 8 and green > blue + 8 and green > 40.
// The image passes when
//   - it has the expected size,
//   - tree pixels cover between 0.5% and 60% of it: a bare tree of thin branches fills
//     only 1-3% of a 1280x800 frame, a blank or tree-less frame has none, and a frame
//     filled by a too-close camera has more than 60%,
//   - all four corners are dark grey or grey-blue (backdrop or panels: not a uniform fill,
//     not a tree filling the window, not a black or white frame),
//   - the tree pixels' centroid lies in the middle half of the width (the tree is framed).
// Any uniform image fails: without tree pixels on the coverage test, with them on the
// corner test.
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

bool is_foliage(Rgb c) {
    return c.g > c.r + 8 && c.g > c.b + 8 && c.g > 40;
}

bool is_tree(Rgb c) {
    return is_bark(c) || is_foliage(c);
}

// The backdrop and the panels are dark grey or grey-blue: every channel low, blue not below
// red.
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

    long tree = 0, bark = 0;
    double sum_x = 0, sum_y = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            if (is_bark(at(x, y))) ++bark;
            if (is_tree(at(x, y))) {
                ++tree;
                sum_x += x;
                sum_y += y;
            }
        }
    }
    const double total = static_cast<double>(width) * height;
    const double fraction = tree / total;
    std::printf("%s: %dx%d, tree pixels %.2f%% (bark %.2f%%)", path, width, height,
                100.0 * fraction, 100.0 * bark / total);
    if (tree > 0) {
        std::printf(", centroid (%.0f, %.0f)", sum_x / tree, sum_y / tree);
    }
    std::printf("\n");

    if (fraction < 0.005) {
        std::fprintf(stderr, "FAIL: tree colours cover %.2f%% of the image, expected > 0.5%%\n",
                     100.0 * fraction);
        ok = false;
    }
    if (fraction > 0.60) {
        std::fprintf(stderr, "FAIL: tree colours cover %.2f%% of the image, expected < 60%%\n",
                     100.0 * fraction);
        ok = false;
    }
    const Rgb corners[] = {at(0, 0), at(width - 1, 0), at(0, height - 1),
                           at(width - 1, height - 1)};
    for (const Rgb& c : corners) {
        if (is_tree(c) || !is_backdrop_like(c)) {
            std::fprintf(stderr, "FAIL: corner pixel (%d, %d, %d) is not backdrop grey-blue\n", c.r,
                         c.g, c.b);
            ok = false;
        }
    }
    if (tree > 0) {
        const double cx = sum_x / tree;
        if (cx < 0.25 * width || cx > 0.75 * width) {
            std::fprintf(stderr, "FAIL: the tree's centroid x = %.0f is outside the middle half\n",
                         cx);
            ok = false;
        }
    }
    std::printf(ok ? "PASS\n" : "FAIL\n");
    return ok ? 0 : 1;
}
