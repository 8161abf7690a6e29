// Vertex positions for an angle graph (Schröder 2024, section 3.4.2): every edge e from v0 to v1
// with direction u and unknown length s gives v0 + s u = v1. Around each closed face the
// steps sum to zero, so the lengths lie in the null space of a (2 faces x edges) matrix,
// found by Gauss-Jordan elimination (reduced row echelon form). Edges keep the example's
// directions exactly.
//
// Lengths are sampled as the thesis suggests, within ranges: each edge has a range (by
// default 0.5 to 3 times the example's mean length for its label; the user may set ranges per
// edge class, the pair of colours either side). Lengths are measured in units of that mean,
// so a least-squares fit keeps every polygon's proportions where it can. The target lengths
// scale each colour by one factor per layout and each polygon by a little more, stretched a
// little along one axis, so plots of one class keep plausible, similar proportions. The
// lengths nearest the target in the null space and within the ranges are found by the
// alternating direction method of multipliers; positions follow by walking a spanning tree.
// A drawing that is not planar (the turning test admits spirals that overlap for some
// lengths) is sampled again. Orthogonal graphs are also refined into rectangles and
// compacted (rectangularize.h), which cannot cross: that drawing tells which edges the
// structure makes long (their targets are raised, so the fit does not squeeze their
// neighbours) and is the one used when the fit crosses or the graph has holes.
//
// Pure functions; thread-safe.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "layout/angle_graph.h"

namespace sylva::layout {

struct LengthRange {
    double lo = 0, hi = 0;  // in the example's units; hi 0: no upper bound
};

struct LengthSettings {
    // Every edge's default range: these factors times the example's mean for its label.
    double min_factor = 0.5, max_factor = 3.0;
    // Ranges by edge class (edge_class()): "meadow/path" (that pair of colours), "meadow"
    // (any edge of a meadow polygon; two such ranges meet in their overlap) or "*".
    std::map<std::string, LengthRange> ranges;
    double class_spread = 1.25;    // a colour's scale per layout: in [1/s, s], log-uniform
    double polygon_spread = 1.08;  // and each polygon's
    double stretch = 1.12;         // a polygon's stretch along x against y
};

// A colour's name in edge classes: "outside" for colour 0, the planting class for the four
// planting colours (polygon_mesh.h), else "#rrggbb".
std::string color_name(const Directions& dirs, int color);
// An edge's class: the names of the colours either side, sorted, joined by "/".
std::string edge_class(const Label& label, const Directions& dirs);
// Every edge class and colour name of the example's edges, sorted (what ranges may name).
std::vector<std::string> edge_classes(const Directions& dirs);

// A planar drawing of the complete graph `g`, or nullopt when the ranges cannot be met or
// `attempts` samples failed. `relax` widens the ranges for graphs whose structure needs it
// (one plot facing many needs a long edge; posts nested between posts need short gaps):
// 0 the ranges, 1 no upper ends, 2 also a third of the lower ends, 3 a twentieth.
std::optional<PolygonMesh> realize(const AngleGraph& g, const Directions& dirs, std::uint64_t seed,
                                   const LengthSettings& lengths = {}, int attempts = 12,
                                   int relax = 0);

// The null space of a row-major matrix (rows x cols) by Gauss-Jordan: one basis vector per
// free column.
std::vector<std::vector<double>> null_space(std::vector<double> a, int rows, int cols);

}  // namespace sylva::layout
