// Growing new angle graphs with a grammar (Schröder 2024, section 3.4.1; Merrell 2023).
//
// Every rule L <-> {R1, ...} is a pair of moves, one each way: cut one side out of the graph
// (its match, found at every place it occurs: rule_match.h) and glue the other in along the
// same ports. A move changes the layout's size by a known amount, from the two sides alone:
// the faces of a connected planar graph are its edges minus its vertices plus 2, so a move
// adds (E - V)(glued side) - (E - V)(cut side) faces. Growing a graph to a target size:
//   1. a starter rule, drawn among the starters no larger than the target, weighted by how
//      many growing moves fit it (a bare starter that no rule extends is a dead end);
//   2. moves that add structure, at random places of the graph (a random vertex or edge,
//      then a random move that can start there), never past the target by more than
//      `overshoot`; now and then a move that keeps the size, for variety;
//   3. once the target is reached, a few size-keeping moves reshape what was grown.
// Every graph in between is complete and passes the planarity test of angle_graph.h. Sizes
// count polygons, or corners for a grammar whose rules never change the number of polygons
// (an example of one polygon grows into longer outlines, never into more polygons).
//
// GrowthTable is immutable once made and may be shared by threads; grow_graph is reentrant.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "layout/graph_grammar.h"
#include "layout/rule_match.h"

namespace sylva::layout {

enum class SizeMeasure { Polygons, Corners };
const char* measure_name(SizeMeasure m);  // "polygons" or "corners"

// A grammar prepared for growing: its moves, what each adds, and indices from a star or an
// edge label to the moves that can start there. Holds its own copy of the grammar.
class GrowthTable {
  public:
    explicit GrowthTable(Grammar grammar);
    GrowthTable(const GrowthTable&) = delete;
    GrowthTable& operator=(const GrowthTable&) = delete;

    const Grammar& grammar() const { return grammar_; }
    SizeMeasure measure() const { return measure_; }
    // The size of a complete graph in this table's measure.
    int size_of(const AngleGraph& g, const Analysis& a) const;
    // The example's size, and whether any move grows a layout.
    int example_size() const { return example_size_; }
    bool can_grow() const { return can_grow_; }
    // Moves by what they do: adding to the size, keeping it, taking from it.
    int moves(int kind) const;

    // Implementation data, used by grow_graph.
    struct Side {
        std::vector<const Piece*> pieces;
        const std::vector<Port>* ports = nullptr;
        std::vector<std::vector<int>> stars;  // per piece, per vertex
    };
    struct Move {
        int rule = 0;
        bool forward = true;  // cut the left side, glue the right
        Side from, to;
        int delta = 0;  // size change, in the measure
    };
    // A move that can start at a graph vertex (a vertex piece's vertex with that star) or
    // at an edge (a floating piece with that label).
    struct Entry {
        int move = 0, piece = 0, vertex = -1;  // vertex -1: a floating piece
    };
    static constexpr int kGrow = 0, kKeep = 1, kShrink = 2;

    const std::vector<Move>& move_list() const { return moves_; }
    const std::vector<Entry>& at_star(int kind, int star) const;
    const std::vector<Entry>& at_label(int kind, const Label& label) const;
    const std::vector<int>& starter_stars(int s) const { return starter_stars_[s]; }
    int starter_size(int s) const { return starter_sizes_[s]; }
    double starter_weight(int s) const { return starter_weights_[s]; }

  private:
    Grammar grammar_;
    StarTable stars_;
    std::vector<Piece> left_pieces_;
    std::vector<Move> moves_;
    std::vector<std::vector<std::vector<Entry>>> by_star_;  // [kind][star]
    std::vector<std::map<Label, std::vector<Entry>>> by_label_;
    std::vector<std::vector<int>> starter_stars_;
    std::vector<int> starter_sizes_;
    std::vector<double> starter_weights_;
    SizeMeasure measure_ = SizeMeasure::Polygons;
    int example_size_ = 0;
    bool can_grow_ = false;
};

struct GrowSettings {
    int target = 0;           // size to grow to, in the table's measure; 0: the example's
    double overshoot = 0.15;  // a move may pass the target by this share of it (at least 1)
    int max_steps = 0;        // moves tried; 0: 4 x target + 64
    int max_vertices = 0;     // 0: none
    double keep_share = 0.2;  // share of size-keeping moves while growing, and of the
                              // growing moves made that reshape afterwards
    int tries = 64;           // random places tried per move before searching every place
    // Share of places drawn from the outside boundary (the rest from anywhere): growth that
    // packs enclosed holes makes layouts whose drawings need ever shorter edges.
    double outside_share = 0.75;
};

// How a growth went, and which limit ended it (none: the target was reached).
struct GrowReport {
    int starter = -1;
    int size = 0;                 // reached, in the table's measure
    int steps = 0;                // moves tried
    int applied = 0;              // moves made
    bool stuck = false;           // no move could grow it further (within the overshoot)
    bool step_limited = false;    // max_steps ended it
    bool vertex_limited = false;  // a move was refused because of max_vertices
};

// A complete angle graph grown from the table's grammar with `seed` (the same seed and
// settings, the same graph).
AngleGraph grow_graph(const GrowthTable& table, std::uint64_t seed, const GrowSettings& settings,
                      GrowReport* report = nullptr);

}  // namespace sylva::layout
