// Deriving grammars (Schröder 2024, 3.3): closed hierarchies where the example allows it, the
// limits that end the others reported, composed right-hand sides of any number of pieces,
// and grammars that always read back.
#include <gtest/gtest.h>

#include <cmath>

#include "layout/grammar_json.h"
#include "layout_test_helpers.h"

namespace sylva::layout {
namespace {

using testing::example;
using testing::grammar_of;

TEST(LayoutDerive, SquareYieldsOneStarterRuleAndItsHierarchyCloses) {
    const Grammar& g = grammar_of("square");
    EXPECT_EQ(g.primitives.size(), 4u);
    EXPECT_EQ(g.starters.size(), 1u);
    EXPECT_EQ(g.rules.size(), 0u);
    EXPECT_EQ(g.hierarchy.stopped_by, "closed");
    EXPECT_EQ(g.hierarchy.open_graphs, 0);
    // Chains of corners that turn past a full turn can never close: pruned, not grown forever.
    EXPECT_GT(g.hierarchy.dead_ends, 0);
    EXPECT_FALSE(g.hierarchy.example_added);
    EXPECT_EQ(g.starters[0].vertices.size(), 4u);
}

TEST(LayoutDerive, TheShapesWithFewNeighbourhoodsClose) {
    for (const char* name : {"l_shape", "t_shape"}) {
        const Grammar& g = grammar_of(name);
        EXPECT_EQ(g.hierarchy.stopped_by, "closed") << name;
        EXPECT_FALSE(g.rules.empty()) << name;
    }
}

// A regular polygon of 130 sides has 130 edge directions (label numbers once overflowed an
// int from direction 128 on). Like the square it is one starter rule and nothing else.
TEST(LayoutDerive, AnExampleWithManyEdgeDirectionsIsOneStarter) {
    std::string text = "p #e6ee9c";
    std::string vertices;
    const int n = 130;
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * M_PI * i / n;
        vertices += "v " + std::to_string(100.0 * std::cos(a)) + " " +
                    std::to_string(100.0 * std::sin(a)) + "\n";
        text += " " + std::to_string(i);
    }
    const Example ex = make_example(read_mesh_text(vertices + text + "\n", "ngon.mesh"));
    EXPECT_GE(ex.dirs.degrees.size(), 128u);
    const Grammar g = derive_grammar(ex);
    EXPECT_EQ(g.rules.size(), 0u);
    ASSERT_EQ(g.starters.size(), 1u);
    EXPECT_EQ(g.starters[0].vertices.size(), static_cast<std::size_t>(n));
}

TEST(LayoutDerive, EveryLimitThatEndsTheHierarchyIsReported) {
    const Example t = example("t_shape");
    DeriveSettings graphs;
    graphs.max_graphs = 40;
    const Grammar a = derive_grammar(t, graphs);
    EXPECT_EQ(a.hierarchy.stopped_by, "graphs");
    EXPECT_EQ(a.hierarchy.graphs, 40);
    EXPECT_GT(a.hierarchy.open_graphs, 0);
    DeriveSettings generations;
    generations.max_generations = 3;
    const Grammar b = derive_grammar(t, generations);
    EXPECT_EQ(b.hierarchy.stopped_by, "generations");
    EXPECT_EQ(b.hierarchy.generations, 3);
    DeriveSettings vertices;
    vertices.max_vertices = 3;
    EXPECT_GT(derive_grammar(t, vertices).hierarchy.vertex_limited, 0);
    // Without a limit the same example closes, and its starter is not the fallback.
    EXPECT_FALSE(grammar_of("t_shape").hierarchy.example_added);
}

// The grid's rules insert whole walls across several plots: their right sides are as many
// separate edges as the wall meets plot sides (R1 v R2 v ... of Schröder's figure 3.7).
TEST(LayoutDerive, RightSidesHaveAnyNumberOfPieces) {
    const Grammar& g = grammar_of("grid_of_plots");
    std::size_t most = 0;
    for (const Rule& r : g.rules) most = std::max(most, r.right.size());
    EXPECT_GE(most, 4u);
    DeriveSettings three;
    three.max_pieces = 3;
    three.max_graphs = 1500;
    EXPECT_GT(derive_grammar(example("grid_of_plots"), three).hierarchy.piece_limited, 0);
}

TEST(LayoutDerive, RuleSidesShareTheirBoundary) {
    for (const char* name : {"l_shape", "t_shape", "h_shape", "grid_of_plots", "village"}) {
        const Grammar& g = grammar_of(name);
        EXPECT_FALSE(g.rules.empty()) << name;
        for (const Rule& r : g.rules) {
            ASSERT_EQ(r.left_ports.size(), r.right_ports.size());
            ASSERT_EQ(static_cast<int>(r.left_ports.size()), r.left.half_edges());
            for (std::size_t k = 0; k < r.left_ports.size(); ++k) {
                const Port& lp = r.left_ports[k];
                const Port& rp = r.right_ports[k];
                const Piece& piece = r.right[rp.piece];
                const Label right = piece.floating
                                        ? (rp.dart == 0 ? piece.edge : reversed(piece.edge, g.dirs))
                                        : dart_label(piece.graph, rp.vertex, rp.dart);
                EXPECT_EQ(dart_label(r.left, lp.vertex, lp.dart), right) << name;
            }
        }
    }
}

TEST(LayoutDerive, GridYieldsTheWallRuleFromTwoComposedBoundaries) {
    // Schröder's (2024) example of R1 v R2: a wall across a plot (two T-junctions and the edge
    // between them) has the boundary of two separate edges put together with one extra
    // negative turn, so it can replace them (and be replaced by them).
    const Grammar& g = grammar_of("grid_of_plots");
    bool wall = false;
    for (const Rule& r : g.rules) {
        if (r.left.vertices.size() != 2 || r.right.size() != 2) continue;
        if (!r.right[0].floating || !r.right[1].floating) continue;
        wall = true;
        EXPECT_EQ(r.left.edges(), 1);
        EXPECT_EQ(r.left.half_edges(), 4);
    }
    EXPECT_TRUE(wall);
}

// What derive writes, the reader takes: a polygon of more vertices than the reader once
// allowed per graph (its starter is the whole example).
TEST(LayoutDerive, ADerivedGrammarAlwaysReadsBack) {
    std::string vertices, poly = "p #2e7d32";
    const int n = 4100;
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * M_PI * i / n;
        vertices += "v " + std::to_string(1000.0 * std::cos(a)) + " " +
                    std::to_string(1000.0 * std::sin(a)) + "\n";
        poly += " " + std::to_string(i);
    }
    const Grammar g = derive_grammar(make_example(read_mesh_text(vertices + poly + "\n", "big")));
    const std::string json = write_grammar_json(g);
    const Grammar back = read_grammar_json(json, "big.json");
    EXPECT_EQ(back.starters.size(), g.starters.size());
    EXPECT_EQ(write_grammar_json(back), json);
}

}  // namespace
}  // namespace sylva::layout
