// Orchard rows for the "orchard" polygons of a ground or layout plan (what links layouts to
// forests): trees on a regular grid whose rows run along the polygon's longest edge,
// `row_spacing` between rows and `tree_spacing` between trees in a row, clipped to the
// polygon with a margin.
#pragma once

#include <glm/vec2.hpp>
#include <vector>

#include "forest/ground.h"

namespace sylva::forest {

struct OrchardSettings {
    double row_spacing = 6.0;   // meters between rows
    double tree_spacing = 4.0;  // meters between trees in a row
    double margin = 2.0;        // least distance from a tree to the polygon's edge, meters
};

// The unit direction of the polygon's longest edge (its rows run along it), from its first to
// its second point. Precondition: at least 2 distinct points.
glm::dvec2 row_direction(const GroundPolygon& polygon);

// The lattice origin of the polygon's rows: every tree is origin + i * tree_spacing * u +
// j * row_spacing * v (u the row direction, v its left perpendicular, i and j integers). The
// lattice is centred on the polygon's extent along u and v.
glm::dvec2 row_origin(const GroundPolygon& polygon, const OrchardSettings& settings);

// At most this many lattice points per orchard polygon (the forest's tree cap).
inline constexpr double kMaxOrchardLattice = 1e6;

// How many lattice points orchard_rows() visits for the polygon: an upper bound on its trees,
// in doubles (a spacing of 1e-9 m gives 1e+20, never an overflowed integer). 0 for fewer
// than 3 points. Throws InputError for a bad spacing or margin.
double orchard_lattice_points(const GroundPolygon& polygon, const OrchardSettings& settings);

// The trees of one orchard polygon: lattice points inside it, at least `margin` from its
// edges and inside no polygon of `ground` whose class is neither "orchard" nor "forest" (a
// path drawn over it). Rows in order, trees along each row. Throws InputError for a spacing
// or margin that is not a positive (margin: non-negative) finite number, and for a lattice
// of more than kMaxOrchardLattice points (naming the figure), before any is visited.
std::vector<glm::dvec2> orchard_rows(const GroundPolygon& polygon, const Ground& ground,
                                     const OrchardSettings& settings);

}  // namespace sylva::forest
