#include "lowpoly/piece_scaling.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <vector>

#include "lowpoly/merge_meshes.h"

namespace sylva {
namespace {

struct Piece {
    double area = 0.0;
    std::size_t triangles = 0;
    glm::dvec3 centroid{0.0};  // area-weighted centre of its triangles
    glm::vec3 low{std::numeric_limits<float>::max()};
    glm::vec3 high{std::numeric_limits<float>::lowest()};
};

// The pieces of `mesh` and, per vertex, the index of its piece (or -1 when unused).
std::vector<Piece> pieces_of(const Mesh& mesh, std::vector<int>& piece_of_vertex) {
    std::size_t count = 0;
    const std::vector<std::uint32_t> component = component_of_triangles(mesh, count);
    piece_of_vertex.assign(mesh.positions.size(), -1);
    std::vector<Piece> pieces(count);
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const auto& t = mesh.triangles[i];
        const int k = static_cast<int>(component[i]);
        Piece& piece = pieces[static_cast<std::size_t>(k)];
        const glm::vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]],
                        c = mesh.positions[t[2]];
        const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
        piece.area += area;
        ++piece.triangles;
        piece.centroid += area * glm::dvec3(a + b + c) / 3.0;
        for (std::uint32_t v : t) {
            piece_of_vertex[v] = k;
            piece.low = glm::min(piece.low, mesh.positions[v]);
            piece.high = glm::max(piece.high, mesh.positions[v]);
        }
    }
    for (Piece& piece : pieces)
        if (piece.area > 0.0) piece.centroid /= piece.area;
    return pieces;
}

// The area of the smooth surface a piece of `triangles` stands for: a polyhedron of n
// triangles with its corners on a sphere covers about 1 - 5 / n of its area (an octahedron
// 0.55, an icosahedron 0.76, the icosahedron split once 0.93), so a marching-cubes ball of a
// few dozen triangles is itself a tenth smaller than the ball; at most twice the area.
double smooth_area(const Piece& piece) {
    constexpr double kShortfall = 5.0;
    return piece.area / std::max(0.5, 1.0 - kShortfall / static_cast<double>(piece.triangles));
}

bool holds(const Piece& box, const glm::dvec3& p) {
    return p.x >= box.low.x && p.y >= box.low.y && p.z >= box.low.z && p.x <= box.high.x &&
           p.y <= box.high.y && p.z <= box.high.z;
}

// The piece of `candidates` whose box holds `p` and whose centroid is nearest it, or -1.
int nearest_holding(const std::vector<Piece>& candidates, const glm::dvec3& p) {
    int best = -1;
    double best_d2 = std::numeric_limits<double>::max();
    for (std::size_t k = 0; k < candidates.size(); ++k) {
        if (!holds(candidates[k], p)) continue;
        const glm::dvec3 d = candidates[k].centroid - p;
        const double d2 = glm::dot(d, d);
        if (d2 < best_d2) {
            best_d2 = d2;
            best = static_cast<int>(k);
        }
    }
    return best;
}

}  // namespace

PieceScaling restore_piece_areas(Mesh& reduced, const Mesh& source, float most) {
    PieceScaling out;
    std::vector<int> reduced_piece, source_piece;
    const std::vector<Piece> now = pieces_of(reduced, reduced_piece);
    const std::vector<Piece> was = pieces_of(source, source_piece);
    // Each reduced piece's source, and how many reduced pieces claim each source piece.
    std::vector<int> match(now.size(), -1);
    std::vector<int> claims(was.size(), 0);
    for (std::size_t k = 0; k < now.size(); ++k) {
        match[k] = nearest_holding(was, now[k].centroid);
        if (match[k] >= 0) ++claims[static_cast<std::size_t>(match[k])];
    }
    std::vector<double> factor(now.size(), 1.0);
    for (std::size_t k = 0; k < now.size(); ++k) {
        if (match[k] < 0 || now[k].area <= 0.0) continue;
        const Piece& from = was[static_cast<std::size_t>(match[k])];
        if (claims[static_cast<std::size_t>(match[k])] != 1) continue;
        const double f =
            std::min(std::sqrt(smooth_area(from) / now[k].area), static_cast<double>(most));
        if (f <= 1.0) continue;
        factor[k] = f;
        ++out.scaled;
        out.largest = std::max(out.largest, static_cast<float>(f));
    }
    for (std::size_t v = 0; v < reduced.positions.size(); ++v) {
        const int k = reduced_piece[v];
        if (k < 0 || factor[static_cast<std::size_t>(k)] == 1.0) continue;
        const Piece& piece = now[static_cast<std::size_t>(k)];
        const glm::dvec3 p(reduced.positions[v]);
        reduced.positions[v] =
            glm::vec3(piece.centroid + factor[static_cast<std::size_t>(k)] * (p - piece.centroid));
    }
    return out;
}

}  // namespace sylva
