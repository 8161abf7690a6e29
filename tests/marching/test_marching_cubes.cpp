#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>
#include <limits>
#include <mutex>
#include <numbers>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "core/errors.h"
#include "core/mesh_checks.h"
#include "marching/marching_cubes.h"
#include "tests/helpers.h"

namespace sylva {
namespace {

constexpr double kPi = std::numbers::pi;

ScalarField sphere(glm::vec3 center, float radius) {
    return [=](const glm::vec3& p) { return glm::length(p - center) - radius; };
}

ScalarField unite(ScalarField a, ScalarField b) {
    return [=](const glm::vec3& p) { return std::min(a(p), b(p)); };
}

Box cube(float half) {
    return {glm::vec3(-half), glm::vec3(half)};
}

MeshSettings settings(int resolution, int padding = 2) {
    MeshSettings s;
    s.resolution = resolution;
    s.padding_cells = padding;
    return s;
}

// Every vertex lies within `box` grown by `margin` on every side.
void expect_inside(const Mesh& mesh, const Box& box, float margin) {
    std::size_t outside = 0;
    for (const auto& p : mesh.positions) {
        for (int a = 0; a < 3; ++a) {
            if (p[a] < box.min[a] - margin || p[a] > box.max[a] + margin) {
                ++outside;
                break;
            }
        }
    }
    EXPECT_EQ(outside, 0u);
}

// The sampled grid: the padded box, widened by less than a cell on its shorter axes.
void expect_inside_grid(const Mesh& mesh, const Box& box, const MeshSettings& s) {
    const glm::vec3 size = box.max - box.min;
    const float h = std::max({size.x, size.y, size.z}) / float(s.resolution);
    expect_inside(mesh, box, (float(s.padding_cells) + 0.5f) * h * 1.0001f);
}

// Runs the mesher while recording every field evaluation, to check that each grid node is
// evaluated once and to count the ambiguous faces the field produces on that grid.
struct RecordedRun {
    Mesh mesh;
    std::size_t evaluations = 0;
    std::size_t distinct_nodes = 0;
    std::size_t grid_nodes = 0;
    std::size_t ambiguous_faces = 0;
};

RecordedRun run_recorded(const ScalarField& field, const Box& box, const MeshSettings& s) {
    std::vector<std::pair<glm::vec3, float>> samples;
    const ScalarField recording = [&](const glm::vec3& p) {
        const float v = field(p);
        samples.emplace_back(p, v);
        return v;
    };
    RecordedRun run;
    run.mesh = marching_cubes(recording, box, s);
    run.evaluations = samples.size();
    if (samples.empty()) return run;

    const glm::vec3 size = box.max - box.min;
    const double h = std::max({size.x, size.y, size.z}) / double(s.resolution);
    glm::vec3 lo = samples.front().first;
    for (const auto& [p, v] : samples) lo = glm::min(lo, p);
    const auto index = [&](const glm::vec3& p, int a) {
        return int(std::lround((double(p[a]) - lo[a]) / h));
    };
    std::array<int, 3> n{0, 0, 0};
    for (const auto& [p, v] : samples) {
        for (int a = 0; a < 3; ++a) n[a] = std::max(n[a], index(p, a) + 1);
    }
    run.grid_nodes = std::size_t(n[0]) * n[1] * n[2];
    const auto flat = [&](int i, int j, int k) { return i + std::size_t(n[0]) * (j + n[1] * k); };
    std::vector<char> seen(run.grid_nodes, 0), in(run.grid_nodes, 0);
    for (const auto& [p, v] : samples) {
        const std::size_t f = flat(index(p, 0), index(p, 1), index(p, 2));
        run.distinct_nodes += !seen[f];
        seen[f] = 1;
        in[f] = v < 0.0f;
    }
    for (int axis = 0; axis < 3; ++axis) {
        const int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;
        for (int k = 0; k < n[2]; ++k) {
            for (int j = 0; j < n[1]; ++j) {
                for (int i = 0; i < n[0]; ++i) {
                    const std::array<int, 3> c{i, j, k};
                    if (c[u] + 1 >= n[u] || c[v] + 1 >= n[v]) continue;
                    const auto at = [&](int du, int dv) {
                        std::array<int, 3> q = c;
                        q[u] += du;
                        q[v] += dv;
                        return in[flat(q[0], q[1], q[2])] != 0;
                    };
                    const bool a = at(0, 0), b = at(1, 0), cc = at(1, 1), d = at(0, 1);
                    if (a == cc && b == d && a != b) ++run.ambiguous_faces;
                }
            }
        }
    }
    return run;
}

float next_unit(std::mt19937& rng) {
    // Fixed mapping (unlike std::uniform_real_distribution) so every platform agrees.
    return float(rng() >> 8) * (1.0f / 16777216.0f);
}

TEST(MarchingCubes, SphereIsClosedAtSeveralResolutions) {
    const ScalarField field = sphere(glm::vec3(0.0f), 1.0f);
    for (const int resolution : {1, 2, 3, 5, 10, 32, 100}) {
        SCOPED_TRACE("resolution " + std::to_string(resolution));
        const MeshSettings s = settings(resolution);
        const Mesh mesh = marching_cubes(field, cube(1.0f), s);
        test::expect_closed_manifold(mesh);
        expect_inside(mesh, cube(1.0f), 0.0f);
        if (resolution >= 3) {
            EXPECT_GT(enclosed_volume(mesh), 0.0);
        }
        if (resolution >= 32) {
            EXPECT_NEAR(surface_area(mesh), 4.0 * kPi, 0.03 * 4.0 * kPi);
            EXPECT_NEAR(enclosed_volume(mesh), 4.0 / 3.0 * kPi, 0.03 * 4.0 / 3.0 * kPi);
        }
    }
}

// 3 km from the origin floats are 0.24 mm apart: a 30 cm sphere meshed in 3 mm cells gets
// vertices that round onto each other, and slivers of zero area. The surface is closed all
// the same, and must be reported so (a crown there was printed "NOT closed").
TEST(MarchingCubes, ASphereFarFromTheOriginIsClosedWithItsSlivers) {
    const glm::vec3 center(0.0f, 2121.3f, 2121.4f);
    const Mesh mesh =
        marching_cubes(sphere(center, 0.15f), {center - 0.16f, center + 0.16f}, settings(110));
    const MeshTopology t = check_topology(mesh);
    EXPECT_TRUE(t.is_closed_manifold()) << to_string(t);
    EXPECT_GT(t.zero_area_triangles, 0u) << to_string(t);
    EXPECT_GT(enclosed_volume(mesh), 0.0);
}

TEST(MarchingCubes, SphereNormalsPointOutward) {
    const glm::vec3 center(0.3f, -0.2f, 0.1f);
    const Mesh mesh =
        marching_cubes(sphere(center, 0.8f), {center - 0.8f, center + 0.8f}, settings(32));
    ASSERT_FALSE(mesh.triangles.empty());
    std::size_t inward = 0;
    for (const auto& t : mesh.triangles) {
        const glm::vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]],
                        c = mesh.positions[t[2]];
        const glm::vec3 normal = glm::cross(b - a, c - a);
        if (glm::dot(normal, (a + b + c) / 3.0f - center) <= 0.0f) ++inward;
    }
    EXPECT_EQ(inward, 0u);
}

TEST(MarchingCubes, EvaluatesEachGridNodeOnce) {
    const Box box{glm::vec3(-1.0f, -1.0f, -0.5f), glm::vec3(1.0f, 0.7f, 0.5f)};
    const RecordedRun run = run_recorded(sphere(glm::vec3(0.0f), 0.45f), box, settings(16));
    EXPECT_EQ(run.evaluations, run.distinct_nodes);
    EXPECT_EQ(run.evaluations, run.grid_nodes);
    // 16 + 4 cells along x, ceil(1.7 / 0.125) + 4 along y, 8 + 4 along z.
    EXPECT_EQ(run.grid_nodes, std::size_t(21 * 19 * 13));
    test::expect_closed_manifold(run.mesh);
}

TEST(MarchingCubes, BatchFieldEvaluatesEachNodeOnceAcrossThreads) {
    const Box box{glm::vec3(-1.0f, -1.0f, -0.5f), glm::vec3(1.0f, 0.7f, 0.5f)};
    for (const int threads : {1, 2, 0}) {
        SCOPED_TRACE("threads " + std::to_string(threads));
        std::mutex mutex;
        std::vector<std::array<float, 3>> points;
        const BatchField field = [&](std::span<const glm::vec3> p, std::span<float> v) {
            ASSERT_EQ(p.size(), v.size());
            for (std::size_t i = 0; i < p.size(); ++i) v[i] = glm::length(p[i]) - 0.45f;
            std::lock_guard lock(mutex);
            for (const auto& q : p) points.push_back({q.x, q.y, q.z});
        };
        MeshSettings s = settings(37);
        s.threads = threads;
        MeshingStats stats;
        s.stats = &stats;
        const Mesh mesh = marching_cubes(field, box, s);
        test::expect_closed_manifold(mesh);
        const std::size_t evaluated = points.size();
        std::sort(points.begin(), points.end());
        EXPECT_EQ(std::unique(points.begin(), points.end()) - points.begin(),
                  std::ptrdiff_t(evaluated));
        // Nodes = cells + 1: 37 + 4 cells along x, ceil(1.7 * 37 / 2) + 4 along y and
        // ceil(37 / 2) + 4 along z.
        EXPECT_EQ(evaluated, std::size_t(42 * 37 * 24));
        EXPECT_EQ(stats.evaluations, evaluated);
    }
}

TEST(MarchingCubes, ScalarFieldRunsOnTheCallingThread) {
    // The ScalarField overload makes no thread-safety demand on the field.
    const std::thread::id caller = std::this_thread::get_id();
    std::size_t elsewhere = 0;
    const ScalarField field = [&](const glm::vec3& p) {
        elsewhere += std::this_thread::get_id() != caller;
        return glm::length(p) - 0.7f;
    };
    MeshSettings s = settings(64);
    s.threads = 2;
    test::expect_closed_manifold(marching_cubes(field, cube(1.0f), s));
    EXPECT_EQ(elsewhere, 0u);
}

TEST(MarchingCubes, ScalarAndBatchFieldsGiveTheSameMesh) {
    const ScalarField scalar =
        unite(sphere({-0.4f, 0.0f, 0.0f}, 0.5f), sphere({0.4f, 0.1f, 0.0f}, 0.45f));
    const BatchField batch = [&](std::span<const glm::vec3> p, std::span<float> v) {
        for (std::size_t i = 0; i < p.size(); ++i) v[i] = scalar(p[i]);
    };
    const Mesh a = marching_cubes(scalar, cube(1.0f), settings(45));
    const Mesh b = marching_cubes(batch, cube(1.0f), settings(45));
    ASSERT_EQ(a.positions.size(), b.positions.size());
    ASSERT_EQ(a.triangles, b.triangles);
    EXPECT_EQ(0, std::memcmp(a.positions.data(), b.positions.data(),
                             a.positions.size() * sizeof(glm::vec3)));
}

TEST(MarchingCubes, SameInputGivesSameMesh) {
    const ScalarField field =
        unite(sphere({-0.4f, 0.0f, 0.0f}, 0.5f), sphere({0.4f, 0.1f, 0.0f}, 0.45f));
    const Box box = cube(1.0f);
    const Mesh a = marching_cubes(field, box, settings(40));
    const Mesh b = marching_cubes(field, box, settings(40));
    ASSERT_EQ(a.positions.size(), b.positions.size());
    ASSERT_EQ(a.triangles, b.triangles);
    EXPECT_EQ(0, std::memcmp(a.positions.data(), b.positions.data(),
                             a.positions.size() * sizeof(glm::vec3)));
}

TEST(MarchingCubes, NonCubicBoxKeepsCubicCellsAndStaysInsideTheGrid) {
    const Box box{glm::vec3(-1.0f, -1.0f, -3.0f), glm::vec3(1.0f, 1.0f, 3.0f)};
    const ScalarField capsule = [](const glm::vec3& p) {
        const float z = std::clamp(p.z, -2.0f, 2.0f);
        return glm::length(p - glm::vec3(0.0f, 0.0f, z)) - 1.0f;
    };
    const MeshSettings s = settings(64);
    const Mesh mesh = marching_cubes(capsule, box, s);
    test::expect_closed_manifold(mesh);
    expect_inside(mesh, box, 0.0f);
    const double expected = kPi * 4.0 + 4.0 / 3.0 * kPi;
    EXPECT_NEAR(enclosed_volume(mesh), expected, 0.02 * expected);
}

TEST(MarchingCubes, TorusIsClosedAtCoarseAndFineResolutions) {
    const float major = 0.7f, minor = 0.12f;
    const ScalarField torus = [=](const glm::vec3& p) {
        const float ring = std::sqrt(p.x * p.x + p.y * p.y) - major;
        return std::sqrt(ring * ring + p.z * p.z) - minor;
    };
    const Box box{glm::vec3(-0.82f, -0.82f, -0.12f), glm::vec3(0.82f, 0.82f, 0.12f)};
    std::size_t ambiguous = 0;
    for (const int resolution : {6, 8, 11, 14, 20, 64, 150}) {
        SCOPED_TRACE("resolution " + std::to_string(resolution));
        const RecordedRun run = run_recorded(torus, box, settings(resolution));
        ambiguous += run.ambiguous_faces;
        test::expect_closed_manifold(run.mesh);
        if (resolution >= 64) {
            const double volume = 2.0 * kPi * kPi * major * minor * minor;
            EXPECT_NEAR(enclosed_volume(run.mesh), volume, 0.03 * volume);
        }
    }
    EXPECT_GT(ambiguous, 0u);
}

TEST(MarchingCubes, SpheresTouchingAtASaddleStayClosed) {
    // Two spheres that touch, nearly touch or barely overlap along a face diagonal of the
    // grid: around the contact the faces see one sphere at each end of a diagonal and must
    // decide whether the spheres connect there.
    const glm::vec3 direction = glm::normalize(glm::vec3(1.0f, 1.0f, 0.25f));
    const Box box{glm::vec3(-1.0f), glm::vec3(1.0f)};
    std::size_t ambiguous = 0;
    for (const float gap : {-0.01f, 0.0f, 0.01f}) {
        const float offset = 0.5f * (1.0f + gap);
        const ScalarField field =
            unite(sphere(-offset * direction, 0.5f), sphere(offset * direction, 0.5f));
        for (int resolution = 7; resolution <= 60; resolution += 4) {
            SCOPED_TRACE("gap " + std::to_string(gap) + ", resolution " +
                         std::to_string(resolution));
            const RecordedRun run = run_recorded(field, box, settings(resolution));
            ambiguous += run.ambiguous_faces;
            test::expect_closed_manifold(run.mesh);
            EXPECT_GT(enclosed_volume(run.mesh), 0.0);
        }
    }
    EXPECT_GT(ambiguous, 0u);
}

TEST(MarchingCubes, GyroidWithManyAmbiguousFacesIsClosed) {
    // Clipped by the box on every side, so this also exercises the border caps.
    for (const float frequency : {6.0f, 9.0f, 14.0f}) {
        SCOPED_TRACE("frequency " + std::to_string(frequency));
        const ScalarField gyroid = [=](const glm::vec3& p) {
            const glm::vec3 q = p * frequency;
            return std::sin(q.x) * std::cos(q.y) + std::sin(q.y) * std::cos(q.z) +
                   std::sin(q.z) * std::cos(q.x);
        };
        const RecordedRun run = run_recorded(gyroid, cube(1.0f), settings(24));
        EXPECT_GT(run.ambiguous_faces, 20u);
        test::expect_closed_manifold(run.mesh);
        EXPECT_GT(enclosed_volume(run.mesh), 0.0);
    }
}

TEST(MarchingCubes, CloudOfSmallRandomSpheresIsClosed) {
    std::mt19937 rng(20240607u);
    std::vector<glm::vec4> spheres(300);
    for (auto& s : spheres) {
        s = glm::vec4(next_unit(rng), next_unit(rng), next_unit(rng), 0.0f) * 2.0f - 1.0f;
        s.w = 0.02f + 0.08f * next_unit(rng);  // from a fifth of a cell to one cell
    }
    const ScalarField cloud = [&](const glm::vec3& p) {
        float d = std::numeric_limits<float>::max();
        for (const auto& s : spheres) d = std::min(d, glm::length(p - glm::vec3(s)) - s.w);
        return d;
    };
    const RecordedRun run = run_recorded(cloud, cube(1.1f), settings(22));
    EXPECT_GT(run.ambiguous_faces, 0u);
    test::expect_closed_manifold(run.mesh);
    EXPECT_GT(run.mesh.triangles.size(), 0u);
}

TEST(MarchingCubes, IntegerNoiseWithExactTiesIsClosed) {
    // Samples in {-2, ..., 2}: many exact zeros (outside) and saddles exactly at zero, where
    // the decider must still agree across each face.
    const ScalarField noise = [](const glm::vec3& p) {
        std::uint32_t bits[3];
        std::memcpy(bits, &p, sizeof bits);
        std::uint32_t hash = 2166136261u;
        for (const std::uint32_t b : bits) hash = (hash ^ b) * 16777619u;
        hash ^= hash >> 15;
        hash *= 0x2c1b3c6du;
        hash ^= hash >> 12;
        return float(int(hash % 5u) - 2);
    };
    for (const int resolution : {4, 9, 17, 30}) {
        SCOPED_TRACE("resolution " + std::to_string(resolution));
        const RecordedRun run = run_recorded(noise, cube(1.0f), settings(resolution, 1));
        EXPECT_GT(run.ambiguous_faces, 0u);
        test::expect_closed_manifold(run.mesh);
        expect_inside_grid(run.mesh, cube(1.0f), settings(resolution, 1));
    }
}

TEST(MarchingCubes, RandomNodeValuesExerciseEveryCaseAndStayClosed) {
    // White noise: every corner configuration and face decision shows up, including the
    // loops that pass the same ambiguous face twice. With h = 1 the nodes sit on integers.
    for (const std::uint32_t seed : {1u, 2u, 3u}) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        const ScalarField noise = [seed](const glm::vec3& p) {
            std::uint32_t bits[3];
            std::memcpy(bits, &p, sizeof bits);
            std::uint32_t hash = 2166136261u ^ seed;
            for (const std::uint32_t b : bits) hash = (hash ^ b) * 16777619u;
            hash ^= hash >> 15;
            hash *= 0x2c1b3c6du;
            hash ^= hash >> 12;
            return float(hash >> 8) / 8388608.0f - 1.0f;
        };
        const Box box{glm::vec3(0.0f), glm::vec3(24.0f)};
        const Mesh mesh = marching_cubes(noise, box, settings(24, 0));
        test::expect_closed_manifold(mesh);
        EXPECT_GT(enclosed_volume(mesh), 0.0);
        // Vertices off every grid line are the centres of loops that could not be fanned.
        std::size_t centres = 0;
        for (const auto& p : mesh.positions) {
            int on_grid = 0;
            for (int a = 0; a < 3; ++a) on_grid += p[a] == std::round(p[a]);
            centres += on_grid < 2;
        }
        EXPECT_GT(centres, 0u);
    }
}

TEST(MarchingCubes, SineNoiseAtManyScalesIsClosed) {
    const ScalarField sines = [](const glm::vec3& p) {
        return std::sin(7.1f * p.x + 0.3f) + std::sin(5.3f * p.y * p.x + 1.1f) +
               std::sin(9.7f * p.z + 2.0f * p.y) + 0.4f * std::sin(23.0f * (p.x + p.y + p.z));
    };
    for (const int resolution : {5, 13, 31, 48}) {
        SCOPED_TRACE("resolution " + std::to_string(resolution));
        const Box box{glm::vec3(-1.0f, -0.6f, -0.9f), glm::vec3(1.3f, 0.8f, 0.7f)};
        const Mesh mesh = marching_cubes(sines, box, settings(resolution, 0));
        test::expect_closed_manifold(mesh);
        expect_inside_grid(mesh, box, settings(resolution, 0));
    }
}

TEST(MarchingCubes, PositiveFieldGivesEmptyMesh) {
    const Mesh mesh =
        marching_cubes([](const glm::vec3&) { return 1.0f; }, cube(1.0f), settings(20));
    EXPECT_TRUE(mesh.positions.empty());
    EXPECT_TRUE(mesh.triangles.empty());
}

TEST(MarchingCubes, ZeroAndNonFiniteFieldsAreOutside) {
    for (const float value :
         {0.0f, -0.0f, std::numeric_limits<float>::quiet_NaN(),
          std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()}) {
        SCOPED_TRACE("value " + std::to_string(value));
        const Mesh mesh =
            marching_cubes([=](const glm::vec3&) { return value; }, cube(1.0f), settings(8));
        EXPECT_TRUE(mesh.triangles.empty());
    }
}

TEST(MarchingCubes, NonFiniteRegionCutsTheSurfaceButKeepsItClosed) {
    const ScalarField field = [](const glm::vec3& p) {
        if (p.x > 0.3f) return std::numeric_limits<float>::quiet_NaN();
        return glm::length(p) - 1.0f;
    };
    const Mesh mesh = marching_cubes(field, cube(1.0f), settings(32));
    test::expect_closed_manifold(mesh);
    float max_x = -1.0f;
    for (const auto& p : mesh.positions) max_x = std::max(max_x, p.x);
    EXPECT_LT(max_x, 0.3f + 1.0f / 16.0f + 1e-5f);
}

TEST(MarchingCubes, FieldStillNegativeAtTheBorderIsCappedHalfACellInside) {
    // The whole grid is inside. The mesh is the block of inner nodes (side l) grown by half a
    // cell, with its edges and corners chamfered where the border cells cut them.
    const MeshSettings s = settings(16, 2);
    const Mesh mesh = marching_cubes([](const glm::vec3&) { return -1.0f; }, cube(1.0f), s);
    test::expect_closed_manifold(mesh);
    const double h = 2.0 / 16.0;
    const double l = 2.0 + 2.0 * 2.0 * h - 2.0 * h;
    const double r = 0.5 * h;
    const double volume =
        l * l * l + 6.0 * l * l * r + 12.0 * l * r * r / 2.0 + 8.0 * r * r * r / 6.0;
    const double area =
        6.0 * l * l + 12.0 * l * r * std::sqrt(2.0) + 8.0 * std::sqrt(3.0) / 2.0 * r * r;
    EXPECT_NEAR(enclosed_volume(mesh), volume, 1e-5);
    EXPECT_NEAR(surface_area(mesh), area, 1e-5);
    expect_inside(mesh, cube(1.0f), float(1.5 * h + 1e-5));
}

TEST(MarchingCubes, SphereBiggerThanTheBoxIsClippedAndClosed) {
    const Box box = cube(1.0f);
    for (const int padding : {0, 1, 2}) {
        SCOPED_TRACE("padding " + std::to_string(padding));
        const MeshSettings s = settings(24, padding);
        const Mesh mesh = marching_cubes(sphere(glm::vec3(0.0f), 1.5f), box, s);
        test::expect_closed_manifold(mesh);
        expect_inside_grid(mesh, box, s);
        const double volume = enclosed_volume(mesh);
        EXPECT_GT(volume, 0.0);
        EXPECT_LT(volume, 4.0 / 3.0 * kPi * 1.5 * 1.5 * 1.5);
        const double grid_side = 2.0 + 2.0 * padding * (2.0 / 24.0);
        EXPECT_LT(volume, grid_side * grid_side * grid_side);
    }
}

TEST(MarchingCubes, HollowSolidHasInwardFacingInnerWall) {
    // Inside is everything outside a sphere, up to the border caps: a box with a spherical
    // hole, whose wall must face into the hole for the volume to come out right.
    const MeshSettings s = settings(48, 2);
    const ScalarField hole = [](const glm::vec3& p) { return 0.7f - glm::length(p); };
    const Mesh mesh = marching_cubes(hole, cube(1.0f), s);
    test::expect_closed_manifold(mesh);
    const double h = 2.0 / 48.0;
    const double side = 2.0 + 4.0 * h - h;
    const double expected = side * side * side - 4.0 / 3.0 * kPi * 0.7 * 0.7 * 0.7;
    EXPECT_NEAR(enclosed_volume(mesh), expected, 0.01 * expected);
}

TEST(MarchingCubes, FlatBoxStillGetsPaddingCells) {
    const Box box{glm::vec3(-1.0f, -1.0f, 0.0f), glm::vec3(1.0f, 1.0f, 0.0f)};
    const Mesh mesh = marching_cubes(sphere(glm::vec3(0.0f), 0.2f), box, settings(20, 3));
    test::expect_closed_manifold(mesh);
    EXPECT_FALSE(mesh.triangles.empty());
}

TEST(MarchingCubes, RejectsBadArguments) {
    const ScalarField field = sphere(glm::vec3(0.0f), 1.0f);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_THROW(marching_cubes(field, cube(1.0f), settings(0)), InputError);
    EXPECT_THROW(marching_cubes(field, cube(1.0f), settings(-5)), InputError);
    EXPECT_THROW(marching_cubes(field, cube(1.0f), settings(8, -1)), InputError);
    EXPECT_THROW(marching_cubes(field, cube(0.0f), settings(8)), InputError);
    EXPECT_THROW(marching_cubes(field, {glm::vec3(1.0f), glm::vec3(-1.0f)}, settings(8)),
                 InputError);
    EXPECT_THROW(marching_cubes(field, {glm::vec3(-1.0f, -1.0f, 1.0f), glm::vec3(1.0f, 1.0f, 0.9f)},
                                settings(8)),
                 InputError);
    EXPECT_THROW(marching_cubes(field, {glm::vec3(-1.0f), glm::vec3(nan)}, settings(8)),
                 InputError);
    EXPECT_THROW(marching_cubes(field, {glm::vec3(-inf), glm::vec3(1.0f)}, settings(8)),
                 InputError);
}

}  // namespace
}  // namespace sylva
