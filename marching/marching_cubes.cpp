#include "marching/marching_cubes.h"

#include "marching/grid.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace sylva {
namespace {

// Cube-local numbering. Corner c has bits (x, y, z) = (c & 1, c >> 1 & 1, c >> 2 & 1).
// Edge e runs along axis e / 4; its low two bits are the coordinates of the other two axes,
// lower axis first, so edge 0 is the x edge at y = z = 0 and edge 11 the z edge at x = y = 1.
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

// The surface inside one cube: closed loops of crossed edges, ready to triangulate.
struct CubeCase {
    std::uint8_t loop_count = 0;
    std::array<std::uint8_t, 4> loop_size{};  // at most 12 crossings, loops of 3 or more
    // Loops triangulated around an added centre vertex (see build_case).
    std::uint8_t center_mask = 0;
    std::array<std::uint8_t, 12> edges{};  // the loops one after another
};

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

// Indexed by corner configuration | joined-face bits << 8. Built once, on first use.
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

// Samples stored as NaN have no usable value: they are outside, and an edge that ends in one
// is crossed at its midpoint.
bool inside(float value) {
    return value < 0.0f;
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

double crossing_fraction(float v0, float v1) {
    if (std::isnan(v0) || std::isnan(v1)) return 0.5;
    const double t = double(v0) / (double(v0) - double(v1));
    return std::clamp(t, kMinEdgeFraction, 1.0 - kMinEdgeFraction);
}

class CubeMesher {
  public:
    CubeMesher(const ScalarField& field, const Grid& grid)
        : field_(field),
          grid_(grid),
          nx_(grid.nodes[0]),
          ny_(grid.nodes[1]),
          layer_size_(std::size_t(nx_) * std::size_t(ny_)),
          table_(case_table()) {
        for (auto& layer : samples_) layer.resize(layer_size_);
        for (auto& layer : x_ids_) layer.resize(layer_size_, kNone);
        for (auto& layer : y_ids_) layer.resize(layer_size_, kNone);
        z_ids_.resize(layer_size_, kNone);
    }

    Mesh run() {
        const int nz = grid_.nodes[2];
        sample_layer(0, samples_[0]);
        add_layer_vertices(0, samples_[0], x_ids_[0], y_ids_[0]);
        for (int k = 0; k + 1 < nz; ++k) {
            sample_layer(k + 1, samples_[1]);
            add_layer_vertices(k + 1, samples_[1], x_ids_[1], y_ids_[1]);
            add_z_vertices(k);
            march_slab();
            std::swap(samples_[0], samples_[1]);
            std::swap(x_ids_[0], x_ids_[1]);
            std::swap(y_ids_[0], y_ids_[1]);
        }
        return std::move(mesh_);
    }

  private:
    static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

    std::size_t at(int i, int j) const { return std::size_t(i) + std::size_t(nx_) * j; }

    glm::dvec3 node(int i, int j, int k) const {
        return grid_.origin + glm::dvec3(i, j, k) * grid_.h;
    }

    // Every node is evaluated exactly once. The outermost layer of nodes counts as outside
    // whatever the field says, so no face on the grid border is ever crossed and the mesh
    // closes even where the field is still negative there.
    void sample_layer(int k, std::vector<float>& out) {
        const bool border_layer = k == 0 || k == grid_.nodes[2] - 1;
        for (int j = 0; j < ny_; ++j) {
            for (int i = 0; i < nx_; ++i) {
                const float value = field_(glm::vec3(node(i, j, k)));
                const bool border =
                    border_layer || i == 0 || j == 0 || i == nx_ - 1 || j == ny_ - 1;
                const bool usable = std::isfinite(value) && !(border && inside(value));
                out[at(i, j)] = usable ? value : std::numeric_limits<float>::quiet_NaN();
            }
        }
    }

    std::uint32_t add_vertex(const glm::dvec3& position) {
        if (mesh_.positions.size() >= kNone) {
            throw std::length_error("marching_cubes: more than 2^32 - 1 vertices");
        }
        mesh_.positions.emplace_back(position);
        return static_cast<std::uint32_t>(mesh_.positions.size() - 1);
    }

    // The vertex on the edge from node (i, j, k) along `axis`, if the edge is crossed.
    std::uint32_t crossing(float v0, float v1, int i, int j, int k, int axis) {
        if (inside(v0) == inside(v1)) return kNone;
        glm::dvec3 p = node(i, j, k);
        p[axis] += crossing_fraction(v0, v1) * grid_.h;
        return add_vertex(p);
    }

    void add_layer_vertices(int k, const std::vector<float>& s, std::vector<std::uint32_t>& x_ids,
                            std::vector<std::uint32_t>& y_ids) {
        for (int j = 0; j < ny_; ++j) {
            for (int i = 0; i < nx_; ++i) {
                const float v = s[at(i, j)];
                if (i + 1 < nx_) x_ids[at(i, j)] = crossing(v, s[at(i + 1, j)], i, j, k, 0);
                if (j + 1 < ny_) y_ids[at(i, j)] = crossing(v, s[at(i, j + 1)], i, j, k, 1);
            }
        }
    }

    void add_z_vertices(int k) {
        for (int j = 0; j < ny_; ++j) {
            for (int i = 0; i < nx_; ++i) {
                z_ids_[at(i, j)] =
                    crossing(samples_[0][at(i, j)], samples_[1][at(i, j)], i, j, k, 2);
            }
        }
    }

    std::uint32_t edge_vertex(int e, int i, int j) const {
        const int b0 = e & 1, b1 = e >> 1 & 1;
        switch (e / 4) {
            case 0:
                return x_ids_[b1][at(i, j + b0)];
            case 1:
                return y_ids_[b1][at(i + b0, j)];
            default:
                return z_ids_[at(i + b0, j + b1)];
        }
    }

    void march_slab() {
        for (int j = 0; j + 1 < ny_; ++j) {
            // Corner c = x + 2y + 4z of cube (i, j) is rows[c >> 1][i + (c & 1)].
            const std::array<const float*, 4> rows{
                &samples_[0][at(0, j)], &samples_[0][at(0, j + 1)], &samples_[1][at(0, j)],
                &samples_[1][at(0, j + 1)]};
            for (int i = 0; i + 1 < nx_; ++i) {
                const std::array<float, 8> v{rows[0][i],     rows[0][i + 1], rows[1][i],
                                             rows[1][i + 1], rows[2][i],     rows[2][i + 1],
                                             rows[3][i],     rows[3][i + 1]};
                // Written out: this loop runs once per grid cell and dominates empty space.
                const unsigned config = unsigned(inside(v[0])) | unsigned(inside(v[1])) << 1 |
                                        unsigned(inside(v[2])) << 2 | unsigned(inside(v[3])) << 3 |
                                        unsigned(inside(v[4])) << 4 | unsigned(inside(v[5])) << 5 |
                                        unsigned(inside(v[6])) << 6 | unsigned(inside(v[7])) << 7;
                if (config == 0 || config == 255) continue;
                unsigned joined = 0;
                for (int f = 0; f < 6; ++f) {
                    const auto& q = kFaces[f].corners;
                    // Only ambiguous faces set a bit, matching the keys of the table.
                    const bool i0 = inside(v[q[0]]), i1 = inside(v[q[1]]);
                    if (i0 != inside(v[q[2]]) || i1 != inside(v[q[3]]) || i0 == i1) continue;
                    if (saddle_inside(v[q[0]], v[q[1]], v[q[2]], v[q[3]])) joined |= 1u << f;
                }
                emit(table_[config | joined << 8], i, j);
            }
        }
    }

    void add_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        mesh_.triangles.push_back({a, b, c});
    }

    void emit(const CubeCase& cube, int i, int j) {
        int offset = 0;
        for (int l = 0; l < cube.loop_count; ++l) {
            const int n = cube.loop_size[l];
            std::array<std::uint32_t, 12> ids;
            for (int m = 0; m < n; ++m) {
                ids[m] = edge_vertex(cube.edges[offset + m], i, j);
                assert(ids[m] != kNone);
            }
            offset += n;
            if (cube.center_mask >> l & 1u) {
                glm::dvec3 sum(0.0);
                for (int m = 0; m < n; ++m) sum += glm::dvec3(mesh_.positions[ids[m]]);
                const std::uint32_t center = add_vertex(sum / double(n));
                for (int m = 0; m < n; ++m) add_triangle(center, ids[m], ids[(m + 1) % n]);
            } else if (n == 4) {
                // Either diagonal is safe here; the shorter one gives better-shaped triangles.
                const auto& p = mesh_.positions;
                const float d02 = glm::distance(p[ids[0]], p[ids[2]]);
                const float d13 = glm::distance(p[ids[1]], p[ids[3]]);
                if (d02 <= d13) {
                    add_triangle(ids[0], ids[1], ids[2]);
                    add_triangle(ids[0], ids[2], ids[3]);
                } else {
                    add_triangle(ids[1], ids[2], ids[3]);
                    add_triangle(ids[1], ids[3], ids[0]);
                }
            } else {
                for (int m = 1; m + 1 < n; ++m) add_triangle(ids[0], ids[m], ids[m + 1]);
            }
        }
    }

    const ScalarField& field_;
    const Grid grid_;
    const int nx_;
    const int ny_;
    const std::size_t layer_size_;
    const std::vector<CubeCase>& table_;
    // Two node layers at a time: [0] is the slab's lower layer, [1] its upper.
    std::array<std::vector<float>, 2> samples_;
    // Vertex ids by lower node of their edge, so each crossing is created exactly once.
    std::array<std::vector<std::uint32_t>, 2> x_ids_;
    std::array<std::vector<std::uint32_t>, 2> y_ids_;
    std::vector<std::uint32_t> z_ids_;
    Mesh mesh_;
};

}  // namespace

Mesh marching_cubes(const ScalarField& field, const Box& box,
                    const MarchingCubesSettings& settings) {
    const Grid grid = make_grid(box, settings);
    return CubeMesher(field, grid).run();
}

}  // namespace sylva
