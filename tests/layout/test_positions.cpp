// Positions (Schröder 2024, 3.4.2): the null space of the thesis's worked example, orthogonal
// graphs refined into rectangles, and edge lengths kept within the ranges asked for.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "layout/positions.h"
#include "layout/rectangularize.h"
#include "layout/variations.h"
#include "layout_test_helpers.h"

namespace sylva::layout {
namespace {

using testing::example;
using testing::table_of;

TEST(LayoutPositions, NullSpaceOfTheThesisExample) {
    const std::vector<double> a = {1, 2, -1, 1, -4, 2, 3, -1, 1, -11, -2, 0, -3, 1, 22};
    const auto basis = null_space(a, 3, 5);
    ASSERT_EQ(basis.size(), 2u);
    for (const auto& x : basis)
        for (int r = 0; r < 3; ++r) {
            double dot = 0;
            for (int c = 0; c < 5; ++c) dot += a[r * 5 + c] * x[c];
            EXPECT_NEAR(dot, 0.0, 1e-9);
        }
    const std::vector<double> first = {2, -2, -1, 1, 0};  // Schröder's (2024) t vector
    for (int c = 0; c < 5; ++c) EXPECT_NEAR(basis[0][c], first[c], 1e-9);
}

// Every face of a refined graph has four convex corners and no reflex one, and the input's
// vertices keep their numbers; grown graphs included.
TEST(LayoutPositions, OrthogonalGraphsRefineIntoRectangles) {
    for (const char* name : {"l_shape", "h_shape", "hollow_square", "village"}) {
        const Example ex = example(name);
        ASSERT_TRUE(orthogonal(ex.dirs));
        std::vector<AngleGraph> graphs{ex.graph};
        GrowSettings grow;
        grow.target = 4 * table_of(name).example_size();
        for (int s = 0; s < 3; ++s) graphs.push_back(grow_graph(table_of(name), 9 + s, grow));
        for (const AngleGraph& g : graphs) {
            const auto r = rectangularize(g, ex.dirs);
            ASSERT_TRUE(r) << name;
            for (std::size_t v = 0; v < g.vertices.size(); ++v)
                for (std::size_t i = 0; i < g.vertices[v].size(); ++i) {
                    const int k = r->graph.find(static_cast<int>(v), g.vertices[v][i].dir);
                    ASSERT_GE(k, 0);
                    EXPECT_EQ(r->origin[v][k],
                              (std::pair<int, int>{static_cast<int>(v), static_cast<int>(i)}));
                }
            const Analysis a = analyze(r->graph, ex.dirs);
            ASSERT_TRUE(a.planar && a.complete) << name;
            for (const Walk& w : a.walks) {
                if (w.turning > 0) continue;
                int convex = 0;
                for (std::size_t k = 0; k < w.darts.size(); ++k) {
                    const auto [pv, pi] = w.darts[(k + w.darts.size() - 1) % w.darts.size()];
                    const auto [v, i] = w.darts[k];
                    double gap = ex.dirs.degrees[r->graph.vertices[v][i].dir] -
                                 ex.dirs.degrees[ex.dirs.opposite[r->graph.vertices[pv][pi].dir]];
                    if (gap <= 0) gap += 360;
                    EXPECT_NE(std::lround(gap), 270) << name << ": a reflex corner left";
                    convex += std::lround(gap) == 90;
                }
                EXPECT_EQ(convex, 4) << name;
            }
        }
    }
}

TEST(LayoutPositions, EdgeClassesAreColourPairs) {
    const Example ex = example("village");
    const std::vector<std::string> classes = edge_classes(ex.dirs);
    for (const char* c : {"meadow/outside", "forest/path", "meadow/path", "meadow", "path"})
        EXPECT_TRUE(std::count(classes.begin(), classes.end(), std::string(c))) << c;
}

// A range asked for holds wherever the drawing reports it kept the ranges.
TEST(LayoutPositions, LengthRangesHold) {
    VariationSettings s;
    s.size = 20;
    s.lengths.ranges["forest/outside"] = {14.0, 18.0};
    VariationsReport report;
    const auto layouts = generate_layouts(table_of("village"), 6, 3, s, &report);
    int kept = 0;
    for (std::size_t i = 0; i < layouts.size(); ++i) {
        if (report.items[i].relax != 0) continue;
        ++kept;
        const PolygonMesh& m = layouts[i];
        // The forest row's outer side is the top of the plan.
        for (const Polygon& p : m.polygons) {
            if (p.color != 0x2e7d32) continue;
            const std::size_t n = p.vertices.size();
            for (std::size_t k = 0; k < n; ++k) {
                const glm::dvec2 a = m.vertices[p.vertices[k]],
                                 b = m.vertices[p.vertices[(k + 1) % n]];
                double top = -1e300;
                for (const glm::dvec2& q : m.vertices) top = std::max(top, q.y);
                if (std::abs(a.y - top) < 1e-9 && std::abs(b.y - top) < 1e-9) {
                    EXPECT_GE(glm::length(b - a), 14.0 * (1 - 2e-3));
                    EXPECT_LE(glm::length(b - a), 18.0 * (1 + 2e-3));
                }
            }
        }
    }
    EXPECT_GT(kept, 0);
}

}  // namespace
}  // namespace sylva::layout
