// The sparse mesher against the dense one: the same mesh, byte for byte, for 1-Lipschitz
// fields, at a fraction of the evaluations; and the settings (threads, progress, cancel,
// stats) honoured by both.
#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>
#include <limits>
#include <mutex>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/mesh_checks.h"
#include "marching/grid.h"
#include "marching/marching_cubes.h"
#include "sdf/capped_cone.h"
#include "tests/helpers.h"

namespace sylva {
namespace {

// A pure point function as a batch field: thread-safe when the function is.
BatchField batch(std::function<float(const glm::vec3&)> f) {
    return [f = std::move(f)](std::span<const glm::vec3> points, std::span<float> values) {
        for (std::size_t i = 0; i < points.size(); ++i) values[i] = f(points[i]);
    };
}

BatchField sphere(glm::vec3 center, float radius) {
    return batch([=](const glm::vec3& p) { return glm::length(p - center) - radius; });
}

BatchField torus(float major, float minor) {
    return batch([=](const glm::vec3& p) {
        const float ring = std::sqrt(p.x * p.x + p.y * p.y) - major;
        return std::sqrt(ring * ring + p.z * p.z) - minor;
    });
}

float next_unit(std::mt19937& rng) {
    // Fixed mapping (unlike std::uniform_real_distribution) so every platform agrees.
    return float(rng() >> 8) * (1.0f / 16777216.0f);
}

// Union of many small spheres: a noisy surface with thin gaps, still a distance bound.
BatchField sphere_cloud(std::uint32_t seed, int count, float min_radius, float max_radius) {
    std::mt19937 rng(seed);
    std::vector<glm::vec4> spheres(count);
    for (auto& s : spheres) {
        s = glm::vec4(next_unit(rng), next_unit(rng), next_unit(rng), 0.0f) * 2.0f - 1.0f;
        s.w = min_radius + (max_radius - min_radius) * next_unit(rng);
    }
    return batch([spheres](const glm::vec3& p) {
        float d = std::numeric_limits<float>::max();
        for (const auto& s : spheres) d = std::min(d, glm::length(p - glm::vec3(s)) - s.w);
        return d;
    });
}

// Random branches in [-1, 1]^3, clamped at `margin` like sylva's culled ConeField (the
// clamp keeps it 1-Lipschitz but caps what the bound can prove).
BatchField cone_cloud(std::uint32_t seed, int count, float margin) {
    std::mt19937 rng(seed);
    std::vector<CappedCone> cones(count);
    for (auto& c : cones) {
        c.a = glm::vec3(next_unit(rng), next_unit(rng), next_unit(rng)) * 1.6f - 0.8f;
        c.b = c.a + (glm::vec3(next_unit(rng), next_unit(rng), next_unit(rng)) - 0.5f) * 0.5f;
        c.ra = 0.02f + 0.06f * next_unit(rng);
        c.rb = 0.01f + 0.04f * next_unit(rng);
    }
    // Bounding spheres skip the cones that cannot lower d (exact, unlike the margin).
    std::vector<glm::vec4> bounds;
    for (const auto& c : cones) {
        bounds.emplace_back(0.5f * (c.a + c.b),
                            0.5f * glm::length(c.b - c.a) + std::max(c.ra, c.rb));
    }
    return batch([cones, bounds, margin](const glm::vec3& p) {
        float d = margin;
        for (std::size_t i = 0; i < cones.size(); ++i) {
            if (glm::length(p - glm::vec3(bounds[i])) - bounds[i].w >= d) continue;
            d = std::min(d, distance(cones[i], p));
        }
        return d;
    });
}

Box cube(float half) {
    return {glm::vec3(-half), glm::vec3(half)};
}

MeshSettings settings(int resolution, int padding = 2, int threads = 0) {
    MeshSettings s;
    s.resolution = resolution;
    s.padding_cells = padding;
    s.threads = threads;
    return s;
}

// Same vertices in the same order, bit for bit, and the same triangles.
void expect_same_mesh(const Mesh& a, const Mesh& b) {
    ASSERT_EQ(a.positions.size(), b.positions.size());
    ASSERT_EQ(a.triangles.size(), b.triangles.size());
    if (!a.positions.empty()) {
        EXPECT_EQ(0, std::memcmp(a.positions.data(), b.positions.data(),
                                 a.positions.size() * sizeof(glm::vec3)));
    }
    EXPECT_TRUE(a.triangles == b.triangles);
}

void expect_inside_grid(const Mesh& mesh, const Box& box, const MeshSettings& s) {
    const Grid grid = make_grid(box, s);
    const glm::dvec3 lo = grid.origin;
    const glm::dvec3 hi = grid.node(grid.nodes[0] - 1, grid.nodes[1] - 1, grid.nodes[2] - 1);
    std::size_t outside = 0;
    for (const auto& p : mesh.positions) {
        for (int a = 0; a < 3; ++a) {
            // Half a cell in from the border: the border layer of nodes is always outside.
            if (p[a] < lo[a] + 0.49 * grid.h || p[a] > hi[a] - 0.49 * grid.h) {
                ++outside;
                break;
            }
        }
    }
    EXPECT_EQ(outside, 0u);
}

void expect_sparse_equals_dense(const BatchField& field, const Box& box, const MeshSettings& s) {
    const Mesh dense = marching_cubes(field, box, s);
    const Mesh sparse = sparse_marching_cubes(field, box, s);
    expect_same_mesh(dense, sparse);
}

TEST(SparseMarchingCubes, EqualsDenseOnSpheres) {
    for (const int resolution : {1, 2, 3, 7, 10, 33, 64, 100}) {
        SCOPED_TRACE("resolution " + std::to_string(resolution));
        expect_sparse_equals_dense(sphere(glm::vec3(0.0f), 1.0f), cube(1.0f), settings(resolution));
        const Box flat{glm::vec3(-1.0f, -0.4f, -0.2f), glm::vec3(1.2f, 0.5f, 0.3f)};
        expect_sparse_equals_dense(sphere(glm::vec3(0.1f, 0.05f, 0.0f), 0.3f), flat,
                                   settings(resolution, 1));
    }
}

TEST(SparseMarchingCubes, EqualsDenseOnTori) {
    const Box box{glm::vec3(-0.82f, -0.82f, -0.12f), glm::vec3(0.82f, 0.82f, 0.12f)};
    for (const int resolution : {6, 11, 20, 64, 150}) {
        SCOPED_TRACE("resolution " + std::to_string(resolution));
        expect_sparse_equals_dense(torus(0.7f, 0.12f), box, settings(resolution));
    }
}

TEST(SparseMarchingCubes, EqualsDenseOnConeClouds) {
    for (const int resolution : {24, 57, 120}) {
        const float h = 2.0f / float(resolution);
        // Margins above and below the 8-cell block's half-diagonal (6.93 cells): the
        // mesh is the same, only the work differs.
        for (const float margin_cells : {1.0f, 8.0f, 1000.0f}) {
            SCOPED_TRACE("resolution " + std::to_string(resolution) + ", margin " +
                         std::to_string(margin_cells));
            expect_sparse_equals_dense(cone_cloud(7u, 200, margin_cells * h), cube(1.0f),
                                       settings(resolution));
        }
    }
}

TEST(SparseMarchingCubes, EqualsDenseOnSphereClouds) {
    // Spheres from a fifth of a cell to a few cells: crumbs, gaps and ambiguous faces.
    for (const std::uint32_t seed : {1u, 2u, 3u}) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        expect_sparse_equals_dense(sphere_cloud(seed, 300, 0.02f, 0.15f), cube(1.1f), settings(22));
        expect_sparse_equals_dense(sphere_cloud(seed, 150, 0.005f, 0.08f), cube(1.1f),
                                   settings(90));
    }
}

TEST(SparseMarchingCubes, EqualsDenseWhereTheFieldIsInsideAtTheBorder) {
    // Inside blocks on the border cannot be skipped: their border nodes count as outside
    // and carry the cap.
    for (const int padding : {0, 1, 2}) {
        SCOPED_TRACE("padding " + std::to_string(padding));
        expect_sparse_equals_dense(sphere(glm::vec3(0.0f), 1.5f), cube(1.0f),
                                   settings(40, padding));
        const BatchField hole = batch([](const glm::vec3& p) { return 0.7f - glm::length(p); });
        expect_sparse_equals_dense(hole, cube(1.0f), settings(48, padding));
    }
    const Mesh solid = sparse_marching_cubes(batch([](const glm::vec3&) { return -1.0f; }),
                                             cube(1.0f), settings(70));
    expect_same_mesh(solid, marching_cubes(batch([](const glm::vec3&) { return -1.0f; }),
                                           cube(1.0f), settings(70)));
    test::expect_closed_manifold(solid);
}

TEST(SparseMarchingCubes, IsClosedAtManyResolutions) {
    const Box torus_box{glm::vec3(-0.82f, -0.82f, -0.12f), glm::vec3(0.82f, 0.82f, 0.12f)};
    for (const int resolution : {10, 17, 40, 99, 180, 300}) {
        SCOPED_TRACE("resolution " + std::to_string(resolution));
        const MeshSettings s = settings(resolution);
        const float h = 2.0f / float(resolution);

        const Mesh ball = sparse_marching_cubes(sphere(glm::vec3(0.1f), 0.9f), cube(1.0f), s);
        test::expect_closed_manifold(ball);
        expect_inside_grid(ball, cube(1.0f), s);
        if (resolution >= 40) {
            const double volume = 4.0 / 3.0 * 3.14159265358979 * 0.9 * 0.9 * 0.9;
            EXPECT_NEAR(enclosed_volume(ball), volume, 0.03 * volume);
        }

        const Mesh ring = sparse_marching_cubes(torus(0.7f, 0.12f), torus_box, s);
        test::expect_closed_manifold(ring);
        expect_inside_grid(ring, torus_box, s);

        const Mesh branches = sparse_marching_cubes(cone_cloud(11u, 60, 8.0f * h), cube(1.0f), s);
        test::expect_closed_manifold(branches);
        expect_inside_grid(branches, cube(1.0f), s);
        EXPECT_FALSE(branches.triangles.empty());
    }
}

TEST(SparseMarchingCubes, SameBytesWhateverTheThreadCount) {
    const BatchField field = cone_cloud(5u, 150, 0.2f);
    const Mesh reference = sparse_marching_cubes(field, cube(1.0f), settings(110, 2, 1));
    ASSERT_FALSE(reference.triangles.empty());
    for (const int threads : {2, 0, 3}) {
        SCOPED_TRACE("threads " + std::to_string(threads));
        expect_same_mesh(reference,
                         sparse_marching_cubes(field, cube(1.0f), settings(110, 2, threads)));
        expect_same_mesh(reference, marching_cubes(field, cube(1.0f), settings(110, 2, threads)));
    }
    for (int run = 0; run < 3; ++run) {
        expect_same_mesh(reference, sparse_marching_cubes(field, cube(1.0f), settings(110)));
    }
}

TEST(SparseMarchingCubes, FieldRunningItsOwnParallelLoopsIsSafe) {
    // While a worker waits for the field's loop it must not start another block of ours
    // on the same thread (it would reuse that thread's buffers under the running batch);
    // the meshers isolate field calls. Such steals are rare and timing-dependent, so this
    // mostly checks that nested loops work and change nothing; more threads than cores
    // and uneven nested work give them their best chance.
    tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism, 8);
    const BatchField nested = [](std::span<const glm::vec3> points, std::span<float> values) {
        tbb::parallel_for(std::size_t(0), points.size(), [&](std::size_t i) {
            float v = glm::length(points[i] - glm::vec3(0.1f, 0.0f, -0.2f)) - 0.7f;
            // A data-dependent delay (that changes nothing) unbalances the nested loop.
            for (int k = 0; k < int(points[i].x * 50.0f + 50.0f); ++k) v = std::nextafter(v, v);
            values[i] = v;
        });
    };
    const BatchField plain = sphere(glm::vec3(0.1f, 0.0f, -0.2f), 0.7f);
    const Mesh reference = marching_cubes(plain, cube(1.0f), settings(80, 2, 1));
    for (int run = 0; run < 3; ++run) {
        expect_same_mesh(reference, sparse_marching_cubes(nested, cube(1.0f), settings(80, 2, 8)));
        expect_same_mesh(reference, marching_cubes(nested, cube(1.0f), settings(80, 2, 8)));
    }
}

TEST(SparseMarchingCubes, EvaluatesFarFewerPointsThanDense) {
    const BatchField field = sphere(glm::vec3(0.0f), 1.0f);
    const MeshSettings base = settings(200);
    MeshingStats dense_stats, sparse_stats;
    MeshSettings s = base;
    s.stats = &dense_stats;
    const Mesh dense = marching_cubes(field, cube(1.0f), s);
    s.stats = &sparse_stats;
    const Mesh sparse = sparse_marching_cubes(field, cube(1.0f), s);
    expect_same_mesh(dense, sparse);

    const Grid grid = make_grid(cube(1.0f), base);
    const std::size_t nodes = std::size_t(grid.nodes[0]) * grid.nodes[1] * grid.nodes[2];
    EXPECT_EQ(dense_stats.evaluations, nodes);  // every node exactly once
    EXPECT_LT(double(sparse_stats.evaluations), 0.25 * double(nodes));
    EXPECT_EQ(sparse_stats.blocks_total, dense_stats.blocks_total);
    EXPECT_EQ(dense_stats.blocks_meshed, dense_stats.blocks_total);
    EXPECT_GT(sparse_stats.blocks_meshed, 0u);
    EXPECT_LT(sparse_stats.blocks_meshed, sparse_stats.blocks_total / 2);
}

TEST(SparseMarchingCubes, WorkGrowsWithAreaNotVolume) {
    // Doubling the resolution multiplies the dense work by 8 and the sparse work by about 4.
    const BatchField field = sphere(glm::vec3(0.0f), 0.8f);
    std::vector<double> evaluations;
    for (const int resolution : {100, 200}) {
        MeshingStats stats;
        MeshSettings s = settings(resolution);
        s.stats = &stats;
        sparse_marching_cubes(field, cube(1.0f), s);
        evaluations.push_back(double(stats.evaluations));
    }
    EXPECT_LT(evaluations[1] / evaluations[0], 5.0);
}

TEST(SparseMarchingCubes, ProgressRisesToOne) {
    for (const bool sparse : {false, true}) {
        SCOPED_TRACE(sparse ? "sparse" : "dense");
        std::mutex mutex;
        std::vector<float> reports;
        MeshSettings s = settings(90);
        s.progress = [&](float f) {
            std::lock_guard lock(mutex);
            reports.push_back(f);
        };
        const BatchField field = sphere(glm::vec3(0.0f), 0.9f);
        sparse ? sparse_marching_cubes(field, cube(1.0f), s) : marching_cubes(field, cube(1.0f), s);
        ASSERT_GE(reports.size(), 3u);
        EXPECT_TRUE(std::is_sorted(reports.begin(), reports.end()));
        EXPECT_GE(reports.front(), 0.0f);
        EXPECT_EQ(reports.back(), 1.0f);
        EXPECT_EQ(std::count(reports.begin(), reports.end(), 1.0f), 1);
    }
}

TEST(SparseMarchingCubes, CancelFromTheProgressCallbackThrows) {
    for (const bool sparse : {false, true}) {
        for (const int threads : {1, 2}) {
            SCOPED_TRACE(std::string(sparse ? "sparse" : "dense") + ", threads " +
                         std::to_string(threads));
            std::atomic<bool> cancel{false};
            std::atomic<int> calls_after_cancel{0};
            MeshSettings s = settings(150, 2, threads);
            s.cancel = &cancel;
            s.progress = [&](float f) {
                if (cancel) ++calls_after_cancel;
                if (f > 0.0f) cancel = true;
            };
            const BatchField field = cone_cloud(3u, 100, 0.1f);
            EXPECT_THROW(sparse ? sparse_marching_cubes(field, cube(1.0f), s)
                                : marching_cubes(field, cube(1.0f), s),
                         Cancelled);
            // Stopped soon: no report of completion.
            EXPECT_LT(calls_after_cancel.load(), 4);
        }
    }
}

TEST(SparseMarchingCubes, CancelledBeforeStartThrowsWithoutEvaluating) {
    std::atomic<bool> cancel{true};
    std::atomic<std::size_t> evaluations{0};
    const BatchField counting = [&](std::span<const glm::vec3> points, std::span<float> values) {
        evaluations += points.size();
        std::fill(values.begin(), values.end(), 1.0f);
    };
    MeshSettings s = settings(50);
    s.cancel = &cancel;
    EXPECT_THROW(sparse_marching_cubes(counting, cube(1.0f), s), Cancelled);
    EXPECT_THROW(marching_cubes(counting, cube(1.0f), s), Cancelled);
    EXPECT_EQ(evaluations.load(), 0u);
}

TEST(SparseMarchingCubes, FieldExceptionsReachTheCaller) {
    const BatchField failing = [](std::span<const glm::vec3>, std::span<float>) {
        throw std::runtime_error("field failed");
    };
    EXPECT_THROW(sparse_marching_cubes(failing, cube(1.0f), settings(30)), std::runtime_error);
    EXPECT_THROW(marching_cubes(failing, cube(1.0f), settings(30)), std::runtime_error);
}

TEST(SparseMarchingCubes, EmptyAndNonFiniteFieldsGiveEmptyMeshes) {
    for (const float value :
         {1.0f, 0.0f, std::numeric_limits<float>::quiet_NaN(),
          std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()}) {
        SCOPED_TRACE("value " + std::to_string(value));
        MeshingStats stats;
        MeshSettings s = settings(64);
        s.stats = &stats;
        const Mesh mesh =
            sparse_marching_cubes(batch([=](const glm::vec3&) { return value; }), cube(1.0f), s);
        EXPECT_TRUE(mesh.triangles.empty());
        EXPECT_TRUE(mesh.positions.empty());
    }
}

TEST(SparseMarchingCubes, FieldBreakingTheDistanceBoundStillGivesAValidMesh) {
    // White noise is nowhere near 1-Lipschitz: blocks get skipped that hold surface. The
    // mesh may have holes, but every index must be valid and every triangle proper.
    const BatchField noise = batch([](const glm::vec3& p) {
        std::uint32_t bits[3];
        std::memcpy(bits, &p, sizeof bits);
        std::uint32_t hash = 2166136261u;
        for (const std::uint32_t b : bits) hash = (hash ^ b) * 16777619u;
        hash ^= hash >> 15;
        hash *= 0x2c1b3c6du;
        hash ^= hash >> 12;
        return (float(hash >> 8) / 8388608.0f - 1.0f) * 40.0f;
    });
    const Mesh mesh =
        sparse_marching_cubes(noise, {glm::vec3(0.0f), glm::vec3(40.0f)}, settings(40, 0));
    EXPECT_FALSE(mesh.triangles.empty());
    for (const auto& t : mesh.triangles) {
        for (const std::uint32_t v : t) ASSERT_LT(v, mesh.positions.size());
    }
    EXPECT_EQ(check_topology(mesh).degenerate_triangles, 0u);
}

TEST(SparseMarchingCubes, RejectsBadArguments) {
    const BatchField field = sphere(glm::vec3(0.0f), 1.0f);
    EXPECT_THROW(sparse_marching_cubes(field, cube(1.0f), settings(0)), InputError);
    EXPECT_THROW(sparse_marching_cubes(field, cube(1.0f), settings(8, -1)), InputError);
    EXPECT_THROW(sparse_marching_cubes(field, cube(0.0f), settings(8)), InputError);
    EXPECT_THROW(
        sparse_marching_cubes(field, {glm::vec3(-1.0f), glm::vec3(std::nanf(""))}, settings(8)),
        InputError);
}

}  // namespace
}  // namespace sylva
