#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <stdexcept>

#include "core/errors.h"
#include "core/mesh_checks.h"
#include "lowpoly/fidelity.h"
#include "lowpoly/merge_meshes.h"
#include "lowpoly/surface_sampling.h"
#include "lowpoly/triangle_bvh.h"
#include "marching/marching_cubes.h"

namespace sylva {
namespace {

Mesh sphere(int resolution, float radius = 1.0f, glm::vec3 center = glm::vec3(0.0f)) {
    ScalarField f = [=](const glm::vec3& p) { return glm::length(p - center) - radius; };
    MeshSettings s;
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

// Independent of the BVH's closest-point routine: the plane distance when the projection
// falls inside the triangle, else the nearest of the three edges.
float segment_distance(glm::vec3 p, glm::vec3 a, glm::vec3 b) {
    const glm::vec3 ab = b - a;
    const float t = glm::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
    return glm::length(p - (a + t * ab));
}

float triangle_distance(glm::vec3 p, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    const glm::vec3 q = p - glm::dot(p - a, n) * n;
    const bool inside = glm::dot(glm::cross(b - a, q - a), n) >= 0 &&
                        glm::dot(glm::cross(c - b, q - b), n) >= 0 &&
                        glm::dot(glm::cross(a - c, q - c), n) >= 0;
    if (inside) return std::abs(glm::dot(p - a, n));
    return std::min(
        {segment_distance(p, a, b), segment_distance(p, b, c), segment_distance(p, c, a)});
}

TEST(TriangleBvh, MatchesBruteForce) {
    const Mesh m = sphere(16);
    const TriangleBvh bvh(m);
    EXPECT_EQ(bvh.size(), m.triangles.size());
    // Probes inside, on and outside the surface.
    std::vector<glm::vec3> probes = sample_surface(sphere(10, 1.6f), 100, 7);
    for (const glm::vec3& p : sample_surface(m, 100, 8)) probes.push_back(p * 0.7f);
    for (const glm::vec3& p : sample_surface(m, 50, 9)) probes.push_back(p);
    for (const glm::vec3& p : probes) {
        float brute = std::numeric_limits<float>::infinity();
        std::uint32_t nearest = 0;
        for (std::uint32_t i = 0; i < m.triangles.size(); ++i) {
            const auto& t = m.triangles[i];
            const float d =
                triangle_distance(p, m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]);
            if (d < brute) {
                brute = d;
                nearest = i;
            }
        }
        const TriangleBvh::Hit hit = bvh.closest(p);
        EXPECT_NEAR(hit.distance, brute, 1e-5f);
        EXPECT_NEAR(glm::length(hit.point - p), hit.distance, 1e-5f);
        if (hit.triangle != nearest) {  // a tie: then both are equally near
            const auto& t = m.triangles[hit.triangle];
            EXPECT_NEAR(
                triangle_distance(p, m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]),
                brute, 1e-5f);
        }
    }
}

TEST(TriangleBvh, KnownDistancesToACube) {
    const TriangleBvh bvh(cube());
    EXPECT_NEAR(bvh.distance({0.5f, 0.5f, 2.0f}), 1.0f, 1e-6f);             // above a face
    EXPECT_NEAR(bvh.distance({2.0f, 2.0f, 0.5f}), std::sqrt(2.0f), 1e-6f);  // off an edge
    EXPECT_NEAR(bvh.distance({2.0f, 2.0f, 2.0f}), std::sqrt(3.0f), 1e-6f);  // off a corner
    EXPECT_NEAR(bvh.distance({0.5f, 0.5f, 0.4f}), 0.4f, 1e-6f);  // inside: to the nearest face
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
    EXPECT_THROW(measure_fidelity(cube(), Mesh{}), InputError);
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
