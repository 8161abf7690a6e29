// Every built-in template, at resolutions from 10 to 300, meshed by each mesher: closed
// 2-manifold meshes inside the padded box, and the meshers agree on the surface.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <string>
#include <tuple>
#include <unordered_map>

#include "core/mesh_checks.h"
#include "marching/grid.h"
#include "marching/mesher.h"
#include "tree/growth.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"

namespace sylva {
namespace {

struct Part {
    std::string name;
    Box box;
    std::function<float(const glm::vec3&)> field;
};

std::vector<Part> parts_of(const TreeFields& f) {
    std::vector<Part> parts{
        {"trunk", f.trunk_box, [&](const glm::vec3& p) { return (*f.trunk)(p); }}};
    if (f.crown)
        parts.push_back({"crown", f.crown_box, [&](const glm::vec3& p) { return (*f.crown)(p); }});
    return parts;
}

Mesh mesh_with(Mesher mesher, const Part& part, int resolution) {
    BatchField batch = [&](std::span<const glm::vec3> points, std::span<float> values) {
        for (size_t i = 0; i < points.size(); ++i) values[i] = part.field(points[i]);
    };
    MeshSettings settings;
    settings.mesher = mesher;
    settings.resolution = resolution;
    return mesh(batch, part.box, settings);
}

// Largest distance from a vertex of `a` to the nearest vertex of `b` (a spatial hash with
// cells of size h; searched within one cell around).
double nearest_vertex_gap(const Mesh& a, const Mesh& b, double h) {
    auto key = [h](const glm::vec3& p, int dx, int dy, int dz) {
        auto c = [h](float v, int d) { return static_cast<long long>(std::floor(v / h)) + d; };
        return (c(p.x, dx) * 73856093LL) ^ (c(p.y, dy) * 19349663LL) ^ (c(p.z, dz) * 83492791LL);
    };
    std::unordered_multimap<long long, glm::vec3> cells;
    for (const glm::vec3& p : b.positions) cells.emplace(key(p, 0, 0, 0), p);
    double worst = 0;
    for (const glm::vec3& p : a.positions) {
        double best = 2 * h;  // beyond the searched neighbourhood
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    auto [lo, hi] = cells.equal_range(key(p, dx, dy, dz));
                    for (auto it = lo; it != hi; ++it)
                        best = std::min(best, double(glm::length(it->second - p)));
                }
        worst = std::max(worst, best);
    }
    return worst;
}

// One test per resolution and template, so that the finest ones spread over the cores.
class EveryTemplate : public ::testing::TestWithParam<std::tuple<int, const TreeTemplate*>> {};

TEST_P(EveryTemplate, ClosedInsideTheBoxAndMeshersAgree) {
    const auto [resolution, t] = GetParam();
    TreeParams params = t->params;
    params.trunk_resolution = params.crown_resolution = resolution;
    Skeleton skeleton = grow(*t);
    TreeFields fields = tree_fields(skeleton, params);
    for (const Part& part : parts_of(fields)) {
        SCOPED_TRACE(t->name + " " + part.name + " at " + std::to_string(resolution));
        MeshSettings settings;
        settings.resolution = resolution;
        Grid grid = make_grid(part.box, settings);
        glm::dvec3 far = grid.node(grid.nodes[0] - 1, grid.nodes[1] - 1, grid.nodes[2] - 1);

        Mesh sparse = mesh_with(Mesher::Sparse, part, resolution);
        Mesh vdb = mesh_with(Mesher::Vdb, part, resolution);
        for (const Mesh* mesh : {&sparse, &vdb}) {
            MeshTopology topology = check_topology(*mesh);
            EXPECT_TRUE(topology.is_closed_manifold())
                << (mesh == &sparse ? "sparse" : "vdb") << ": boundary " << topology.boundary_edges
                << ", non-manifold edges " << topology.non_manifold_edges << ", vertices "
                << topology.non_manifold_vertices << ", misoriented " << topology.misoriented_edges
                << ", degenerate " << topology.degenerate_triangles;
            EXPECT_GT(mesh->triangles.size(), 0u);
            for (const glm::vec3& p : mesh->positions)
                for (int a = 0; a < 3; ++a) {
                    ASSERT_GT(p[a], grid.origin[a]);  // inside, never on the border
                    ASSERT_LT(p[a], far[a]);
                }
        }
        if (resolution <= 150) {  // the dense mesher evaluates every node: keep it quick
            Mesh dense = mesh_with(Mesher::Dense, part, resolution);
            EXPECT_EQ(dense.triangles.size(), sparse.triangles.size());
            EXPECT_EQ(dense.positions.size(), sparse.positions.size());
        }
        // The OpenVDB surface and the marching-cubes surface lie within a cell of each
        // other, sampled at every vertex both ways.
        EXPECT_LT(nearest_vertex_gap(vdb, sparse, grid.h), 1.5 * grid.h);
        EXPECT_LT(nearest_vertex_gap(sparse, vdb, grid.h), 1.5 * grid.h);
    }
}

INSTANTIATE_TEST_SUITE_P(Resolutions, EveryTemplate,
                         ::testing::Combine(::testing::Values(10, 25, 64, 150, 300),
                                            ::testing::ValuesIn(builtin_templates())),
                         [](const auto& param) {
                             return "r" + std::to_string(std::get<0>(param.param)) + "_" +
                                    std::get<1>(param.param)->name;
                         });

}  // namespace
}  // namespace sylva

namespace sylva {
namespace {

// Nothing reaches the grid's outer node layer (where meshes would be capped flat), even
// with the strongest blends at a fine grid: the boxes grow with what the blends add.
TEST(Boxes, StrongBlendsAreNeverClippedByTheGrid) {
    TreeTemplate t = load_template("seed_spruce");
    t.params.crown_fusion = 0.1;
    t.params.joint_blend = 0.2;
    t.params.trunk_resolution = t.params.crown_resolution = 200;
    Skeleton skeleton = grow(t);
    TreeFields fields = tree_fields(skeleton, t.params);
    for (const Part& part : parts_of(fields)) {
        SCOPED_TRACE(part.name);
        MeshSettings settings;
        settings.resolution = 200;
        Grid grid = make_grid(part.box, settings);
        glm::dvec3 far = grid.node(grid.nodes[0] - 1, grid.nodes[1] - 1, grid.nodes[2] - 1);
        Mesh mesh = mesh_with(Mesher::Sparse, part, 200);
        for (const glm::vec3& p : mesh.positions)
            for (int a = 0; a < 3; ++a) {
                ASSERT_GT(p[a], grid.origin[a] + grid.h);
                ASSERT_LT(p[a], far[a] - grid.h);
            }
    }
}

}  // namespace
}  // namespace sylva
