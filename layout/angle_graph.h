// The angle graph of Schröder 2024 (section 3.2.3) after Merrell 2023: vertices without
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
// The planarity test: the boundary turns by exactly +360 (one more ^ than v), every closed
// face by -360, and Euler's formula holds.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "layout/polygon_mesh.h"

namespace sylva::layout {

// The distinct edge directions of an example, counter-clockwise from +x, each with its
// opposite (every edge brings both), and the example's mean edge length per direction.
struct Directions {
    std::vector<double> degrees;  // in [0, 360), ascending
    std::vector<int> opposite;
    std::vector<double> mean_length;
    // The example's mean length per edge label, index (dir * colors + left) * colors + right;
    // 0 where the example has no such edge.
    std::vector<double> label_length;
    // Colour 0 is the outside; palette[c] is colour c's 0xrrggbb (palette[0] unused).
    std::vector<std::uint32_t> palette;
    int colors() const { return static_cast<int>(palette.size()); }
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

// An edge label (k~ = (l, r, theta)) oriented along a dart.
struct Label {
    int dir = 0, left = 0, right = 0;
    bool operator==(const Label&) const = default;
    auto operator<=>(const Label&) const = default;
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
    int open_walk = -1;  // the walk with the half-edges (the graph boundary), or -1
    Boundary boundary;
};
Analysis analyze(const AngleGraph& g, const Directions& dirs);

// The angle graph of a (validated) polygon mesh, and its directions and palette.
struct Example {
    PolygonMesh mesh;
    Directions dirs;
    AngleGraph graph;
};
Example make_example(const PolygonMesh& mesh);

// A code equal for two graphs exactly when they are the same labelled planar graph.
std::vector<int> canonical_code(const AngleGraph& g);

// Schröder's (2024) notation: half-edges as e<label> (theta in [0, 180)) or e<label>' (reversed),
// turns as ^ and v.
std::string boundary_string(const Boundary& b, const Directions& dirs);
// The sorted star of darts at v as labels (the vertex's neighbourhood).
std::vector<Label> star(const AngleGraph& g, int v);

}  // namespace sylva::layout
