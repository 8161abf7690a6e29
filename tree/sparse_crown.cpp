#include "tree/sparse_crown.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <numeric>
#include <vector>

#include "lowpoly/merge_meshes.h"

namespace sylva {
namespace {

// A connected piece of the crown: the mean of its vertices and their mean distance from it.
struct Piece {
    glm::vec3 center{0.0f};
    float radius = 0.0f;
};

std::vector<Piece> pieces_of(const Mesh& crown) {
    std::size_t count = 0;
    const std::vector<std::uint32_t> label = component_of_triangles(crown, count);
    std::vector<Piece> pieces(count);
    // A vertex belongs to the piece of any triangle using it (pieces share no vertex).
    std::vector<std::uint32_t> of_vertex(crown.positions.size(),
                                         std::numeric_limits<std::uint32_t>::max());
    for (std::size_t t = 0; t < crown.triangles.size(); ++t) {
        for (std::uint32_t v : crown.triangles[t]) of_vertex[v] = label[t];
    }
    std::vector<std::size_t> vertices(count, 0);
    for (std::size_t v = 0; v < of_vertex.size(); ++v) {
        if (of_vertex[v] >= count) continue;
        pieces[of_vertex[v]].center += crown.positions[v];
        ++vertices[of_vertex[v]];
    }
    for (std::size_t k = 0; k < count; ++k)
        pieces[k].center /= static_cast<float>(std::max<std::size_t>(vertices[k], 1));
    for (std::size_t v = 0; v < of_vertex.size(); ++v)
        if (of_vertex[v] < count)
            pieces[of_vertex[v]].radius +=
                glm::distance(crown.positions[v], pieces[of_vertex[v]].center);
    for (std::size_t k = 0; k < count; ++k)
        pieces[k].radius /= static_cast<float>(std::max<std::size_t>(vertices[k], 1));
    return pieces;
}

// Regular polyhedra of circumradius 1 about the origin: corners and faces (any winding; the
// faces are turned outward when drawn).
struct Polyhedron {
    std::vector<glm::vec3> corners;
    std::vector<std::array<std::uint32_t, 3>> faces;
};

Polyhedron polyhedron(std::size_t faces) {
    Polyhedron p;
    if (faces >= 8) {  // octahedron
        p.corners = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
        for (std::uint32_t y : {2u, 3u})
            for (std::uint32_t x : {0u, 1u})
                for (std::uint32_t z : {4u, 5u}) p.faces.push_back({x, y, z});
    } else if (faces >= 6) {  // triangular bipyramid
        for (int j = 0; j < 3; ++j) {
            const float a = 2.0f * std::numbers::pi_v<float> * static_cast<float>(j) / 3.0f;
            p.corners.push_back({std::cos(a), 0.0f, std::sin(a)});
        }
        p.corners.push_back({0, 1, 0});
        p.corners.push_back({0, -1, 0});
        for (std::uint32_t j = 0; j < 3; ++j)
            for (std::uint32_t pole : {3u, 4u}) p.faces.push_back({j, (j + 1) % 3, pole});
    } else {  // tetrahedron
        const float s = 1.0f / std::sqrt(3.0f);
        p.corners = {{s, s, s}, {s, -s, -s}, {-s, s, -s}, {-s, -s, s}};
        p.faces = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
    }
    return p;
}

double area_of(const Polyhedron& p) {
    double area = 0.0;
    for (const auto& f : p.faces)
        area += 0.5 * glm::length(glm::cross(p.corners[f[1]] - p.corners[f[0]],
                                             p.corners[f[2]] - p.corners[f[0]]));
    return area;
}

constexpr float kGoldenAngle = 2.39996323f;  // radians

}  // namespace

std::size_t sparse_crown_pieces(const Mesh& crown) {
    const std::vector<Piece> pieces = pieces_of(crown);
    if (pieces.size() < 2) return 0;
    double spacing = 0.0;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        float nearest = std::numeric_limits<float>::max();
        std::size_t other = i;
        for (std::size_t j = 0; j < pieces.size(); ++j) {
            if (j == i) continue;
            const float d = glm::distance(pieces[i].center, pieces[j].center);
            if (d < nearest) {
                nearest = d;
                other = j;
            }
        }
        spacing += nearest / std::max({pieces[i].radius, pieces[other].radius, 1e-6f});
    }
    return spacing > kSparseCrownSpacing * static_cast<double>(pieces.size()) ? pieces.size() : 0;
}

Mesh sparse_crown_polyhedra(const Mesh& crown, std::size_t budget) {
    Mesh out;
    const std::vector<Piece> pieces = pieces_of(crown);
    if (pieces.empty() || budget < 4) return out;
    const std::size_t faces = std::min<std::size_t>(budget / pieces.size(), 8);
    const Polyhedron shape = polyhedron(std::max<std::size_t>(faces, 4));
    const std::size_t each = shape.faces.size();
    // The largest pieces that fit, drawn in the crown's order.
    std::vector<std::size_t> order(pieces.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return pieces[a].radius > pieces[b].radius;
    });
    std::vector<char> kept(pieces.size(), 0);
    for (std::size_t r = 0; r < std::min(pieces.size(), budget / each); ++r) kept[order[r]] = 1;
    const double unit_area = area_of(shape);
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        if (!kept[k]) continue;
        const Piece& piece = pieces[k];
        // The area of the smooth ball the piece stands for: 4 pi r^2.
        const float scale = static_cast<float>(
            std::sqrt(4.0 * std::numbers::pi * piece.radius * piece.radius / unit_area));
        const float turn = kGoldenAngle * static_cast<float>(k);
        const float c = std::cos(turn), s = std::sin(turn);
        const auto first = static_cast<std::uint32_t>(out.positions.size());
        for (const glm::vec3& q : shape.corners)
            out.positions.push_back(piece.center +
                                    scale * glm::vec3(c * q.x + s * q.z, q.y, -s * q.x + c * q.z));
        for (const auto& f : shape.faces) {
            std::array<std::uint32_t, 3> t = {first + f[0], first + f[1], first + f[2]};
            const glm::vec3 a = out.positions[t[0]], b = out.positions[t[1]],
                            d = out.positions[t[2]];
            if (glm::dot(glm::cross(b - a, d - a), (a + b + d) / 3.0f - piece.center) < 0.0f)
                std::swap(t[1], t[2]);
            out.triangles.push_back(t);
        }
    }
    return out;
}

}  // namespace sylva
