// The graph grammar of Schröder (2024, section 3.3.4) after Merrell (2023), as data: the
// example's directions and colours, its primitives, the starter rules (empty graph -> a
// complete graph) and the double-pushout rules L <-> {R1, R2, ...}, whose two sides share one
// boundary (the interface graph). derive.h makes a grammar from an example, generate.h grows
// graphs with it, grammar_json.h reads and writes it.
#pragma once

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

// How the graph hierarchy went, and which limit ended it.
struct HierarchyReport {
    int graphs = 0;       // graphs made, duplicates removed
    int generations = 0;  // generations grown (1: the primitives)
    int open_graphs = 0;  // graphs still open when growth stopped (0: the grammar is complete)
    // "closed" (no graph left open), "graphs", "seconds" or "generations": the limit that
    // ended growth (DeriveSettings).
    std::string stopped_by = "closed";
    int vertex_limited = 0;      // graphs not made because of DeriveSettings::max_vertices
    int piece_limited = 0;       // boundaries not decomposed because of max_pieces
    int decompositions_cut = 0;  // decompositions ended by max_decomposition_steps
    int multi_boundary = 0;      // graphs with more than one open boundary (grown, no rules)
    int dead_ends = 0;           // graphs dropped because no face could close their boundary
    bool example_added = false;  // the example was added as a starter (growth never made it)
};

struct Grammar {
    Directions dirs;
    std::vector<AngleGraph> primitives;
    std::vector<AngleGraph> starters;
    std::vector<Rule> rules;
    HierarchyReport hierarchy;
    int example_vertices = 0;
    int example_polygons = 0;
};

// The boundary of a piece (a floating edge: its two ends, each turning 180 degrees).
Boundary piece_boundary(const Piece& piece, const Directions& dirs);

}  // namespace sylva::layout
