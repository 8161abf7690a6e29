// The one mesher entry: mesh() runs the mesher the settings name, exactly as calling it
// directly, and the names round-trip.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstring>
#include <glm/geometric.hpp>
#include <span>

#include "core/errors.h"
#include "marching/marching_cubes.h"
#include "marching/mesher.h"
#include "marching/vdb_mesher.h"

namespace sylva {
namespace {

const BatchField kSphere = [](std::span<const glm::vec3> points, std::span<float> values) {
    for (std::size_t i = 0; i < points.size(); ++i) values[i] = glm::length(points[i]) - 0.7f;
};
const Box kBox{glm::vec3(-1.0f), glm::vec3(1.0f)};

void expect_same_bytes(const Mesh& a, const Mesh& b) {
    ASSERT_EQ(a.positions.size(), b.positions.size());
    ASSERT_EQ(a.triangles.size(), b.triangles.size());
    EXPECT_EQ(
        std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(glm::vec3)),
        0);
    EXPECT_TRUE(a.triangles == b.triangles);
}

TEST(Mesher, RunsTheMesherTheSettingsName) {
    MeshSettings s;
    s.resolution = 24;
    s.vdb.adaptivity = 0.3;
    MeshingStats stats;
    s.stats = &stats;

    s.mesher = Mesher::Dense;
    const Mesh dense = mesh(kSphere, kBox, s);
    EXPECT_EQ(stats.blocks_meshed, stats.blocks_total);
    expect_same_bytes(dense, marching_cubes(kSphere, kBox, s));

    s.mesher = Mesher::Sparse;
    const Mesh sparse = mesh(kSphere, kBox, s);
    EXPECT_LT(stats.blocks_meshed, stats.blocks_total);
    expect_same_bytes(sparse, sparse_marching_cubes(kSphere, kBox, s));
    expect_same_bytes(sparse, dense);

    s.mesher = Mesher::Vdb;
    const Mesh vdb = mesh(kSphere, kBox, s);
    EXPECT_FALSE(vdb.triangles.empty());
    expect_same_bytes(vdb, vdb_mesh(kSphere, kBox, s));
    s.vdb.adaptivity = 0.0;
    EXPECT_GT(mesh(kSphere, kBox, s).triangles.size(), vdb.triangles.size());
}

TEST(Mesher, NamesRoundTrip) {
    for (Mesher m : {Mesher::Dense, Mesher::Sparse, Mesher::Vdb}) {
        ASSERT_FALSE(mesher_name(m).empty());
        EXPECT_EQ(mesher_from_name(mesher_name(m)), m);
    }
    EXPECT_EQ(mesher_name(Mesher::Dense), "dense");
    EXPECT_EQ(mesher_name(Mesher::Sparse), "sparse");
    EXPECT_EQ(mesher_name(Mesher::Vdb), "vdb");
    EXPECT_EQ(mesher_from_name("Sparse"), std::nullopt);
    EXPECT_EQ(mesher_from_name(""), std::nullopt);
}

TEST(Mesher, RejectsAValueThatNamesNoMesher) {
    MeshSettings s;
    s.mesher = static_cast<Mesher>(99);
    EXPECT_THROW(mesh(kSphere, kBox, s), InputError);
    EXPECT_TRUE(mesher_name(s.mesher).empty());
}

}  // namespace
}  // namespace sylva
