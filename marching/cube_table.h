// The per-cube part of marching cubes, shared by the dense and sparse meshers: which surface
// a cube holds given its eight samples, and where a crossed edge is cut.
//
// Watertightness rests here: a cube face decides its contour from its four samples alone,
// read in a canonical corner order (asymptotic decider), so the two cubes sharing a face
// always agree, whichever mesher, block or thread visits them.
#pragma once

#include <array>
#include <cstdint>

namespace sylva::detail {

// Cube-local numbering. Corner c has bits (x, y, z) = (c & 1, c >> 1 & 1, c >> 2 & 1).
// Edge e runs along axis e / 4 from its lower corner; its low two bits are the coordinates
// of the other two axes, lower axis first, so edge 0 is the x edge at y = z = 0 and edge 11
// the z edge at x = y = 1.
constexpr int edge_axis(int e) {
    return e / 4;
}

// The lower corner of edge e, as (x, y, z) offsets in {0, 1}.
constexpr std::array<int, 3> edge_origin(int e) {
    const int axis = e / 4, b0 = e & 1, b1 = e >> 1 & 1;
    return axis == 0   ? std::array<int, 3>{0, b0, b1}
           : axis == 1 ? std::array<int, 3>{b0, 0, b1}
                       : std::array<int, 3>{b0, b1, 0};
}

// The surface inside one cube: closed loops of crossed edges, ready to triangulate.
struct CubeCase {
    std::uint8_t loop_count = 0;
    std::array<std::uint8_t, 4> loop_size{};  // at most 12 crossings, loops of 3 or more
    // Loops to triangulate around an added centre vertex: their fan would put a diagonal on
    // a cube face, where the neighbouring cube could use it too.
    std::uint8_t center_mask = 0;
    // The loops one after another. Fan loops of 5 or more from their first edge; quads may
    // take either diagonal.
    std::array<std::uint8_t, 12> edges{};
};

// A sample counts as inside only when strictly negative; NaN (the meshers' "no usable
// value") is outside.
inline bool inside(float value) {
    return value < 0.0f;
}

// Bit c set when corner c is inside. Inline: it runs once per cell and decides almost all
// of them (0 and 255 hold no surface).
inline unsigned corner_config(const std::array<float, 8>& v) {
    return unsigned(inside(v[0])) | unsigned(inside(v[1])) << 1 | unsigned(inside(v[2])) << 2 |
           unsigned(inside(v[3])) << 3 | unsigned(inside(v[4])) << 4 | unsigned(inside(v[5])) << 5 |
           unsigned(inside(v[6])) << 6 | unsigned(inside(v[7])) << 7;
}

// The surface of a cube whose corner samples are v[c], given config = corner_config(v),
// which must be neither 0 nor 255. Builds the case table on first use (thread-safe).
const CubeCase& cube_case(unsigned config, const std::array<float, 8>& v);

// Where the edge from a sample v0 to a sample v1 of the other sign is cut, as a fraction of
// its length from v0: linear interpolation, kept off the end points; the midpoint when either
// sample is NaN.
double crossing_fraction(float v0, float v1);

}  // namespace sylva::detail
