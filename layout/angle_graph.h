// The angle graph of Schröder (2024, section 3.2.3) after Merrell (2023): vertices without
// positions, edges that know only their tangent angle and the colours on their left and
// right. A partial graph also has half-edges: edges cut open by the split operation (3.2.5),
// kept at the vertex they leave. Each vertex holds its darts (edges and half-edges leaving
// it) sorted counter-clockwise by angle; angles are indices into the example's direction
// table, so "same direction" is exact.
//
// analyze() walks the faces and reads the graph boundary string (GBS, 3.2.4): the cyclic
// list of half-edges met going counter-clockwise around the graph, with the turning between
// consecutive ones. The turning is kept as a real angle (the tangent difference plus 360
// per positive turn ^, minus 360 per negative turn v), which is the reduced GBS in numbers.
// The planarity test: exactly one walk (the outside) turns by +360 (one more ^ than v),
// every other walk by -360, every closed face has one colour, and Euler's formula holds. A
// partial graph may have half-edges on several walks (a ring whose hole is not finished
// yet): each such walk is an open boundary.
//
// Plain data and free functions; nothing here is shared between threads.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "layout/limits.h"
#include "layout/polygon_mesh.h"

namespace sylva::layout {

// An edge label (k~ = (l, r, theta)) oriented along a dart: its direction index and the
// colours on its left and right (colour 0 is the outside).
struct Label {
    int dir = 0, left = 0, right = 0;
    bool operator==(const Label&) const = default;
    auto operator<=>(const Label&) const = default;
};

// The distinct edge directions of an example, counter-clockwise from +x, each with its
// opposite (every edge brings both), the example's mean edge length per direction and per
// label, and its colours.
struct Directions {
    std::vector<double> degrees;  // in [0, 360), ascending
    std::vector<int> opposite;
    std::vector<double> mean_length;
    // The example's mean length of the edges with a label (both orientations are listed);
    // only the labels the example has, so the table grows with its edges, never with
    // directions x colours x colours.
    std::map<Label, double> label_length;
    // Colour 0 is the outside; palette[c] is colour c's 0xrrggbb (palette[0] unused).
    std::vector<std::uint32_t> palette;
    int colors() const { return static_cast<int>(palette.size()); }
    // The example's mean length of edges labelled `l`, else of its direction.
    double length_of(const Label& l) const;
};

struct Dart {
    int dir = 0;
    int left = 0;  // colour of the face left of the dart (the sector counter-clockwise after it)
    int to = -1;   // the vertex it reaches; -1: a half-edge
};

struct AngleGraph {
    std::vector<std::vector<Dart>> vertices;  // darts sorted by dir (counter-clockwise)

    int right(int v, int i) const {  // colour right of dart i at v
        const auto& d = vertices[v];
        return d[(i + d.size() - 1) % d.size()].left;
    }
    int find(int v, int dir) const {
        for (std::size_t i = 0; i < vertices[v].size(); ++i)
            if (vertices[v][i].dir == dir) return static_cast<int>(i);
        return -1;
    }
    int half_edges() const;
    int edges() const;  // full edges
};

Label dart_label(const AngleGraph& g, int v, int i);
Label reversed(const Label& l, const Directions& dirs);

// One element of a boundary string: a half-edge (pointing out of the graph) and the turning
// from it to the next half-edge, counter-clockwise around the graph.
struct BoundaryItem {
    int vertex = -1, dart = -1;  // where it sits (-1 for a floating edge's ends)
    Label label;
    double turn = 0;  // degrees, to the next item
    int wraps = 0;    // turn = ccw difference of the tangents in [0, 360) + 360 * wraps
};
using Boundary = std::vector<BoundaryItem>;

// Turning from an item with direction a to one with direction b is base(a, b) + 360 k.
double base_turn(const Directions& dirs, int a, int b);
void set_wraps(Boundary& b, const Directions& dirs);
// Same half-edges with the same turns, up to rotation. Returns the rotation r with
// a[i] ~ b[(i + r) % n], or -1.
int boundary_match(const Boundary& a, const Boundary& b);

struct Walk {
    std::vector<std::pair<int, int>> darts;  // (vertex, dart) left, in order
    double turning = 0;                      // +360 around the outside, -360 around a face
    int color = -1;                          // the face's colour; -2 when mixed
    Boundary items;                          // the half-edges met (open walks only)
};

struct Analysis {
    bool planar = false;
    std::string why;  // when not planar
    bool complete = false;
    std::vector<Walk> walks;
    std::vector<int> open_walks;  // the walks with half-edges (the open boundaries)
    int outer = -1;               // the walk turning +360
    // The graph boundary string: the outer walk's half-edges, when that walk is the only
    // open one (the graphs rules are made of); empty otherwise.
    Boundary boundary;
    bool single_boundary() const { return open_walks.size() == 1 && open_walks[0] == outer; }
    // Closed faces with a colour (the polygons a complete graph draws).
    int polygons() const;
};
Analysis analyze(const AngleGraph& g, const Directions& dirs);

// The angle graph of a (validated) polygon mesh, and its directions and palette. Throws
// InputError when two edges leave one vertex in the same direction or the example has more
// directions or colours than limits.h allows.
struct Example {
    PolygonMesh mesh;
    Directions dirs;
    AngleGraph graph;
};
Example make_example(const PolygonMesh& mesh);

// A code equal for two graphs exactly when they are the same labelled planar graph (the
// same structure up to isomorphism of the plane graph: directions are absolute, so a
// vertex and one of its darts fix the whole map of a connected graph).
std::vector<int> canonical_code(const AngleGraph& g);
// A 64-bit hash of a code (unsigned arithmetic: wraps by definition).
std::uint64_t code_hash(const std::vector<int>& code);

// The number Schröder (2024) writes a label as: (dir x colours + left) x colours + right, in
// unsigned 64 bits (limits.h keeps it below 2^63).
std::uint64_t label_number(const Label& l, const Directions& dirs);
// Schröder's (2024) notation: half-edges as e<label> (theta in [0, 180)) or e<label>' (reversed),
// turns as ^ and v.
std::string boundary_string(const Boundary& b, const Directions& dirs);
// The sorted star of darts at v as labels (the vertex's neighbourhood).
std::vector<Label> star(const AngleGraph& g, int v);

}  // namespace sylva::layout
