// The method on the shipped examples: angle graphs and boundary strings, the derived
// grammars (the square: one starter rule, nothing else), and the acceptance properties of
// generated layouts: planar, only the example's edge directions, every vertex neighbourhood
// found in the example, the same seed giving the same layout.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <tuple>

#include "core/errors.h"
#include "layout/angle_graph.h"
#include "layout/graph_grammar.h"
#include "layout/layout_cli.h"
#include "layout/positions.h"

namespace sylva::layout {
namespace {

Example example(const std::string& name) {
    return make_example(load_example(name));
}

// Deriving the larger examples takes a few hundred milliseconds (seconds under the
// sanitizers): each grammar is derived once for all tests.
const Grammar& grammar_of(const std::string& name) {
    static std::map<std::string, Grammar> cache;
    auto it = cache.find(name);
    if (it == cache.end()) it = cache.emplace(name, derive_grammar(example(name))).first;
    return it->second;
}

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
    ASSERT_EQ(a.walks.size(), 2u);
    EXPECT_NEAR(std::max(a.walks[0].turning, a.walks[1].turning), 360.0, 1e-9);
    EXPECT_NEAR(std::min(a.walks[0].turning, a.walks[1].turning), -360.0, 1e-9);
    EXPECT_EQ(boundary_string(a.boundary, ex.dirs), "^");
}

TEST(LayoutAngleGraph, BoundaryStringsOfPlanarGraphsHaveOneMorePositiveTurn) {
    for (const auto& [name, text] : builtin_examples()) {
        const Example ex = example(name);
        const Grammar& g = grammar_of(name);
        std::vector<const AngleGraph*> graphs;
        for (const AngleGraph& p : g.primitives) graphs.push_back(&p);
        for (const Rule& r : g.rules) graphs.push_back(&r.left);
        for (const AngleGraph* graph : graphs) {
            const Analysis a = analyze(*graph, ex.dirs);
            ASSERT_TRUE(a.planar) << name << ": " << a.why;
            double sum = 0;
            for (const BoundaryItem& item : a.boundary) sum += item.turn;
            EXPECT_NEAR(sum, 360.0, 1e-6);
            const std::string gbs = boundary_string(a.boundary, ex.dirs);
            EXPECT_EQ(count_of(gbs, '^') - count_of(gbs, 'v'), 1) << name << ": " << gbs;
        }
    }
}

TEST(LayoutAngleGraph, PlanarityTestRefusesASelfCrossingLoop) {
    // Square corners glued round twice would need a second full turn: cut the square's
    // graph and re-glue a corner to itself the wrong way, and the test must say no.
    const Example ex = example("square");
    AngleGraph g = ex.graph;
    // Split one edge: the result is a partial graph whose boundary turns by 360.
    const int v = 0, i = 0, w = g.vertices[v][i].to;
    const int j = g.find(w, ex.dirs.opposite[g.vertices[v][i].dir]);
    g.vertices[v][i].to = -1;
    g.vertices[w][j].to = -1;
    const Analysis open = analyze(g, ex.dirs);
    ASSERT_TRUE(open.planar) << open.why;
    ASSERT_EQ(open.boundary.size(), 2u);
    // Two half-edges next to each other with a -180 turn: the loop gluing closes the face.
    EXPECT_TRUE(std::abs(open.boundary[0].turn + 180.0) < 1e-6 ||
                std::abs(open.boundary[1].turn + 180.0) < 1e-6);
    // A vertex with darts out of counter-clockwise order is refused.
    AngleGraph bad = ex.graph;
    std::swap(bad.vertices[0][0], bad.vertices[0][1]);
    EXPECT_FALSE(analyze(bad, ex.dirs).planar);
}

TEST(LayoutGrammar, SquareYieldsOneStarterRuleAndNoOthers) {
    const Grammar& g = grammar_of("square");
    EXPECT_EQ(g.primitives.size(), 4u);
    EXPECT_EQ(g.starters.size(), 1u);
    EXPECT_EQ(g.rules.size(), 0u);
    EXPECT_EQ(g.open_graphs, 0);
    EXPECT_EQ(g.starters[0].vertices.size(), 4u);
}

// A regular polygon of 130 sides has 130 edge directions: the boundary keys once packed a
// label into one int that overflowed from direction 128 on (undefined; in practice keys
// wrapped and could collide). Like the square it is one starter rule and nothing else.
TEST(LayoutGrammar, AnExampleWithManyEdgeDirectionsIsOneStarter) {
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
    EXPECT_EQ(g.starters.size(), 1u);
    EXPECT_EQ(g.rules.size(), 0u);
    ASSERT_EQ(g.starters.size(), 1u);
    EXPECT_EQ(g.starters[0].vertices.size(), static_cast<std::size_t>(n));
}

TEST(LayoutGrammar, RulesSidesShareTheirBoundary) {
    for (const char* name : {"l_shape", "t_shape", "h_shape", "grid_of_plots"}) {
        const Example ex = example(name);
        const Grammar& g = grammar_of(name);
        EXPECT_FALSE(g.rules.empty()) << name;
        for (const Rule& r : g.rules) {
            ASSERT_EQ(r.left_ports.size(), r.right_ports.size());
            ASSERT_EQ(static_cast<int>(r.left_ports.size()), r.left.half_edges());
            for (std::size_t k = 0; k < r.left_ports.size(); ++k) {
                const Port& lp = r.left_ports[k];
                const Port& rp = r.right_ports[k];
                const Piece& piece = r.right[rp.piece];
                const Label right =
                    piece.floating ? (rp.dart == 0 ? piece.edge : reversed(piece.edge, ex.dirs))
                                   : dart_label(piece.graph, rp.vertex, rp.dart);
                EXPECT_EQ(dart_label(r.left, lp.vertex, lp.dart), right) << name;
            }
        }
    }
}

TEST(LayoutGrammar, GridYieldsTheWallRuleFromTwoComposedBoundaries) {
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

TEST(LayoutGrammar, GrammarFilesRoundTripAndRefuseBadIndices) {
    const Grammar& g = grammar_of("t_shape");
    const std::string json = write_grammar_json(g);
    const Grammar back = read_grammar_json(json, "t.json");
    EXPECT_TRUE(write_grammar_json(back) == json);
    std::string bad = json;
    const std::size_t at = bad.find("\"starters\"");
    ASSERT_NE(at, std::string::npos);
    bad.replace(bad.find("[", bad.find("[", at) + 1) + 1, 0, "[[99,0,-1]],");
    try {
        read_grammar_json(bad, "t.json");
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("starters[0]"), std::string::npos) << e.what();
    }
    EXPECT_THROW(read_grammar_json("{\"format\": 3}"), InputError);
}

TEST(LayoutPositions, NullSpaceOfTheSeedsExample) {
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

// A vertex neighbourhood: its edge directions (0.001 degree) with the colours either side.
using Star = std::vector<std::tuple<long, std::uint32_t, std::uint32_t>>;

std::set<Star> stars_of(const Example& ex) {
    std::set<Star> out;
    for (std::size_t v = 0; v < ex.graph.vertices.size(); ++v) {
        Star s;
        for (const Label& l : star(ex.graph, static_cast<int>(v)))
            s.emplace_back(std::lround(ex.dirs.degrees[l.dir] * 1000.0) % 360000,
                           ex.dirs.palette[l.left] | (l.left ? 0 : 0xff000000u),
                           ex.dirs.palette[l.right] | (l.right ? 0 : 0xff000000u));
        out.insert(s);
    }
    return out;
}

TEST(LayoutGenerate, EveryOutputIsPlanarAndLocallySimilarToItsExample) {
    for (const auto& [name, text] : builtin_examples()) {
        const Example ex = example(name);
        const std::set<Star> input_stars = stars_of(ex);
        std::set<long> input_dirs;
        for (double d : ex.dirs.degrees) input_dirs.insert(std::lround(d * 1000.0) % 360000);
        const Grammar& g = grammar_of(name);
        const std::vector<PolygonMesh> layouts = generate_layouts(g, 12, 7);
        ASSERT_EQ(layouts.size(), 12u);
        int distinct_sizes = 0;
        std::set<std::size_t> sizes;
        for (const PolygonMesh& m : layouts) {
            PolygonMesh copy = m;
            // Planar: no crossing edges, every polygon simple and closed, no overlaps.
            EXPECT_NO_THROW(validate_mesh(copy, name)) << name;
            const Example out = make_example(m);
            for (double d : out.dirs.degrees)
                EXPECT_TRUE(input_dirs.count(std::lround(d * 1000.0) % 360000))
                    << name << ": direction " << d;
            for (const Star& s : stars_of(out))
                EXPECT_TRUE(input_stars.count(s)) << name << ": a new vertex neighbourhood";
            sizes.insert(m.polygons.size() * 1000 + m.vertices.size());
        }
        distinct_sizes = static_cast<int>(sizes.size());
        if (!g.rules.empty()) {
            EXPECT_GT(distinct_sizes, 1) << name << ": the rules never changed the structure";
        }
    }
}

TEST(LayoutGenerate, SameSeedSameOutput) {
    const Grammar& g = grammar_of("h_shape");
    const auto a = generate_layouts(g, 5, 42);
    const auto b = generate_layouts(g, 5, 42);
    const auto c = generate_layouts(g, 5, 43);
    ASSERT_EQ(a.size(), b.size());
    bool any_differs = false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(write_mesh_json(a[i]), write_mesh_json(b[i]));
        any_differs = any_differs || write_mesh_json(a[i]) != write_mesh_json(c[i]);
    }
    EXPECT_TRUE(any_differs);
}

TEST(LayoutCli, GenerateWritesJsonAndSvgForEveryVariation) {
    const auto dir =
        std::filesystem::temp_directory_path() / ("sylva_layout_cli_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::FILE* null = std::fopen("/dev/null", "w");
    EXPECT_EQ(run_layout_cli({"layout", "generate", "village", "--count", "3", "--seed", "5", "-o",
                              dir.string()},
                             null, null),
              0);
    for (const char* f : {"layout_000.json", "layout_000.svg", "layout_002.json", "layout_002.svg"})
        EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
    EXPECT_FALSE(std::filesystem::exists(dir / "layout_003.json"));
    const auto grammar = dir / "g.json";
    EXPECT_EQ(run_layout_cli({"layout", "derive", "l_shape", "-o", grammar.string()}, null, null),
              0);
    EXPECT_EQ(run_layout_cli({"layout", "generate", grammar.string(), "--count", "2", "-o",
                              (dir / "g").string()},
                             null, null),
              0);
    EXPECT_TRUE(std::filesystem::exists(dir / "g" / "layout_001.svg"));
    EXPECT_THROW(
        run_layout_cli({"layout", "derive", "no_such_example", "-o", grammar.string()}, null, null),
        InputError);
    EXPECT_EQ(run_layout_cli({"layout", "generate", "square", "--bogus", "-o", grammar.string()},
                             null, null),
              2);
    std::fclose(null);
    std::filesystem::remove_all(dir);
}

// The output folder is made or refused before any layout is derived, and a generate that
// fails leaves no folder it made.
TEST(LayoutCli, TheOutputFolderIsRefusedFirstAndNotLeftBehind) {
    namespace fs = std::filesystem;
    const fs::path dir =
        fs::temp_directory_path() / ("sylva_layout_out_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::FILE* null = std::fopen("/dev/null", "w");
    { std::ofstream(dir / "plain") << "x"; }
    // A file on the way: an IoError naming the path, before the example is even read.
    const fs::path under_file = dir / "plain" / "out";
    try {
        run_layout_cli({"layout", "generate", "no_such_example", "-o", under_file.string()}, null,
                       null);
        ADD_FAILURE() << "accepted";
    } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find(under_file.string()), std::string::npos) << e.what();
    }
    // A generate that fails (no such example) after the folder was made removes it.
    const fs::path made = dir / "a" / "b";
    EXPECT_THROW(
        run_layout_cli({"layout", "generate", "no_such_example", "-o", made.string()}, null, null),
        InputError);
    EXPECT_FALSE(fs::exists(dir / "a"));
    std::fclose(null);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace sylva::layout
