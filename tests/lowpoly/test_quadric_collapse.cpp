// The flat-array collapse under decimate() (lowpoly/quadric_collapse.h) and decimate() on
// the shapes that stress it: handles, many pieces, thin parts, a foot; and handle cutting on
// a surface with many handles at once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <initializer_list>

#include "core/errors.h"
#include "core/mesh_checks.h"
#include "lowpoly/decimate.h"
#include "lowpoly/fidelity.h"
#include "lowpoly/handle_cutting.h"
#include "lowpoly/quadric_collapse.h"
#include "marching/marching_cubes.h"
#include "quality/folds.h"
#include "quality/self_intersections.h"
#include "tests/quality/shapes.h"

namespace sylva {
namespace {

Mesh mesh_of(ScalarField f, Box box, int resolution) {
    MeshSettings s;
    s.resolution = resolution;
    return marching_cubes(f, box, s);
}

Mesh sphere(int resolution, glm::vec3 centre = glm::vec3(0.0f), float radius = 1.0f) {
    return mesh_of([=](const glm::vec3& p) { return glm::length(p - centre) - radius; },
                   Box{centre - glm::vec3(radius), centre + glm::vec3(radius)}, resolution);
}

float segment_distance(glm::vec3 p, glm::vec3 a, glm::vec3 b, float radius) {
    const glm::vec3 ab = b - a;
    const float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
    return glm::length(p - (a + t * ab)) - radius;
}

// A lattice of rods: `n` along X crossing `n` along Z, one surface with (n - 1)^2 handles.
Mesh lattice(int n, int resolution) {
    const float half = 0.5f * static_cast<float>(n - 1);
    auto f = [=](const glm::vec3& p) {
        float d = 1e9f;
        for (int i = 0; i < n; ++i) {
            const float c = static_cast<float>(i) - half;
            d = std::min(d, segment_distance(p, {-half - 0.3f, 0, c}, {half + 0.3f, 0, c}, 0.12f));
            d = std::min(d, segment_distance(p, {c, 0, -half - 0.3f}, {c, 0, half + 0.3f}, 0.12f));
        }
        return d;
    };
    const float extent = half + 0.5f;
    return mesh_of(f, Box{glm::vec3(-extent, -0.2f, -extent), glm::vec3(extent, 0.2f, extent)},
                   resolution);
}

// Pieces of a mesh: connected components through shared vertices.
std::size_t pieces(const Mesh& m) {
    return component_volumes(m).size();
}

bool all_outward(const Mesh& m) {
    const std::vector<double> v = component_volumes(m);
    return std::all_of(v.begin(), v.end(), [](double x) { return x > 0.0; });
}

DecimateSettings budget(std::size_t triangles) {
    DecimateSettings s;
    s.max_triangles = triangles;
    return s;
}

TEST(QuadricCollapse, BuildAcceptsClosedPartsAndNamesTheFirstBadOne) {
    const Mesh a = sphere(12), b = sphere(12, glm::vec3(3.0f, 0.0f, 0.0f));
    Mesh open = a;
    open.triangles.pop_back();
    Mesh flipped = a;  // one triangle turned: its edges run the same way as their neighbours'
    std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
    Mesh pinched = a;  // a vertex shared by two fans: a and a copy glued at one vertex
    {
        const auto offset = static_cast<std::uint32_t>(pinched.positions.size());
        for (const glm::vec3& p : a.positions)
            pinched.positions.push_back(p + glm::vec3(2.0f, 0, 0));
        for (auto t : a.triangles) {
            for (auto& v : t) v = v == a.triangles[0][0] ? v : v + offset;
            pinched.triangles.push_back(t);
        }
    }
    CollapseMesh mesh;
    std::size_t bad = 99;
    const Mesh* good[] = {&a, &b};
    EXPECT_TRUE(mesh.build(good, &bad));
    EXPECT_EQ(mesh.triangles(), a.triangles.size() + b.triangles.size());
    for (const Mesh* broken : {&open, &flipped, &pinched}) {
        const Mesh* parts[] = {&a, broken};
        EXPECT_FALSE(mesh.build(parts, &bad));
        EXPECT_EQ(bad, 1u);
    }
}

TEST(QuadricCollapse, FloorCountsPiecesAndHandles) {
    const Mesh a = sphere(12), b = sphere(12, glm::vec3(3.0f, 0.0f, 0.0f));
    const Mesh grid = lattice(3, 40);  // 4 handles
    ASSERT_EQ(genus(grid), 4u);
    CollapseMesh mesh;
    const Mesh* parts[] = {&a, &b, &grid};
    ASSERT_TRUE(mesh.build(parts));
    EXPECT_EQ(mesh.triangle_floor(), 3u * 4u + 12u * 4u);
}

// The bulk of the collapses in sorted passes (DecimateSettings::fast_passes) instead of
// one at a time from the heap: another order, the same guarantees (closed, outward, the
// handles kept, the count reached) and about the same distance from the input, in both
// directions (a lost rod would show in the second).
TEST(QuadricCollapse, PassesReduceAsCloseToTheInputAsTheHeap) {
    const Mesh rods = lattice(4, 96), ball = sphere(60);
    for (const Mesh* input : {&rods, &ball}) {
        ASSERT_GT(input->triangles.size(), 4u * 4096u);
        DecimateSettings passes = budget(600), heap = budget(600);
        passes.cut_handles = heap.cut_handles = false;
        heap.fast_passes = false;
        const DecimateResult a = decimate(*input, passes), b = decimate(*input, heap);
        const Mesh &fast = a.parts[0], &exact = b.parts[0];
        EXPECT_TRUE(a.within_budget) << a.note;
        EXPECT_GT(fast.triangles.size(), 560u);
        EXPECT_NE(fast.positions, exact.positions) << "the passes made no collapse";
        EXPECT_TRUE(check_topology(fast).is_closed_manifold());
        EXPECT_TRUE(all_outward(fast));
        EXPECT_EQ(genus(fast), genus(*input));
        const double there = measure_fidelity(fast, *input).mean;
        const double back = measure_fidelity(*input, fast).mean;
        EXPECT_LT(there, 1.15 * measure_fidelity(exact, *input).mean);
        EXPECT_LT(back, 1.15 * measure_fidelity(*input, exact).mean);
    }
}

TEST(QuadricCollapse, KeepsHandlesWhenNotCutting) {
    const Mesh input = lattice(3, 48);
    ASSERT_TRUE(check_topology(input).is_closed_manifold());
    DecimateSettings s = budget(300);
    s.cut_handles = false;
    const DecimateResult r = decimate(input, s);
    const Mesh& m = r.parts[0];
    EXPECT_TRUE(check_topology(m).is_closed_manifold());
    EXPECT_TRUE(r.within_budget) << r.note;
    EXPECT_EQ(genus(m), 4u);
    EXPECT_EQ(pieces(m), 1u);
    EXPECT_TRUE(all_outward(m));
    EXPECT_EQ(r.backoffs, 0);
}

TEST(QuadricCollapse, ManyPiecesNeverVanishNorMerge) {
    // One part of 8 small spheres in a row (some nearly touching), another of one big one.
    Mesh row;
    for (int i = 0; i < 8; ++i) {
        const Mesh s = sphere(14, glm::vec3(0.42f * static_cast<float>(i), 0, 0), 0.2f);
        const auto offset = static_cast<std::uint32_t>(row.positions.size());
        row.positions.insert(row.positions.end(), s.positions.begin(), s.positions.end());
        for (auto t : s.triangles)
            row.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    }
    const Mesh big = sphere(40, glm::vec3(0, 3, 0), 1.0f);
    const Mesh* parts[] = {&row, &big};
    for (std::size_t target : {40u, 120u, 600u}) {
        SCOPED_TRACE(target);
        const DecimateResult r = decimate(parts, budget(target));
        ASSERT_EQ(r.parts.size(), 2u);
        EXPECT_EQ(pieces(r.parts[0]), 8u);
        EXPECT_EQ(pieces(r.parts[1]), 1u);
        for (const Mesh& m : r.parts) {
            EXPECT_TRUE(check_topology(m).is_closed_manifold());
            EXPECT_TRUE(all_outward(m));
        }
        // Each piece keeps at least a tetrahedron: 8 * 4 + 4 triangles at the least.
        EXPECT_LE(r.triangles, std::max<std::size_t>(target, 36));
        EXPECT_EQ(r.within_budget, r.triangles <= target);
    }
}

TEST(QuadricCollapse, ThinPartsStayOutwardAndDeterministic) {
    // A long thin rod (radius 1.5% of its length) bent at the middle, and a thin disc.
    const Mesh rod = mesh_of(
        [](const glm::vec3& p) {
            return std::min(segment_distance(p, {0, 0, 0}, {0, 1, 0}, 0.015f),
                            segment_distance(p, {0, 1, 0}, {0.6f, 1.6f, 0}, 0.015f));
        },
        Box{glm::vec3(-0.05f, -0.05f, -0.05f), glm::vec3(0.65f, 1.65f, 0.05f)}, 160);
    const Mesh disc = mesh_of(
        [](const glm::vec3& p) {
            const float q = std::sqrt(p.x * p.x + p.z * p.z) - 0.5f;
            return std::max(q, std::abs(p.y - 2.0f) - 0.01f);
        },
        Box{glm::vec3(-0.55f, 1.95f, -0.55f), glm::vec3(0.55f, 2.05f, 0.55f)}, 120);
    ASSERT_TRUE(check_topology(rod).is_closed_manifold());
    ASSERT_TRUE(check_topology(disc).is_closed_manifold());
    const Mesh* parts[] = {&rod, &disc};
    for (std::size_t target : {16u, 60u, 400u}) {
        SCOPED_TRACE(target);
        const DecimateResult a = decimate(parts, budget(target));
        const DecimateResult b = decimate(parts, budget(target));
        for (std::size_t k = 0; k < 2; ++k) {
            const Mesh& m = a.parts[k];
            EXPECT_TRUE(check_topology(m).is_closed_manifold());
            EXPECT_EQ(pieces(m), 1u);
            EXPECT_TRUE(all_outward(m));
            EXPECT_EQ(m.positions, b.parts[k].positions);
            EXPECT_EQ(m.triangles, b.parts[k].triangles);
        }
        EXPECT_TRUE(a.within_budget) << a.note;
        EXPECT_LE(a.triangles, target);
    }
}

TEST(QuadricCollapse, FootKeepsItsVerticesOnTheGround) {
    // A cylinder standing on y = 0.
    const Mesh post = mesh_of(
        [](const glm::vec3& p) {
            const float q = std::sqrt(p.x * p.x + p.z * p.z) - 0.1f;
            return std::max(q, std::abs(p.y - 0.5f) - 0.5f);
        },
        Box{glm::vec3(-0.15f, -0.05f, -0.15f), glm::vec3(0.15f, 1.05f, 0.15f)}, 80);
    float ground = 1e9f;
    for (const glm::vec3& p : post.positions) ground = std::min(ground, p.y);
    DecimateSettings s = budget(30);
    s.foot_height = ground + 0.002f;
    const DecimateResult r = decimate(post, s);
    const Mesh& m = r.parts[0];
    EXPECT_TRUE(check_topology(m).is_closed_manifold());
    EXPECT_TRUE(all_outward(m));
    // Foot vertices only merge into foot vertices and relocation keeps their height, so at
    // least a hexagon stays on the ground, and nothing sinks below it.
    const auto on_ground = std::count_if(m.positions.begin(), m.positions.end(),
                                         [&](const glm::vec3& p) { return p.y <= s.foot_height; });
    EXPECT_GE(static_cast<std::size_t>(on_ground), kMinFootVertices);
    float lowest = 1e9f;
    for (const glm::vec3& p : m.positions) lowest = std::min(lowest, p.y);
    EXPECT_GE(lowest, ground - 1e-5f);
}

TEST(QuadricCollapse, EagerLegalityKeepsTheSameGuarantees) {
    const Mesh big = sphere(32), lattice_part = lattice(3, 48);
    const Mesh* parts[] = {&big, &lattice_part};
    DecimateSettings s = budget(150);
    s.cut_handles = false;
    for (bool lazy : {true, false}) {
        SCOPED_TRACE(lazy);
        s.lazy_legality = lazy;
        const DecimateResult r = decimate(parts, s);
        EXPECT_TRUE(r.within_budget) << r.note;
        EXPECT_EQ(genus(r.parts[1]), 4u);
        for (const Mesh& m : r.parts) {
            EXPECT_TRUE(check_topology(m).is_closed_manifold());
            EXPECT_EQ(pieces(m), 1u);
            EXPECT_TRUE(all_outward(m));
        }
    }
}

TEST(QuadricCollapse, ReportsProgressInOrderAndCancels) {
    const Mesh input = lattice(3, 48);
    DecimateSettings s = budget(100);
    std::vector<float> seen;
    s.progress = [&](float f) { seen.push_back(f); };
    decimate(input, s);
    ASSERT_GT(seen.size(), 2u);
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    EXPECT_FLOAT_EQ(seen.back(), 1.0f);
    std::atomic<bool> cancel{false};
    int calls = 0;
    s.progress = [&](float) {
        if (++calls == 2) cancel = true;  // stop while collapsing
    };
    s.cancel = &cancel;
    EXPECT_THROW(decimate(input, s), Cancelled);
}

TEST(HandleCutting, CutsManyHandlesInFewRoundsAndStaysOnePiece) {
    Mesh m = lattice(5, 64);  // 16 handles
    ASSERT_EQ(genus(m), 16u);
    const double volume = enclosed_volume(m);
    Mesh again = m;
    EXPECT_EQ(cut_handles(m, 100), 16u);
    EXPECT_EQ(genus(m), 0u);
    EXPECT_EQ(pieces(m), 1u);
    EXPECT_TRUE(check_topology(m).is_closed_manifold());
    EXPECT_TRUE(all_outward(m));
    // Cuts go around rods (cross-section 0.12 radius), so almost no volume changes.
    EXPECT_NEAR(enclosed_volume(m), volume, 0.02 * volume);
    // Deterministic, and a limit is a limit.
    Mesh twice = again;
    EXPECT_EQ(cut_handles(again, 100), 16u);
    EXPECT_EQ(again.triangles, m.triangles);
    EXPECT_EQ(again.positions, m.positions);
    EXPECT_EQ(cut_handles(twice, 5), 5u);
    EXPECT_EQ(genus(twice), 11u);
    EXPECT_TRUE(check_topology(twice).is_closed_manifold());
}

TEST(HandleCutting, DecimationBelowTheHandleFloorOfALattice) {
    const Mesh input = lattice(5, 64);
    const DecimateResult r = decimate(input, budget(120));  // floor: 4 + 16 * 12 = 196
    const Mesh& m = r.parts[0];
    EXPECT_TRUE(r.within_budget) << r.note;
    EXPECT_GT(r.handles_cut, 0);
    EXPECT_TRUE(check_topology(m).is_closed_manifold());
    EXPECT_EQ(pieces(m), 1u);
    EXPECT_TRUE(all_outward(m));
}

}  // namespace
}  // namespace sylva

namespace sylva {
namespace {

// Each mesh in a CollapseMesh of its own, started.
std::vector<CollapseMesh> started_apart(std::initializer_list<const Mesh*> meshes,
                                        const CollapseSettings& settings) {
    std::vector<CollapseMesh> apart(meshes.size());
    std::size_t k = 0;
    for (const Mesh* m : meshes) {
        const Mesh* only[] = {m};
        EXPECT_TRUE(apart[k].build(only));
        apart[k++].start(settings, nullptr);
    }
    return apart;
}

// Parts reduced in meshes of their own but with one order of collapses (collapse_together)
// share the budget as one mesh of both parts does: the same triangles in all, split between
// the parts alike (equal errors, of which a marching-cubes sphere has many, may go in another
// order), every piece closed and outward.
TEST(QuadricCollapse, MeshesCollapsedTogetherShareTheBudgetAsOneMesh) {
    const Mesh a = sphere(20), b = lattice(3, 40);
    CollapseSettings settings;
    settings.min_twice_area = 1e-12;
    const Mesh* both[] = {&a, &b};
    CollapseMesh joint;
    ASSERT_TRUE(joint.build(both));
    joint.start(settings, nullptr);
    joint.collapse_to(300);
    const std::vector<Mesh> expected = joint.extract();

    std::vector<CollapseMesh> apart = started_apart({&a, &b}, settings);
    collapse_together(apart, 300);
    EXPECT_EQ(apart[0].triangles() + apart[1].triangles(), joint.triangles());
    for (std::size_t k = 0; k < 2; ++k) {
        const Mesh got = apart[k].extract().front();
        const double want = static_cast<double>(expected[k].triangles.size());
        EXPECT_NEAR(static_cast<double>(got.triangles.size()), want, 0.1 * want) << "part " << k;
        EXPECT_TRUE(check_topology(got).is_closed_manifold()) << "part " << k;
        EXPECT_TRUE(all_outward(got)) << "part " << k;
        EXPECT_EQ(genus(got), genus(expected[k])) << "part " << k;
    }
}

// A floor per mesh in the shared order (DecimateSettings::part_floor): the mesh whose
// collapses are cheapest stops at the floor and the other gives up the rest of the budget.
TEST(QuadricCollapse, AMeshAtItsFloorStopsAndTheOthersTakeTheRest) {
    const Mesh ball = sphere(24), rods = lattice(3, 40);
    CollapseSettings settings;
    settings.min_twice_area = 1e-12;
    auto reduce = [&](std::size_t floor) {
        std::vector<CollapseMesh> meshes = started_apart({&ball, &rods}, settings);
        collapse_together(meshes, 300, nullptr, floor);
        return std::pair(meshes[0].extract().front(), meshes[1].extract().front());
    };
    const auto [free_ball, free_rods] = reduce(0);
    // Without a floor the smooth ball gives up more than the rods.
    ASSERT_LT(free_ball.triangles.size(), 150u);
    const auto [ball_kept, rods_kept] = reduce(150);
    EXPECT_GE(ball_kept.triangles.size(), 150u);
    EXPECT_LE(ball_kept.triangles.size() + rods_kept.triangles.size(), 300u);
    EXPECT_LT(rods_kept.triangles.size(), free_rods.triangles.size());
    for (const Mesh* m : {&ball_kept, &rods_kept}) {
        EXPECT_TRUE(check_topology(*m).is_closed_manifold());
        EXPECT_TRUE(all_outward(*m));
    }
}

// A box whose top is a valley: the two corners on its diagonal lowered, so the top's halves
// fold inwards at 97 degrees. unfold() flips the diagonal to the other one, a ridge. Still
// closed, no vertex moved, no volume lost.
TEST(Unfold, FlipsSharpInwardFoldsAway) {
    Mesh dented = test::box(glm::vec3(0.0f), glm::vec3(1.0f));
    for (std::size_t v : {2, 7}) dented.positions[v].y = 0.2f;  // the top's diagonal
    const double before = concave_fold_share(dented);
    ASSERT_GT(before, 0.01);
    CollapseMesh m;
    const Mesh* parts[] = {&dented};
    ASSERT_TRUE(m.build(parts));
    m.start({}, nullptr);
    EXPECT_GT(m.unfold(), 0u);
    const Mesh out = m.extract().front();
    EXPECT_LT(concave_fold_share(out), 0.5 * before);
    EXPECT_TRUE(check_topology(out).is_closed_manifold());
    EXPECT_EQ(out.positions, dented.positions);
    EXPECT_GE(component_volumes(out).front(), component_volumes(dented).front());
    EXPECT_EQ(self_intersecting_pairs(out), 0u);
}

TEST(Unfold, LeavesAConvexMeshAlone) {
    const Mesh ball = test::icosphere(2);
    CollapseMesh m;
    const Mesh* parts[] = {&ball};
    ASSERT_TRUE(m.build(parts));
    m.start({}, nullptr);
    EXPECT_EQ(m.unfold(), 0u);
    EXPECT_EQ(m.extract().front().triangles, ball.triangles);
}

// decimate() unfolds by default: a reduced bumpy ball keeps fewer sharp inward folds.
TEST(Unfold, ReducedBumpsFoldLess) {
    const Mesh bumps = mesh_of(
        [](const glm::vec3& p) {
            return glm::length(p) - 1.0f +
                   0.15f * std::sin(9.0f * p.x) * std::sin(9.0f * p.y) * std::sin(9.0f * p.z);
        },
        Box{glm::vec3(-1.3f), glm::vec3(1.3f)}, 64);
    DecimateSettings s;
    s.max_triangles = 300;
    s.unfold = false;
    const Mesh folded = decimate(bumps, s).parts.front();
    s.unfold = true;
    const Mesh unfolded = decimate(bumps, s).parts.front();
    EXPECT_TRUE(check_topology(unfolded).is_closed_manifold());
    EXPECT_LE(unfolded.triangles.size(), 300u);
    EXPECT_LT(concave_fold_share(unfolded), concave_fold_share(folded));
}

}  // namespace
}  // namespace sylva
