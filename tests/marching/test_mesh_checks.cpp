#include <gtest/gtest.h>

#include <cmath>

#include "marching/mesh_checks.h"

namespace sylva {
namespace {

// Right-angled tetrahedron at the origin, faces counter-clockwise seen from outside.
Mesh tetrahedron() {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return mesh;
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
    EXPECT_EQ(check_topology(mesh).degenerate_triangles, 3u);
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
