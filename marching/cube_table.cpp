#include "marching/cube_table.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <vector>

namespace sylva::detail {
namespace {

// Face f lies at coordinate f % 2 of axis f / 2.

constexpr int corner_index(const std::array<int, 3>& c) {
    return c[0] | c[1] << 1 | c[2] << 2;
}

// The two axes other than `axis`, increasing.
constexpr std::array<int, 2> other_axes(int axis) {
    return axis == 0   ? std::array<int, 2>{1, 2}
           : axis == 1 ? std::array<int, 2>{0, 2}
                       : std::array<int, 2>{0, 1};
}

constexpr int edge_index(int axis, const std::array<int, 3>& c) {
    const auto [lo, hi] = other_axes(axis);
    return axis * 4 + c[lo] + 2 * c[hi];
}

// Bitmask of the two cube faces that contain edge e.
constexpr std::uint8_t edge_faces(int e) {
    const auto [lo, hi] = other_axes(e / 4);
    return static_cast<std::uint8_t>(1u << (2 * lo + (e & 1)) | 1u << (2 * hi + (e >> 1 & 1)));
}

// A cube face seen in its canonical frame (u, v) = its two axes in increasing global order.
// corners[k] are (u, v) = (0,0), (1,0), (1,1), (0,1): the order in which both cubes sharing
// the face read its samples, so the decider sees the same numbers in the same order.
// edges[k] joins corners[k] and corners[k + 1].
struct Face {
    std::array<int, 4> corners;
    std::array<int, 4> edges;
    // The (u, v) frame is clockwise seen from outside the cube.
    bool clockwise;
};

constexpr Face make_face(int f) {
    const int axis = f / 2;
    const int side = f % 2;
    const auto [u, v] = other_axes(axis);
    constexpr std::array<std::array<int, 2>, 4> uv{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
    Face face{};
    for (int k = 0; k < 4; ++k) {
        std::array<int, 3> c{};
        c[axis] = side;
        c[u] = uv[k][0];
        c[v] = uv[k][1];
        face.corners[k] = corner_index(c);
    }
    for (int k = 0; k < 4; ++k) {
        std::array<int, 3> c{};
        c[axis] = side;
        // Edges 0 and 2 run along u at v = 0 and v = 1; edges 1 and 3 along v at u = 1 and 0.
        const bool along_u = k % 2 == 0;
        c[u] = along_u ? 0 : (k == 1 ? 1 : 0);
        c[v] = along_u ? (k == 2 ? 1 : 0) : 0;
        face.edges[k] = edge_index(along_u ? u : v, c);
    }
    // u x v is +x, -y, +z for axis 0, 1, 2; the outward normal is -axis on side 0.
    const bool uv_normal_positive = axis != 1;
    face.clockwise = uv_normal_positive != (side == 1);
    return face;
}

constexpr std::array<Face, 6> kFaces{make_face(0), make_face(1), make_face(2),
                                     make_face(3), make_face(4), make_face(5)};

// The numbering in cube_table.h must match the one the faces are built from.
static_assert(edge_origin(5)[0] == 1 && edge_origin(5)[1] == 0 && edge_origin(5)[2] == 0);
static_assert(edge_index(1, edge_origin(6)) == 6 && edge_index(2, edge_origin(11)) == 11);

// Faces whose samples alternate in sign around the square, for each corner configuration.
std::uint8_t ambiguous_faces(unsigned config) {
    std::uint8_t mask = 0;
    for (int f = 0; f < 6; ++f) {
        const auto& c = kFaces[f].corners;
        const bool i0 = config >> c[0] & 1u, i1 = config >> c[1] & 1u;
        const bool i2 = config >> c[2] & 1u, i3 = config >> c[3] & 1u;
        if (i0 == i2 && i1 == i3 && i0 != i1) mask |= static_cast<std::uint8_t>(1u << f);
    }
    return mask;
}

// The one generic routine behind the case table. `joined` bit f says the bilinear saddle of
// ambiguous face f is inside, so the face's two inside corners connect through it; the bit
// is ignored on the other faces.
//
// Each face contributes contour segments oriented so that, seen from outside the cube, the
// inside is on their right. Every crossed edge lies on two faces and is the end of one
// segment and the start of another, so the segments chain into closed loops; the cube
// across a face reads the same samples and the same decision, and with its opposite normal
// runs the shared segments backwards. Fanned loops then give triangles that are
// counter-clockwise seen from outside and whose edges pair up across the whole grid.
CubeCase build_case(unsigned config, unsigned joined) {
    std::array<int, 12> next;
    next.fill(-1);
    const auto add_segment = [&](const Face& face, int from, int to) {
        if (face.clockwise) std::swap(from, to);
        assert(next[face.edges[from]] == -1);
        next[face.edges[from]] = face.edges[to];
    };
    const std::uint8_t ambiguous = ambiguous_faces(config);
    for (int f = 0; f < 6; ++f) {
        const Face& face = kFaces[f];
        std::array<bool, 4> in{};
        for (int k = 0; k < 4; ++k) in[k] = config >> face.corners[k] & 1u;
        // Walking counter-clockwise in (u, v), edge k "enters" the inside when corner k is
        // outside and corner k + 1 inside; a segment runs from an entry to an exit.
        if (ambiguous >> f & 1u) {
            const bool connected = joined >> f & 1u;
            for (int k = 0; k < 4; ++k) {
                const int prev = (k + 3) % 4;
                if (!connected && in[k]) add_segment(face, prev, k);  // cut off corner k
                if (connected && !in[k]) add_segment(face, k, prev);
            }
        } else {
            int entry = -1, leave = -1;
            for (int k = 0; k < 4; ++k) {
                if (in[k] == in[(k + 1) % 4]) continue;
                (in[k] ? leave : entry) = k;
            }
            if (entry >= 0) add_segment(face, entry, leave);
        }
    }

    CubeCase result;
    std::array<bool, 12> visited{};
    int count = 0;
    for (int start = 0; start < 12; ++start) {
        if (next[start] < 0 || visited[start]) continue;
        const int begin = count;
        // Every crossed edge starts exactly one segment, so the walk returns to `start`.
        for (int e = start; e >= 0 && !visited[e]; e = next[e]) {
            visited[e] = true;
            result.edges[count++] = static_cast<std::uint8_t>(e);
        }
        const int n = count - begin;
        assert(n >= 3 && result.loop_count < 4);
        const int loop = result.loop_count++;
        result.loop_size[loop] = static_cast<std::uint8_t>(n);
        // Up to five crossings a loop meets each face once, so no diagonal joins two
        // crossings on one face; quads pick their shorter diagonal at run time.
        if (n <= 4) continue;
        // A fan diagonal between two crossings on the same face would also be a candidate
        // diagonal of the cube across that face: two cubes could both use it and give an
        // edge with four triangles. That can only happen when an ambiguous face puts both
        // of its segments into one loop (6 or more crossings). Pick an apex that shares no
        // face with the crossings it connects to; if none exists, use a centre vertex whose
        // spokes belong to this cube alone.
        auto* loop_edges = &result.edges[begin];
        int apex = -1;
        for (int i = 0; i < n && apex < 0; ++i) {
            bool ok = true;
            for (int j = 0; j < n && ok; ++j) {
                if (j == i || j == (i + 1) % n || (j + 1) % n == i) continue;
                ok = (edge_faces(loop_edges[i]) & edge_faces(loop_edges[j])) == 0;
            }
            if (ok) apex = i;
        }
        if (apex < 0) {
            result.center_mask |= static_cast<std::uint8_t>(1u << loop);
        } else {
            std::rotate(loop_edges, loop_edges + apex, loop_edges + n);
        }
    }
    return result;
}

// Indexed by corner configuration | joined-face bits << 8.
const std::vector<CubeCase>& case_table() {
    static const std::vector<CubeCase> table = [] {
        std::vector<CubeCase> t(256 * 64);
        for (unsigned config = 1; config < 255; ++config) {
            const unsigned ambiguous = ambiguous_faces(config);
            // Only subsets of the ambiguous faces are ever looked up.
            for (unsigned joined = ambiguous;; joined = (joined - 1) & ambiguous) {
                t[config | joined << 8] = build_case(config, joined);
                if (joined == 0) break;
            }
        }
        return t;
    }();
    return table;
}

// Whether the bilinear interpolant of a face, read in canonical order a, b, c, d around it,
// is inside at its saddle point. Only called on ambiguous faces, where a and c share a sign
// and b and d the other. The saddle value is (ac - bd) / (a + c - b - d), and the
// denominator has the sign of the inside diagonal, so it is never zero here and only the
// sign of the numerator matters. Products of floats are exact in double, so the only
// rounding is the subtraction; a zero saddle counts as outside, like a zero sample.
bool saddle_inside(float a, float b, float c, float d) {
    if (!(std::isfinite(a) && std::isfinite(b) && std::isfinite(c) && std::isfinite(d))) {
        return false;
    }
    const double numerator = double(a) * double(c) - double(b) * double(d);
    return inside(a) ? numerator > 0.0 : numerator < 0.0;
}

// Keeps crossings off the grid corners, so that no two vertices of a cube coincide and any
// three of them span a proper triangle (three points inside distinct edges of a convex cube
// are never collinear).
constexpr double kMinEdgeFraction = 1e-3;

}  // namespace

const CubeCase& cube_case(unsigned config, const std::array<float, 8>& v) {
    static const std::vector<CubeCase>& table = case_table();
    unsigned joined = 0;
    for (int f = 0; f < 6; ++f) {
        const auto& q = kFaces[f].corners;
        // Only ambiguous faces set a bit, matching the keys of the table.
        const bool i0 = config >> q[0] & 1u, i1 = config >> q[1] & 1u;
        if (i0 != bool(config >> q[2] & 1u) || i1 != bool(config >> q[3] & 1u) || i0 == i1) {
            continue;
        }
        if (saddle_inside(v[q[0]], v[q[1]], v[q[2]], v[q[3]])) joined |= 1u << f;
    }
    return table[config | joined << 8];
}

double crossing_fraction(float v0, float v1) {
    if (std::isnan(v0) || std::isnan(v1)) return 0.5;
    const double t = double(v0) / (double(v0) - double(v1));
    return std::clamp(t, kMinEdgeFraction, 1.0 - kMinEdgeFraction);
}

}  // namespace sylva::detail
