#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <map>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/mesh_checks.h"

namespace sylva {
namespace {

// Right-angled tetrahedron at the origin, faces counter-clockwise seen from outside.
Mesh tetrahedron() {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return mesh;
}

// check_topology the plain way: every use of every undirected edge in a map, every link
// component by flooding, to compare with the fast version on meshes with every defect.
MeshTopology reference_topology(const Mesh& mesh) {
    MeshTopology result;
    glm::dvec3 lo(0.0), hi(0.0);
    if (!mesh.positions.empty()) lo = hi = glm::dvec3(mesh.positions.front());
    for (const auto& p : mesh.positions) {
        lo = glm::min(lo, glm::dvec3(p));
        hi = glm::max(hi, glm::dvec3(p));
    }
    const double min_twice_area = 2e-12 * glm::dot(hi - lo, hi - lo);
    const std::size_t n = mesh.positions.size();
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<bool>> edges;  // forward?
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> links(n);
    for (const auto& t : mesh.triangles) {
        if (t[0] >= n || t[1] >= n || t[2] >= n || t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) {
            ++result.degenerate_triangles;
            continue;
        }
        const glm::dvec3 a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
        if (glm::length(glm::cross(b - a, c - a)) <= min_twice_area) ++result.zero_area_triangles;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t u = t[k], w = t[(k + 1) % 3];
            edges[{std::min(u, w), std::max(u, w)}].push_back(u < w);
            links[u].push_back({t[(k + 1) % 3], t[(k + 2) % 3]});
        }
    }
    for (const auto& [edge, uses] : edges) {
        if (uses.size() == 1) {
            ++result.boundary_edges;
        } else if (uses.size() >= 3) {
            ++result.non_manifold_edges;
        } else if (uses[0] == uses[1]) {
            ++result.misoriented_edges;
        }
    }
    for (const auto& link : links) {
        if (link.empty()) continue;
        std::set<std::uint32_t> unseen;
        for (const auto& [a, b] : link) unseen.insert({a, b});
        std::size_t components = 0;
        while (!unseen.empty()) {
            ++components;
            std::vector<std::uint32_t> stack = {*unseen.begin()};
            unseen.erase(unseen.begin());
            while (!stack.empty()) {
                const std::uint32_t x = stack.back();
                stack.pop_back();
                for (const auto& [a, b] : link) {
                    const std::uint32_t y = a == x ? b : b == x ? a : x;
                    if (y != x && unseen.erase(y)) stack.push_back(y);
                }
            }
        }
        if (components > 1) ++result.non_manifold_vertices;
    }
    return result;
}

void expect_same(const MeshTopology& a, const MeshTopology& b) {
    EXPECT_EQ(a.boundary_edges, b.boundary_edges);
    EXPECT_EQ(a.non_manifold_edges, b.non_manifold_edges);
    EXPECT_EQ(a.misoriented_edges, b.misoriented_edges);
    EXPECT_EQ(a.degenerate_triangles, b.degenerate_triangles);
    EXPECT_EQ(a.non_manifold_vertices, b.non_manifold_vertices);
    EXPECT_EQ(a.zero_area_triangles, b.zero_area_triangles);
}

// A closed grid-like surface (a torus of quads) that the random edits below then break:
// repeated and out-of-range indices, flipped, duplicated and removed triangles, fans glued
// at a vertex, a third triangle on an edge, collapsed (flat) positions.
Mesh torus(int rows, int columns) {
    Mesh mesh;
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < columns; ++j) {
            const float u = 6.2831853f * float(i) / float(rows);
            const float w = 6.2831853f * float(j) / float(columns);
            mesh.positions.push_back({(2.0f + std::cos(w)) * std::cos(u),
                                      (2.0f + std::cos(w)) * std::sin(u), std::sin(w)});
        }
    const auto at = [&](int i, int j) {
        return std::uint32_t((i % rows) * columns + (j % columns));
    };
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < columns; ++j) {
            mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return mesh;
}

TEST(MeshChecks, TorusIsClosed) {
    const Mesh mesh = torus(8, 6);
    EXPECT_TRUE(check_topology(mesh).is_closed_manifold()) << to_string(check_topology(mesh));
    expect_same(check_topology(mesh), reference_topology(mesh));
}

TEST(MeshChecks, AgreesWithAPlainCountOnBrokenMeshes) {
    std::mt19937 random(17);
    const auto below = [&](std::size_t n) {
        return std::uniform_int_distribution<std::size_t>(0, n - 1)(random);
    };
    for (int round = 0; round < 300; ++round) {
        Mesh mesh = torus(3 + int(below(6)), 3 + int(below(6)));
        const std::size_t vertices = mesh.positions.size();
        const int edits = int(below(12));
        for (int e = 0; e < edits; ++e) {
            auto& t = mesh.triangles[below(mesh.triangles.size())];
            switch (below(9)) {
                case 0:
                    t[below(3)] = std::uint32_t(below(vertices));
                    break;  // may repeat
                case 1:
                    std::swap(t[1], t[2]);
                    break;  // flipped
                case 2:
                    mesh.triangles.push_back(t);
                    break;  // duplicated
                case 3: {   // reversed copy
                    const auto copy = std::array<std::uint32_t, 3>{t[0], t[2], t[1]};
                    mesh.triangles.push_back(copy);
                    break;
                }
                case 4:  // removed: an open mesh
                    t = mesh.triangles.back();
                    mesh.triangles.pop_back();
                    break;
                case 5:
                    t[below(3)] = std::uint32_t(vertices + below(3));
                    break;  // out of range
                case 6: {   // a fan of a far vertex glued on: a bow-tie
                    const std::uint32_t base = std::uint32_t(mesh.positions.size());
                    mesh.positions.push_back({5.0f, 5.0f, 5.0f});
                    mesh.positions.push_back({6.0f, 5.0f, 5.0f});
                    mesh.triangles.push_back({t[0], base, base + 1});
                    break;
                }
                case 7: {  // a third triangle on an edge
                    const std::uint32_t apex = std::uint32_t(below(vertices));
                    mesh.triangles.push_back({t[0], t[1], apex});
                    break;
                }
                default:  // two vertices in one place: flat triangles
                    mesh.positions[below(vertices)] = mesh.positions[below(vertices)];
                    break;
            }
        }
        SCOPED_TRACE("round " + std::to_string(round));
        expect_same(check_topology(mesh), reference_topology(mesh));
    }
}

TEST(MeshChecks, SingleTriangleHasThreeBoundaryEdges) {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 2}};
    const MeshTopology topology = check_topology(mesh);
    EXPECT_EQ(topology.boundary_edges, 3u);
    EXPECT_EQ(topology.non_manifold_edges, 0u);
    EXPECT_EQ(topology.misoriented_edges, 0u);
    EXPECT_EQ(topology.degenerate_triangles, 0u);
    EXPECT_EQ(topology.non_manifold_vertices, 0u);
    EXPECT_FALSE(topology.is_closed_manifold());
    EXPECT_DOUBLE_EQ(surface_area(mesh), 0.5);
}

TEST(MeshChecks, TetrahedronIsClosedWithPositiveVolume) {
    const Mesh mesh = tetrahedron();
    EXPECT_TRUE(check_topology(mesh).is_closed_manifold());
    EXPECT_NEAR(enclosed_volume(mesh), 1.0 / 6.0, 1e-12);
    EXPECT_NEAR(surface_area(mesh), 1.5 + std::sqrt(3.0) / 2.0, 1e-7);
}

TEST(MeshChecks, VolumeDoesNotDependOnPlacement) {
    Mesh mesh = tetrahedron();
    for (auto& p : mesh.positions) p += glm::vec3(1000.0f, -2000.0f, 500.0f);
    EXPECT_NEAR(enclosed_volume(mesh), 1.0 / 6.0, 1e-9);
}

TEST(MeshChecks, FlippedFaceIsMisoriented) {
    Mesh mesh = tetrahedron();
    std::swap(mesh.triangles[3][1], mesh.triangles[3][2]);
    const MeshTopology topology = check_topology(mesh);
    EXPECT_EQ(topology.misoriented_edges, 3u);
    EXPECT_EQ(topology.boundary_edges, 0u);
    EXPECT_FALSE(topology.is_closed_manifold());
}

TEST(MeshChecks, InsideOutTetrahedronIsClosedWithNegativeVolume) {
    Mesh mesh = tetrahedron();
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
    EXPECT_TRUE(check_topology(mesh).is_closed_manifold());
    EXPECT_NEAR(enclosed_volume(mesh), -1.0 / 6.0, 1e-12);
}

TEST(MeshChecks, DegenerateTriangles) {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 2}, {0, 0, 3}, {0, 1, 7}};  // collinear, repeated, out of range
    EXPECT_EQ(check_topology(mesh).degenerate_triangles, 2u);
    EXPECT_EQ(check_topology(mesh).zero_area_triangles, 1u);
}

// Slivers of zero area (two vertices in one place) leave a closed surface closed: marching
// cubes makes them on fine grids and far from the origin, and such a mesh was reported
// open.
TEST(MeshChecks, ZeroAreaSliversLeaveAClosedMeshClosed) {
    Mesh mesh = torus(8, 6);
    mesh.positions[1] = mesh.positions[0];
    const MeshTopology topology = check_topology(mesh);
    EXPECT_TRUE(topology.is_closed_manifold()) << to_string(topology);
    EXPECT_EQ(topology.zero_area_triangles, 2u);
    EXPECT_EQ(topology.degenerate_triangles, 0u);
    EXPECT_NE(to_string(topology).find("zero-area 2"), std::string::npos);
}

TEST(MeshChecks, ThreeTrianglesOnOneEdgeAreNonManifold) {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
    mesh.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
    EXPECT_EQ(check_topology(mesh).non_manifold_edges, 1u);
}

TEST(MeshChecks, TwoTetrahedraSharingOneVertexMakeANonManifoldVertex) {
    // The second tetrahedron is the first reflected through its vertex 1 = (1, 0, 0); a
    // point reflection turns a mesh inside out, hence the swapped triangle corners.
    Mesh mesh = tetrahedron();
    const Mesh first = tetrahedron();
    mesh.positions.insert(mesh.positions.end(), {{2, 0, 0}, {2, -1, 0}, {2, 0, -1}});
    const std::uint32_t reflected[4] = {4, 1, 5, 6};
    for (const auto& t : first.triangles) {
        mesh.triangles.push_back({reflected[t[0]], reflected[t[2]], reflected[t[1]]});
    }
    const MeshTopology topology = check_topology(mesh);
    EXPECT_EQ(topology.non_manifold_vertices, 1u);
    EXPECT_EQ(topology.boundary_edges, 0u);
    EXPECT_EQ(topology.non_manifold_edges, 0u);
    EXPECT_EQ(topology.misoriented_edges, 0u);
    EXPECT_NEAR(enclosed_volume(mesh), 2.0 / 6.0, 1e-9);
}

TEST(MeshChecks, EmptyMeshIsClosed) {
    const Mesh mesh;
    EXPECT_TRUE(check_topology(mesh).is_closed_manifold());
    EXPECT_EQ(surface_area(mesh), 0.0);
    EXPECT_EQ(enclosed_volume(mesh), 0.0);
}

}  // namespace
}  // namespace sylva
