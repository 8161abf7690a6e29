// The angle graph (Schröder 2024, 3.2.3-3.2.4): faces, boundary strings and the planarity test,
// open boundaries, the canonical code, and label numbers at the largest sizes the readers take.
#include <gtest/gtest.h>

#include <algorithm>

#include "layout/limits.h"
#include "layout_test_helpers.h"

namespace sylva::layout {
namespace {

using testing::example;
using testing::grammar_of;

int count_of(const std::string& s, char c) {
    return static_cast<int>(std::count(s.begin(), s.end(), c));
}

TEST(LayoutAngleGraph, SquareHasFourCornersAndTwoFaces) {
    const Example ex = example("square");
    EXPECT_EQ(ex.dirs.degrees, (std::vector<double>{0, 90, 180, 270}));
    ASSERT_EQ(ex.graph.vertices.size(), 4u);
    EXPECT_EQ(ex.graph.edges(), 4);
    const Analysis a = analyze(ex.graph, ex.dirs);
    ASSERT_TRUE(a.planar) << a.why;
    EXPECT_TRUE(a.complete);
    EXPECT_EQ(a.polygons(), 1);
    ASSERT_EQ(a.walks.size(), 2u);
    EXPECT_NEAR(std::max(a.walks[0].turning, a.walks[1].turning), 360.0, 1e-9);
    EXPECT_NEAR(std::min(a.walks[0].turning, a.walks[1].turning), -360.0, 1e-9);
    EXPECT_EQ(boundary_string(a.boundary, ex.dirs), "^");
}

TEST(LayoutAngleGraph, BoundaryStringsOfPlanarGraphsHaveOneMorePositiveTurn) {
    for (const auto& [name, text] : builtin_examples()) {
        const Grammar& g = grammar_of(name);
        std::vector<const AngleGraph*> graphs;
        for (const AngleGraph& p : g.primitives) graphs.push_back(&p);
        for (const Rule& r : g.rules) graphs.push_back(&r.left);
        for (const AngleGraph* graph : graphs) {
            const Analysis a = analyze(*graph, g.dirs);
            ASSERT_TRUE(a.planar) << name << ": " << a.why;
            ASSERT_TRUE(a.single_boundary()) << name;
            double sum = 0;
            for (const BoundaryItem& item : a.boundary) sum += item.turn;
            EXPECT_NEAR(sum, 360.0, 1e-6);
            const std::string gbs = boundary_string(a.boundary, g.dirs);
            EXPECT_EQ(count_of(gbs, '^') - count_of(gbs, 'v'), 1) << name << ": " << gbs;
        }
    }
}

TEST(LayoutAngleGraph, PlanarityTestRefusesDartsOutOfOrder) {
    const Example ex = example("square");
    AngleGraph g = ex.graph;
    // Split one edge: the result is a partial graph whose boundary turns by 360, with the two
    // halves next to each other and a -180 turn between them (a loop gluing closes it).
    const int v = 0, i = 0, w = g.vertices[v][i].to;
    const int j = g.find(w, ex.dirs.opposite[g.vertices[v][i].dir]);
    g.vertices[v][i].to = -1;
    g.vertices[w][j].to = -1;
    const Analysis open = analyze(g, ex.dirs);
    ASSERT_TRUE(open.planar) << open.why;
    ASSERT_EQ(open.boundary.size(), 2u);
    EXPECT_TRUE(std::abs(open.boundary[0].turn + 180.0) < 1e-6 ||
                std::abs(open.boundary[1].turn + 180.0) < 1e-6);
    AngleGraph bad = ex.graph;
    std::swap(bad.vertices[0][0], bad.vertices[0][1]);
    EXPECT_FALSE(analyze(bad, ex.dirs).planar);
}

// A ring whose hole still has half-edges has an open boundary inside (turning -360) besides
// the outside one (+360). Such graphs are planar, but not graphs a rule is made of.
TEST(LayoutAngleGraph, AGraphMayHaveHalfEdgesOnTwoBoundaries) {
    const Example ex = example("hollow_square");
    const Analysis whole = analyze(ex.graph, ex.dirs);
    // For every edge on the outside and every edge on the courtyard: which strip is across.
    auto across = [&](int v, int i) {
        const int w = ex.graph.vertices[v][i].to;
        const int j = ex.graph.find(w, ex.dirs.opposite[ex.graph.vertices[v][i].dir]);
        for (std::size_t f = 0; f < whole.walks.size(); ++f)
            for (const auto& d : whole.walks[f].darts)
                if (d == std::pair{w, j}) return static_cast<int>(f);
        return -1;
    };
    std::vector<std::pair<int, int>> outside, courtyard;
    for (std::size_t f = 0; f < whole.walks.size(); ++f) {
        const Walk& walk = whole.walks[f];
        if (walk.color != 0) continue;
        (static_cast<int>(f) == whole.outer ? outside : courtyard) = walk.darts;
    }
    ASSERT_FALSE(outside.empty());
    ASSERT_FALSE(courtyard.empty());
    auto cut = [&](AngleGraph& g, std::pair<int, int> d) {
        const auto [v, i] = d;
        const int w = g.vertices[v][i].to;
        const int j = g.find(w, ex.dirs.opposite[g.vertices[v][i].dir]);
        g.vertices[v][i].to = -1;
        g.vertices[w][j].to = -1;
    };
    // The courtyard alone opened: one open boundary, and it is not the outside.
    AngleGraph inner = ex.graph;
    cut(inner, courtyard[0]);
    const Analysis a = analyze(inner, ex.dirs);
    ASSERT_TRUE(a.planar) << a.why;
    EXPECT_EQ(a.open_walks.size(), 1u);
    EXPECT_FALSE(a.single_boundary());
    // Both opened, through different strips: two open boundaries.
    AngleGraph both = inner;
    for (const auto& d : outside)
        if (across(d.first, d.second) != across(courtyard[0].first, courtyard[0].second)) {
            cut(both, d);
            break;
        }
    const Analysis b = analyze(both, ex.dirs);
    ASSERT_TRUE(b.planar) << b.why;
    EXPECT_EQ(b.open_walks.size(), 2u);
    EXPECT_FALSE(b.single_boundary());
    EXPECT_TRUE(b.boundary.empty());
}

TEST(LayoutAngleGraph, CanonicalCodeIgnoresVertexNumbering) {
    const Example ex = example("village");
    const int n = static_cast<int>(ex.graph.vertices.size());
    // Reverse the vertex numbering.
    AngleGraph r;
    r.vertices.resize(n);
    for (int v = 0; v < n; ++v) {
        r.vertices[n - 1 - v] = ex.graph.vertices[v];
        for (Dart& d : r.vertices[n - 1 - v]) d.to = d.to < 0 ? -1 : n - 1 - d.to;
    }
    EXPECT_EQ(canonical_code(r), canonical_code(ex.graph));
    AngleGraph recoloured = ex.graph;
    recoloured.vertices[0][0].left = (recoloured.vertices[0][0].left + 1) % ex.dirs.colors();
    EXPECT_NE(canonical_code(recoloured), canonical_code(ex.graph));
}

// Label numbers are unsigned 64-bit: at the most directions and colours the readers take,
// (dir x colours + left) x colours + right is exact (it overflowed a signed int once).
TEST(LayoutAngleGraph, LabelNumbersAreExactAtTheLargestSizes) {
    Directions dirs;
    dirs.palette.assign(kMaxColors, 0);
    const Label l{kMaxDirections - 1, kMaxColors - 1, kMaxColors - 2};
    const unsigned __int128 c = kMaxColors;
    const unsigned __int128 exact =
        (static_cast<unsigned __int128>(l.dir) * c + static_cast<unsigned>(l.left)) * c +
        static_cast<unsigned>(l.right);
    EXPECT_EQ(static_cast<unsigned __int128>(label_number(l, dirs)), exact);
    EXPECT_LT(label_number(l, dirs), std::uint64_t{1} << 63);
    EXPECT_EQ(label_number({0, 0, 1}, dirs), 1u);
    EXPECT_EQ(label_number({1, 0, 0}, dirs), static_cast<std::uint64_t>(kMaxColors) * kMaxColors);
}

}  // namespace
}  // namespace sylva::layout
