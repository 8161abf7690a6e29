#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <glm/geometric.hpp>
#include <limits>
#include <mutex>
#include <numbers>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/mesh_checks.h"
#include "marching/grid.h"
#include "marching/marching_cubes.h"
#include "marching/vdb_mesher.h"
#include "tests/helpers.h"

namespace sylva {
namespace {

constexpr double kPi = std::numbers::pi;

ScalarField sphere(glm::vec3 center, float radius) {
    return [=](const glm::vec3& p) { return glm::length(p - center) - radius; };
}

// Ring of radius `major` around the z axis, tube radius `minor`.
ScalarField torus(float major, float minor) {
    return [=](const glm::vec3& p) {
        const float ring = std::sqrt(p.x * p.x + p.y * p.y) - major;
        return std::sqrt(ring * ring + p.z * p.z) - minor;
    };
}

ScalarField unite(ScalarField a, ScalarField b) {
    return [=](const glm::vec3& p) { return std::min(a(p), b(p)); };
}

BatchField batch(ScalarField f) {
    return [f = std::move(f)](std::span<const glm::vec3> points, std::span<float> values) {
        for (std::size_t i = 0; i < points.size(); ++i) values[i] = f(points[i]);
    };
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

MeshSettings adaptive(MeshSettings s, double adaptivity) {
    s.vdb.adaptivity = adaptivity;
    return s;
}

double cell_size(const Box& box, int resolution) {
    const glm::vec3 size = box.max - box.min;
    return std::max({size.x, size.y, size.z}) / double(resolution);
}

// The largest |field| over the mesh's vertices: how far they are from the surface.
double max_vertex_distance(const Mesh& mesh, const ScalarField& field) {
    double worst = 0.0;
    for (const auto& p : mesh.positions) worst = std::max(worst, double(std::abs(field(p))));
    return worst;
}

TEST(VdbMesher, SphereIsClosedOutwardManifold) {
    for (int resolution : {20, 64, 150}) {
        SCOPED_TRACE("resolution " + std::to_string(resolution));
        const Mesh mesh = vdb_mesh(batch(sphere({}, 1.0f)), cube(1.0f), settings(resolution));
        ASSERT_FALSE(mesh.triangles.empty());
        test::expect_closed_manifold(mesh);
        // Counter-clockwise seen from outside: the divergence theorem gives a positive volume.
        EXPECT_GT(enclosed_volume(mesh), 0.0);
    }
}

TEST(VdbMesher, SphereAreaAndVolumeMatchAnalytic) {
    for (int resolution : {64, 150}) {
        SCOPED_TRACE("resolution " + std::to_string(resolution));
        const Mesh mesh = vdb_mesh(batch(sphere({}, 1.0f)), cube(1.0f), settings(resolution));
        EXPECT_NEAR(surface_area(mesh), 4.0 * kPi, 0.03 * 4.0 * kPi);
        EXPECT_NEAR(enclosed_volume(mesh), 4.0 / 3.0 * kPi, 0.03 * 4.0 / 3.0 * kPi);
    }
}

// Both meshers put every vertex within a cell of the true surface, so they agree to a cell.
TEST(VdbMesher, VerticesLieOnTheSurfaceLikeMarchingCubes) {
    const ScalarField field = sphere({0.1f, -0.05f, 0.02f}, 1.0f);
    const Box box = cube(1.2f);
    for (int resolution : {20, 64}) {
        SCOPED_TRACE("resolution " + std::to_string(resolution));
        const double h = cell_size(box, resolution);
        const Mesh vdb = vdb_mesh(batch(field), box, settings(resolution));
        const Mesh mc = marching_cubes(field, box, settings(resolution));
        ASSERT_FALSE(vdb.positions.empty());
        EXPECT_LT(max_vertex_distance(vdb, field), h);
        EXPECT_LT(max_vertex_distance(mc, field), h);
        // One vertex per surface cell against one per crossed edge: about as many triangles.
        const double ratio = double(vdb.triangles.size()) / double(mc.triangles.size());
        EXPECT_GT(ratio, 1.0 / 1.5);
        EXPECT_LT(ratio, 1.5);
    }
}

// volumeToMesh merges cells only within one 8^3 leaf, so adaptivity 0.5 already reaches
// about one quad per leaf on smooth shapes; the chords cut a few percent off convex parts.
TEST(VdbMesher, AdaptivityGivesFewerTrianglesAndStaysClosed) {
    const BatchField field = batch(sphere({}, 1.0f));
    const Mesh uniform = vdb_mesh(field, cube(1.0f), settings(64));
    const Mesh merged = vdb_mesh(field, cube(1.0f), adaptive(settings(64), 0.5));
    EXPECT_LT(merged.triangles.size(), uniform.triangles.size() / 10);
    test::expect_closed_manifold(merged);
    EXPECT_NEAR(enclosed_volume(merged), 4.0 / 3.0 * kPi, 0.05 * 4.0 / 3.0 * kPi);
}

TEST(VdbMesher, TorusIsClosedWithItsVolume) {
    const float major = 0.7f, minor = 0.25f;
    const Box box{{-1.0f, -1.0f, -0.3f}, {1.0f, 1.0f, 0.3f}};
    const double volume = 2.0 * kPi * kPi * major * minor * minor;
    const Mesh uniform = vdb_mesh(batch(torus(major, minor)), box, settings(100));
    test::expect_closed_manifold(uniform);
    EXPECT_NEAR(enclosed_volume(uniform), volume, 0.03 * volume);

    const Mesh merged = vdb_mesh(batch(torus(major, minor)), box, adaptive(settings(100), 0.5));
    test::expect_closed_manifold(merged);
    EXPECT_LT(merged.triangles.size(), uniform.triangles.size() / 10);
    // The tube is 12 cells across: merged cells cut 8% of its volume.
    EXPECT_NEAR(enclosed_volume(merged), volume, 0.12 * volume);
}

TEST(VdbMesher, UnionOfSpheresIsClosedAndAgreesWithMarchingCubes) {
    const ScalarField field =
        unite(unite(sphere({-0.5f, 0.0f, 0.0f}, 0.6f), sphere({0.5f, 0.1f, 0.0f}, 0.55f)),
              sphere({0.0f, 0.0f, 0.6f}, 0.3f));
    const Box box{{-1.2f, -0.7f, -0.7f}, {1.2f, 0.7f, 1.0f}};
    const Mesh mc = marching_cubes(field, box, settings(80));
    const Mesh vdb = vdb_mesh(batch(field), box, settings(80));
    test::expect_closed_manifold(vdb);
    EXPECT_NEAR(enclosed_volume(vdb), enclosed_volume(mc), 0.02 * enclosed_volume(mc));
    EXPECT_NEAR(surface_area(vdb), surface_area(mc), 0.02 * surface_area(mc));

    const Mesh merged = vdb_mesh(batch(field), box, adaptive(settings(80), 0.5));
    test::expect_closed_manifold(merged);
    EXPECT_LT(merged.triangles.size(), vdb.triangles.size());
    EXPECT_NEAR(enclosed_volume(merged), enclosed_volume(mc), 0.12 * enclosed_volume(mc));
}

// A sample at (or within float noise of) zero would put every crossing on its edges at the
// node, and the cells around it would meet in triangles of no area.
TEST(VdbMesher, SamplesAtZeroGiveNoDegenerateTriangles) {
    const Box box = cube(1.0f);
    const auto s = settings(100);
    const Grid grid = make_grid(box, s);
    const glm::vec3 node(grid.node(30, 40, 50));
    // A speck around one node, far from a large sphere: a tiny closed component.
    const Mesh speck =
        vdb_mesh(batch(unite(sphere({0.3f, 0.3f, 0.3f}, 0.5f), sphere(node, 1e-6f))), box, s);
    test::expect_closed_manifold(speck);
    // A sphere through whole rows of nodes: exact zeros all over its surface.
    const glm::vec3 centre(grid.node(50, 50, 50));
    const Mesh through = vdb_mesh(batch(sphere(centre, float(40 * grid.h))), box, s);
    test::expect_closed_manifold(through);
}

// Two spheres whose gap is below a cell: the sign pattern has ambiguous faces and cubes.
TEST(VdbMesher, NearlyTouchingSpheresStayManifold) {
    for (float gap : {0.001f, 0.01f, 0.02f, 0.03f}) {
        SCOPED_TRACE("gap " + std::to_string(gap));
        const float r = 0.5f;
        const ScalarField field =
            unite(sphere({-r - gap / 2, 0.0f, 0.0f}, r), sphere({r + gap / 2, 0.013f, 0.007f}, r));
        const Mesh mesh =
            vdb_mesh(batch(field), {{-1.1f, -0.6f, -0.6f}, {1.1f, 0.6f, 0.6f}}, settings(40));
        test::expect_closed_manifold(mesh);
        EXPECT_GT(enclosed_volume(mesh), 0.0);
    }
}

TEST(VdbMesher, ClippedFieldIsCappedAtTheGridBorder) {
    // Negative everywhere: the surface is the grid border, pulled in to close the solid.
    const BatchField negative = [](std::span<const glm::vec3>, std::span<float> values) {
        std::fill(values.begin(), values.end(), -1.0f);
    };
    const Mesh all_inside = vdb_mesh(negative, cube(1.0f), settings(20));
    test::expect_closed_manifold(all_inside);
    EXPECT_GT(enclosed_volume(all_inside), 0.0);

    // A sphere larger than the grid: clipped on every side, still closed.
    const Box box = cube(1.0f);
    const auto s = settings(30, 1);
    const Mesh clipped = vdb_mesh(batch(sphere({}, 1.4f)), box, s);
    test::expect_closed_manifold(clipped);
    const Grid grid = make_grid(box, s);
    for (const auto& p : clipped.positions) {
        for (int a = 0; a < 3; ++a) {
            ASSERT_GT(p[a], grid.origin[a]);
            ASSERT_LT(p[a], grid.origin[a] + (grid.nodes[a] - 1) * grid.h);
        }
    }
}

TEST(VdbMesher, NonFiniteSamplesCountAsOutside) {
    const ScalarField base = sphere({}, 0.8f);
    const ScalarField field = [&](const glm::vec3& p) {
        return p.x > 0.5f ? std::numeric_limits<float>::quiet_NaN() : base(p);
    };
    const Mesh mesh = vdb_mesh(batch(field), cube(1.0f), settings(40));
    test::expect_closed_manifold(mesh);
    for (const auto& p : mesh.positions) EXPECT_LT(p.x, 0.6f);
}

TEST(VdbMesher, EmptyWhenNoSurface) {
    const Mesh mesh = vdb_mesh(batch(sphere({5.0f, 0.0f, 0.0f}, 1.0f)), cube(1.0f), settings(32));
    EXPECT_TRUE(mesh.positions.empty());
    EXPECT_TRUE(mesh.triangles.empty());
}

TEST(VdbMesher, SkipsBlocksFarFromTheSurfaceAndCountsEvaluations) {
    std::atomic<std::size_t> calls{0};
    const ScalarField f = sphere({0.1f, 0.0f, 0.0f}, 0.4f);
    const BatchField counted = [&](std::span<const glm::vec3> points, std::span<float> values) {
        calls += points.size();
        for (std::size_t i = 0; i < points.size(); ++i) values[i] = f(points[i]);
    };
    MeshingStats stats;
    auto s = settings(150);
    s.stats = &stats;
    const Mesh mesh = vdb_mesh(counted, cube(1.0f), s);
    test::expect_closed_manifold(mesh);
    EXPECT_EQ(stats.evaluations, calls.load());
    EXPECT_GT(stats.blocks_meshed, 0u);
    EXPECT_LT(stats.blocks_meshed, stats.blocks_total);
    const Grid grid = make_grid(cube(1.0f), s);
    const double nodes = double(grid.nodes[0]) * grid.nodes[1] * grid.nodes[2];
    // Sampled: a shell about 11 cells thick (the band, 3 cells each side, plus a 4^3
    // sub-block's half-diagonal each side) around a sphere of 30 cells radius.
    const double shell = 4.0 * kPi * 30.0 * 30.0 * 11.0;
    EXPECT_LT(double(stats.evaluations), 1.5 * shell);
    EXPECT_LT(double(stats.evaluations), 0.1 * nodes);
}

TEST(VdbMesher, SameMeshWhateverTheThreadCount) {
    const BatchField field = batch(unite(sphere({-0.3f, 0.0f, 0.0f}, 0.6f), torus(0.6f, 0.2f)));
    auto one = settings(70);
    one.threads = 1;
    auto two = settings(70);
    two.threads = 2;
    for (double adaptivity : {0.0, 0.5}) {
        const Mesh a = vdb_mesh(field, cube(1.0f), adaptive(one, adaptivity));
        const Mesh b = vdb_mesh(field, cube(1.0f), adaptive(two, adaptivity));
        ASSERT_EQ(a.positions.size(), b.positions.size());
        ASSERT_EQ(a.triangles.size(), b.triangles.size());
        EXPECT_EQ(std::memcmp(a.positions.data(), b.positions.data(),
                              a.positions.size() * sizeof(glm::vec3)),
                  0);
        EXPECT_TRUE(a.triangles == b.triangles);
    }
}

TEST(VdbMesher, ProgressRisesToOneOnce) {
    std::mutex mutex;
    std::vector<float> seen;
    auto s = settings(100);
    s.progress = [&](float fraction) {
        std::lock_guard lock(mutex);
        seen.push_back(fraction);
    };
    vdb_mesh(batch(sphere({}, 1.0f)), cube(1.0f), s);
    ASSERT_FALSE(seen.empty());
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    EXPECT_GE(seen.front(), 0.0f);
    EXPECT_EQ(seen.back(), 1.0f);
    EXPECT_EQ(std::count(seen.begin(), seen.end(), 1.0f), 1);
}

TEST(VdbMesher, CancelThrows) {
    std::atomic<bool> cancel{true};
    MeshingStats stats;
    stats.evaluations = 12345;
    auto s = settings(64);
    s.cancel = &cancel;
    s.stats = &stats;
    EXPECT_THROW(vdb_mesh(batch(sphere({}, 1.0f)), cube(1.0f), s), Cancelled);
    EXPECT_EQ(stats.evaluations, 12345u);  // only a completed run overwrites the stats

    // Cancelled while sampling, from the field itself.
    cancel = false;
    const ScalarField f = sphere({}, 1.0f);
    const BatchField cancelling = [&](std::span<const glm::vec3> points, std::span<float> values) {
        cancel = true;
        for (std::size_t i = 0; i < points.size(); ++i) values[i] = f(points[i]);
    };
    EXPECT_THROW(vdb_mesh(cancelling, cube(1.0f), s), Cancelled);

    // Cancelled from the progress callback, at each of its calls but the last (1: done).
    auto p = settings(64);
    p.threads = 1;
    p.cancel = &cancel;
    int calls = 0;
    p.progress = [&](float) { ++calls; };
    cancel = false;
    vdb_mesh(batch(f), cube(1.0f), p);
    const int total = calls;
    ASSERT_GE(total, 3);
    for (int at_call = 1; at_call < total; ++at_call) {
        cancel = false;
        calls = 0;
        p.progress = [&](float) {
            if (++calls == at_call) cancel = true;
        };
        EXPECT_THROW(vdb_mesh(batch(f), cube(1.0f), p), Cancelled) << "call " << at_call;
    }
}

TEST(VdbMesher, FieldExceptionsReachTheCaller) {
    const BatchField failing = [](std::span<const glm::vec3>, std::span<float>) {
        throw std::runtime_error("field failed");
    };
    EXPECT_THROW(vdb_mesh(failing, cube(1.0f), settings(40)), std::runtime_error);
}

TEST(VdbMesher, RejectsBadSettings) {
    const BatchField field = batch(sphere({}, 1.0f));
    EXPECT_THROW(vdb_mesh(field, cube(1.0f), settings(0)), InputError);
    EXPECT_THROW(vdb_mesh(field, cube(0.0f), settings(10)), InputError);
    EXPECT_THROW(vdb_mesh(field, cube(1.0f), adaptive(settings(10), 1.5)), InputError);
    auto thin = settings(10);
    thin.vdb.band_voxels = 0.5f;
    EXPECT_THROW(vdb_mesh(field, cube(1.0f), thin), InputError);
}

}  // namespace
}  // namespace sylva
