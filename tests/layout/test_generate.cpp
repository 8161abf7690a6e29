// Growing layouts (Schröder 2024, 3.4.1): on every shipped example, 50 variations at the
// default sizes are planar, locally similar to the example, mostly unlike the example and its
// starters and of many structures; variations grown to a size reach it; the same seed gives
// the same bytes whatever the thread count.
#include <gtest/gtest.h>

#include <set>

#include "layout/similarity.h"
#include "layout/variations.h"
#include "layout_test_helpers.h"

namespace sylva::layout {
namespace {

using testing::example;
using testing::grammar_of;
using testing::table_of;

TEST(LayoutGenerate, MovesKnowWhatTheyAdd) {
    EXPECT_EQ(table_of("t_shape").measure(), SizeMeasure::Polygons);
    EXPECT_TRUE(table_of("t_shape").can_grow());
    // An example of one polygon grows longer outlines, never more polygons.
    EXPECT_EQ(table_of("l_shape").measure(), SizeMeasure::Corners);
    EXPECT_TRUE(table_of("l_shape").can_grow());
    EXPECT_FALSE(table_of("square").can_grow());
    // The bare forest rectangle of the T is a starter some growing move fits.
    const GrowthTable& t = table_of("t_shape");
    double weight = 0;
    for (std::size_t s = 0; s < t.grammar().starters.size(); ++s)
        weight += t.starter_weight(static_cast<int>(s));
    EXPECT_GT(weight, 0.0);
}

// The acceptance properties on 50 seeds per example (the square, whose grammar is only its
// starter, is exempt from variety).
TEST(LayoutGenerate, FiftyVariationsArePlanarSimilarAndVaried) {
    for (const auto& [name, text] : builtin_examples()) {
        const Example ex = example(name);
        const GrowthTable& table = table_of(name);
        VariationsReport report;
        const std::vector<PolygonMesh> layouts = generate_layouts(table, 50, 1, {}, &report);
        ASSERT_EQ(layouts.size(), 50u);
        std::set<std::vector<int>> trivial{canonical_code(ex.graph)};
        for (const AngleGraph& s : table.grammar().starters) trivial.insert(canonical_code(s));
        std::set<std::vector<int>> distinct;
        int differ = 0;
        for (const PolygonMesh& m : layouts) {
            PolygonMesh copy = m;
            EXPECT_NO_THROW(validate_mesh(copy, name)) << name;
            std::string why;
            EXPECT_TRUE(locally_similar(ex, m, &why)) << name << ": " << why;
            const std::vector<int> key = structure_key(ex, m);
            distinct.insert(key);
            differ += !trivial.count(key);
        }
        if (!table.can_grow()) continue;
        EXPECT_GE(differ, 45) << name << ": too many copies of the example or a starter";
        EXPECT_GE(distinct.size(), 20u) << name;
    }
}

TEST(LayoutGenerate, VariationsReachTheSizeAskedFor) {
    for (const auto& [name, text] : builtin_examples()) {
        const GrowthTable& table = table_of(name);
        if (!table.can_grow()) continue;
        for (int factor : {2, 5, 10}) {
            VariationSettings s;
            s.size = factor * table.example_size();
            VariationsReport report;
            generate_layouts(table, 4, 11, s, &report);
            for (const VariationReport& r : report.items)
                EXPECT_LE(std::abs(r.size - s.size), 0.2 * s.size)
                    << name << " at " << factor << "x: " << r.size << " "
                    << measure_name(table.measure());
        }
    }
}

TEST(LayoutGenerate, SameSeedSameBytesWhateverTheThreads) {
    const GrowthTable& table = table_of("h_shape");
    VariationSettings one, two;
    one.threads = 1;
    two.threads = 2;
    const auto a = generate_layouts(table, 6, 42, one);
    const auto b = generate_layouts(table, 6, 42, two);
    const auto c = generate_layouts(table, 6, 43, two);
    bool any_differs = false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(write_mesh_json(a[i]), write_mesh_json(b[i]));
        any_differs = any_differs || write_mesh_json(a[i]) != write_mesh_json(c[i]);
    }
    EXPECT_TRUE(any_differs);
}

// An area instead of a size: the drawings come near it.
TEST(LayoutGenerate, AnAreaTargetIsReachedRoughly) {
    const GrowthTable& table = table_of("village");
    VariationSettings s;
    s.area = 5000;  // the example covers 690
    VariationsReport report;
    generate_layouts(table, 3, 5, s, &report);
    for (const VariationReport& r : report.items) {
        EXPECT_GT(r.area, 0.6 * s.area);
        EXPECT_LT(r.area, 2.0 * s.area);
    }
}

}  // namespace
}  // namespace sylva::layout
