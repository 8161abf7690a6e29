// Deriving a graph grammar from one example (Schröder 2024, section 3.3, after Merrell 2023) and
// growing new angle graphs with it (3.4.1).
//
// Derivation: the split operation cuts every edge of the example's angle graph; the
// one-vertex pieces left are the primitives (generation 1; generation 0 are the distinct
// edges). The graph hierarchy is grown generation by generation: each graph of the newest
// generation gets every loop gluing its boundary string allows (two opposite half-edges next
// to each other with a -180 degree turn between them) and every branch gluing with a
// primitive. A new graph L is then tested:
//   - complete (no half-edges): a starter rule (empty graph -> L); L leaves the hierarchy;
//   - its boundary equals that of an earlier graph R, or is composed of the boundaries of
//     several earlier graphs R1 v R2 ... (one extra negative turn per joint, found
//     recursively): a DPO rule L <-> {R1, R2, ...} (the interface is the common boundary);
//     L leaves the hierarchy, since the rule reduces it;
//   - else L stays and grows in the next generation.
// Growth stops when no graph is left, or at the limits in DeriveSettings (the hierarchy of
// most inputs does not empty itself; the grammar is then partial, as Schröder 2024 says).
//
// Generation: a starter rule gives a complete graph; then random rules are applied in either
// direction: the matched side is cut out (its half-edges become the DPO interface) and the
// other side glued in along the same boundary. Every result is checked with the planarity
// test of angle_graph.h before it is kept.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "layout/angle_graph.h"

namespace sylva::layout {

// One connected side piece of a rule: a partial angle graph, or an edge alone (generation 0)
// whose two ends are open.
struct Piece {
    AngleGraph graph;
    bool floating = false;
    Label edge;  // floating: the edge, oriented from its tail end to its head end
};

// A place on a rule side's boundary: a half-edge (piece, vertex, dart), or a floating edge's
// end (piece, -1, 0 = head, 1 = tail).
struct Port {
    int piece = 0, vertex = -1, dart = 0;
};

// L <-> {R1, R2, ...}: left_ports[i] and right_ports[i] are the same place of the common
// boundary (the interface graph of the double pushout).
struct Rule {
    AngleGraph left;
    std::vector<Port> left_ports;
    std::vector<Piece> right;
    std::vector<Port> right_ports;
    std::string boundary;  // the common boundary string
};

struct Grammar {
    Directions dirs;
    std::vector<AngleGraph> primitives;
    std::vector<AngleGraph> starters;
    std::vector<Rule> rules;
    // How the hierarchy went: graphs made (after removing duplicates), generations grown,
    // graphs still open when growth stopped (0: the grammar reduces every graph it met).
    int hierarchy_graphs = 0;
    int generations = 0;
    int open_graphs = 0;
    int example_vertices = 0;
};

struct DeriveSettings {
    int max_generations = 16;
    int max_graphs = 3000;  // graphs in the hierarchy
    int max_vertices = 0;   // per hierarchy graph; 0: the example's vertex count
    int max_pieces = 3;     // right-hand pieces per rule
};

Grammar derive_grammar(const Example& example, const DeriveSettings& settings = {});

struct GenerateSettings {
    int steps = 16;        // rule applications tried
    int max_vertices = 0;  // 0: 3 x the example's vertex count (at least 24)
    double grow = 0.7;     // chance of using a rule constructively (right -> left)
};

// A complete angle graph grown from the grammar with `seed` (the same seed, the same graph).
AngleGraph derive_graph(const Grammar& grammar, std::uint64_t seed,
                        const GenerateSettings& settings = {});

// The boundary of a piece (a floating edge: its two ends, each turning 180 degrees).
Boundary piece_boundary(const Piece& piece, const Directions& dirs);

// Grammar files (JSON, "format": "sylva-layout-grammar"). read_grammar_json checks every
// index and every graph (InputError naming the key).
std::string write_grammar_json(const Grammar& grammar);
Grammar read_grammar_json(const std::string& text, const std::string& source = "grammar");

}  // namespace sylva::layout
