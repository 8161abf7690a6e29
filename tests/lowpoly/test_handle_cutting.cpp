#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/mesh_checks.h"
#include "lowpoly/decimate.h"
#include "lowpoly/handle_cutting.h"
#include "marching/marching_cubes.h"

namespace sylva {
namespace {

Mesh mesh_of(ScalarField f, Box box, int resolution) {
    MeshSettings s;
    s.resolution = resolution;
    return marching_cubes(f, box, s);
}

float torus_distance(glm::vec3 p, glm::vec3 centre, float major, float minor) {
    p -= centre;
    const float q = std::sqrt(p.x * p.x + p.z * p.z) - major;
    return std::sqrt(q * q + p.y * p.y) - minor;
}

Mesh torus(int resolution) {
    return mesh_of(
        [](const glm::vec3& p) { return torus_distance(p, glm::vec3(0.0f), 1.0f, 0.3f); },
        Box{glm::vec3(-1.3f, -0.3f, -1.3f), glm::vec3(1.3f, 0.3f, 1.3f)}, resolution);
}

// Two tori side by side, overlapping: one surface of genus 2.
Mesh double_torus(int resolution) {
    return mesh_of(
        [](const glm::vec3& p) {
            return std::min(torus_distance(p, glm::vec3(-0.9f, 0, 0), 1.0f, 0.3f),
                            torus_distance(p, glm::vec3(0.9f, 0, 0), 1.0f, 0.3f));
        },
        Box{glm::vec3(-2.2f, -0.3f, -1.3f), glm::vec3(2.2f, 0.3f, 1.3f)}, resolution);
}

Mesh sphere(int resolution) {
    return mesh_of([](const glm::vec3& p) { return glm::length(p) - 1.0f; },
                   Box{glm::vec3(-1.0f), glm::vec3(1.0f)}, resolution);
}

TEST(HandleCutting, GenusCountsHandles) {
    EXPECT_EQ(genus(sphere(16)), 0u);
    EXPECT_EQ(genus(torus(40)), 1u);
    EXPECT_EQ(genus(double_torus(60)), 2u);
    EXPECT_EQ(genus(Mesh{}), 0u);
}

TEST(HandleCutting, CutsTheThinSideAndStaysClosed) {
    Mesh m = torus(48);
    const double volume = enclosed_volume(m);
    EXPECT_EQ(cut_handles(m, 5), 1u);  // there is only one
    EXPECT_EQ(genus(m), 0u);
    EXPECT_TRUE(check_topology(m).is_closed_manifold());
    // The cut goes around the tube (length ~2 pi 0.3), not around the hole (~2 pi): the
    // volume is kept, and no point moved.
    EXPECT_NEAR(enclosed_volume(m), volume, 1e-3 * volume);
    for (const glm::vec3& p : m.positions)
        EXPECT_LT(std::abs(torus_distance(p, glm::vec3(0.0f), 1.0f, 0.3f)), 0.31f);
}

TEST(HandleCutting, StopsAtTheLimitAndAtGenusZero) {
    Mesh m = double_torus(60);
    EXPECT_EQ(cut_handles(m, 1), 1u);
    EXPECT_EQ(genus(m), 1u);
    EXPECT_EQ(cut_handles(m, 10), 1u);
    EXPECT_EQ(genus(m), 0u);
    EXPECT_TRUE(check_topology(m).is_closed_manifold());
    Mesh s = sphere(16);
    const Mesh before = s;
    EXPECT_EQ(cut_handles(s, 3), 0u);
    EXPECT_EQ(s.triangles, before.triangles);
}

TEST(HandleCutting, LetsDecimationReachBudgetsBelowTheHandleFloor) {
    const Mesh input = double_torus(60);
    DecimateSettings s;
    s.max_triangles = 12;
    s.cut_handles = false;
    const DecimateResult kept = decimate(input, s);
    EXPECT_FALSE(kept.within_budget);
    EXPECT_EQ(genus(kept.parts[0]), 2u);
    EXPECT_EQ(kept.handles_cut, 0);

    s.cut_handles = true;
    const DecimateResult cut = decimate(input, s);
    EXPECT_TRUE(cut.within_budget) << cut.note;
    EXPECT_GT(cut.handles_cut, 0);
    EXPECT_LT(genus(cut.parts[0]), 2u);
    EXPECT_TRUE(check_topology(cut.parts[0]).is_closed_manifold());
    EXPECT_GT(enclosed_volume(cut.parts[0]), 0.0);
}

}  // namespace
}  // namespace sylva
