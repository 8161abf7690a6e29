#include <gtest/gtest.h>

#include "lowpoly/fidelity.h"
#include "lowpoly/merge_meshes.h"
#include "lowpoly/surface_sampling.h"
#include "lowpoly/triangle_bvh.h"
#include "marching/marching_cubes.h"
#include "marching/mesh_checks.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace sylva {
namespace {

Mesh sphere(int resolution, float radius = 1.0f, glm::vec3 center = glm::vec3(0.0f)) {
    ScalarField f = [=](const glm::vec3& p) { return glm::length(p - center) - radius; };
    MarchingCubesSettings s;
    s.resolution = resolution;
    return marching_cubes(f, Box{center - glm::vec3(radius), center + glm::vec3(radius)}, s);
}

// Axis-aligned unit cube [0,1]^3, outward-facing.
Mesh cube() {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                   {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    m.triangles = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                   {3, 7, 6}, {3, 6, 2}, {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}};
    return m;
}

TEST(TriangleBvh, MatchesBruteForce) {
    const Mesh m = sphere(24);
    const TriangleBvh bvh(m);
    EXPECT_EQ(bvh.size(), m.triangles.size());
    const std::vector<glm::vec3> probes = sample_surface(sphere(10, 1.6f), 300, 7);
    for (const glm::vec3& p : probes) {
        float brute = std::numeric_limits<float>::infinity();
        for (const auto& t : m.triangles) {
            // Dense sampling of the triangle is too coarse; use the BVH's own hit and check
            // it against the distance to every vertex and the plane bound instead.
            for (std::uint32_t i : t) brute = std::min(brute, glm::length(m.positions[i] - p));
        }
        const TriangleBvh::Hit hit = bvh.closest(p);
        EXPECT_LE(hit.distance, brute + 1e-5f);
        EXPECT_NEAR(glm::length(hit.point - p), hit.distance, 1e-5f);
        // Points 1.6 from the centre are ~0.6 from a unit sphere.
        EXPECT_NEAR(hit.distance, 0.6f, 0.02f);
    }
}

TEST(TriangleBvh, KnownDistancesToACube) {
    const TriangleBvh bvh(cube());
    EXPECT_NEAR(bvh.distance({0.5f, 0.5f, 2.0f}), 1.0f, 1e-6f);   // above a face
    EXPECT_NEAR(bvh.distance({2.0f, 2.0f, 0.5f}), std::sqrt(2.0f), 1e-6f);  // off an edge
    EXPECT_NEAR(bvh.distance({2.0f, 2.0f, 2.0f}), std::sqrt(3.0f), 1e-6f);  // off a corner
    EXPECT_NEAR(bvh.distance({0.5f, 0.5f, 0.4f}), 0.4f, 1e-6f);   // inside: to the nearest face
    EXPECT_TRUE(std::isinf(TriangleBvh(Mesh{}).distance({0, 0, 0})));
}

TEST(SurfaceSampling, UniformByAreaAndSeeded) {
    const Mesh m = cube();
    const auto a = sample_surface(m, 6000, 3);
    EXPECT_EQ(a, sample_surface(m, 6000, 3));
    EXPECT_NE(a, sample_surface(m, 6000, 4));
    int top = 0;
    for (const glm::vec3& p : a) {
        EXPECT_GE(p.x, -1e-6f);
        EXPECT_LE(p.x, 1.0f + 1e-6f);
        if (p.z > 1.0f - 1e-6f) ++top;
    }
    EXPECT_NEAR(top / 6000.0, 1.0 / 6.0, 0.02);
    EXPECT_TRUE(sample_surface(Mesh{}, 10).empty());
}

TEST(Fidelity, ZeroForIdenticalMeshes) {
    const Mesh m = sphere(32);
    const Fidelity f = measure_fidelity(m, m);
    EXPECT_LT(f.mean, 1e-6);
    EXPECT_LT(f.max, 1e-5);
    EXPECT_NEAR(f.height, 2.0, 0.05);
    EXPECT_EQ(f.samples, FidelitySettings{}.samples);
}

TEST(Fidelity, KnownOffsetInPercentOfHeight) {
    // A sphere of radius 1.1 against one of radius 1 (height 2): 0.1 everywhere = 5 %.
    const Mesh reference = sphere(96, 1.0f);
    const Mesh bigger = sphere(96, 1.1f);
    const Fidelity f = measure_fidelity(bigger, reference);
    EXPECT_NEAR(f.mean, 0.1, 0.01);
    EXPECT_NEAR(f.mean_percent, 5.0, 0.5);
    EXPECT_GE(f.max, f.mean);
    EXPECT_LT(f.max, 0.12);

    FidelitySettings s;
    s.height = 10.0;
    EXPECT_NEAR(measure_fidelity(bigger, reference, s).mean_percent, 1.0, 0.1);
}

TEST(Fidelity, OneSided) {
    // A small sphere on the surface of a big one: from the small one, everything is near.
    // From the big one, most of it is far from the small one.
    const Mesh big = sphere(48, 1.0f);
    const Mesh small = sphere(48, 0.1f, glm::vec3(0.0f, 1.0f, 0.0f));
    const Mesh* both[] = {&big, &small};
    const Mesh reference = merge_meshes(both);
    EXPECT_LT(measure_fidelity(small, reference).max, 0.11);
    EXPECT_GT(measure_fidelity(reference, small).mean, 0.5);
}

TEST(Fidelity, RejectsAnEmptyReference) {
    EXPECT_THROW(measure_fidelity(cube(), Mesh{}), std::invalid_argument);
}

TEST(MergeMeshes, ShiftsIndices) {
    const Mesh a = cube();
    const Mesh* parts[] = {&a, nullptr, &a};
    const Mesh m = merge_meshes(parts);
    EXPECT_EQ(m.positions.size(), 16u);
    EXPECT_EQ(m.triangles.size(), 24u);
    EXPECT_EQ(m.triangles[12][0], a.triangles[0][0] + 8);
    EXPECT_EQ(check_topology(m).is_closed_manifold(), true);
}

}  // namespace
}  // namespace sylva
