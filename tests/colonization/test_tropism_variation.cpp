// Tropism variation on space colonization: a seeded 3D noise field added to every
// growth direction. Off by default; when on, bounded, coherent in space, deterministic, and
// it changes the tree.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>

#include "colonization/attraction_points.h"
#include "colonization/colonization_growth.h"
#include "colonization/space_colonization.h"

namespace sylva {
namespace {

ColonizationGraph grow(const TreeParams& p) {
    const auto points = attraction_points(template_envelope(colonization_params(p)), 1500,
                                          PointDistribution::Uniform, 3);
    return colonize(points, glm::vec3(0.0f), colonization_settings(p));
}

bool same_graph(const ColonizationGraph& a, const ColonizationGraph& b) {
    return a.nodes.size() == b.nodes.size() &&
           std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(ColonizationNode)) ==
               0;
}

TEST(TropismVariation, OffByDefault) {
    EXPECT_FALSE(colonization_settings(TreeParams{}).tropism_field);
}

TEST(TropismVariation, BoundedCoherentAndSeeded) {
    TreeParams p;
    p.tropism_variation = 0.5;
    const auto field = colonization_settings(p).tropism_field;
    ASSERT_TRUE(field);
    p.seed = 2;
    const auto other = colonization_settings(p).tropism_field;
    bool differs = false;
    for (int i = 0; i < 200; ++i) {
        const glm::vec3 q(0.37f * i, 0.11f * i + 2.0f, -0.23f * i);
        const glm::vec3 v = field(q);
        EXPECT_LE(glm::length(v), 0.5f * std::sqrt(3.0f) + 1e-5f);
        // bend_frequency 0.5 cycles per meter: 1 cm away, the vector barely moves.
        EXPECT_LT(glm::distance(v, field(q + glm::vec3(0.01f, 0.0f, 0.0f))), 0.05f);
        differs = differs || glm::distance(v, other(q)) > 1e-3f;
    }
    EXPECT_TRUE(differs);
}

TEST(TropismVariation, ChangesTheTreeDeterministically) {
    TreeParams plain;
    TreeParams varied = plain;
    varied.tropism_variation = 0.6;
    EXPECT_TRUE(same_graph(grow(varied), grow(varied)));
    EXPECT_FALSE(same_graph(grow(varied), grow(plain)));
}

}  // namespace
}  // namespace sylva
