// Finding a rule side inside a graph and replacing it (the double pushout of Schröder 2024,
// section 3.3.4): star ids, the anchored match of one connected piece, and the cut-and-glue
// step. Derivation uses the match to prune reducible graphs; generation uses all of it.
//
// Directions are absolute and every vertex of a rule side carries a whole star of the
// example (a primitive), so a piece placed with one of its vertices on a graph vertex of the
// same star is placed entirely: following its full edges fixes every other vertex. Trying
// each graph vertex with the right star as the anchor therefore finds every match of the
// piece (the planar subgraph search the thesis cites, in linear time per anchor).
//
// Free functions on caller-owned data; no shared state.
#pragma once

#include <map>
#include <optional>
#include <vector>

#include "layout/graph_grammar.h"

namespace sylva::layout {

// Ids of the stars (the counter-clockwise (direction, left colour) darts) of an example's
// vertices: the primitives. Every vertex a grammar makes has one of them.
class StarTable {
  public:
    // Returns the star's id, adding it when new.
    int add(const AngleGraph& g, int v);
    // The star's id, or -1 when it is not in the table.
    int find(const AngleGraph& g, int v) const;
    // Ids for every vertex of g (-1 for unknown stars).
    std::vector<int> ids(const AngleGraph& g) const;
    int size() const { return static_cast<int>(ids_.size()); }

  private:
    static std::vector<int> key(const AngleGraph& g, int v);
    std::map<std::vector<int>, int> ids_;
};

// Maps the connected `piece` into `g` with piece vertex `from` on graph vertex `anchor` and
// follows the piece's full edges; false when it does not fit (a star differs, a full edge of
// the piece is a half-edge in g, or two piece vertices land on one graph vertex). A half-edge
// of the piece may lie on anything. `map` gets piece vertex -> graph vertex.
bool map_piece(const AngleGraph& piece, const std::vector<int>& piece_stars, int from,
               const AngleGraph& g, const std::vector<int>& g_stars, int anchor,
               std::vector<int>& map);

// One side of a rule used in an application: its pieces and the ports of its boundary.
struct SideView {
    std::vector<const Piece*> pieces;
    const std::vector<Port>* ports = nullptr;
};

// Where the side X was found in g: per piece the vertex map (vertex pieces) or the matched
// edge as the dart (vertex, dart) whose label is the piece's edge (floating pieces).
struct SideMatch {
    std::vector<std::vector<int>> maps;
    std::vector<std::pair<int, int>> edges;
};

// Cuts the matched side X out of `g` and glues Y in along the same ports. `stars` are g's
// star ids and `y_stars` those of Y's pieces (per piece, per vertex); the result's ids are
// written to `out_stars`. nullopt when the match is not a place X can be cut from (a port's
// edge does not lead out of the match, two ports meet one dart), or the result is not a
// complete planar graph.
std::optional<AngleGraph> replace_side(const AngleGraph& g, const std::vector<int>& stars,
                                       const Directions& dirs, const SideView& x,
                                       const SideMatch& match, const SideView& y,
                                       const std::vector<std::vector<int>>& y_stars,
                                       std::vector<int>& out_stars, Analysis* analysis = nullptr);

}  // namespace sylva::layout
