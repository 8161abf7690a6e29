// Low budgets and the crown's shape. A crown of blobs (tree/crown_merge.h bridges them into
// a few pieces) reduced to a hundred triangles loses its shape piece by piece: the quadric
// queue collapses the bridges and dents into spikes and slabs, and whole blobs end as
// tetrahedra. A convex hull is what a small budget draws well: a few dozen triangles that
// cover the piece, never a token. The convex hull of a whole crown would fill its hollows
// (under an umbrella or a willow's curtain), so the crown is split into a few clusters
// first, and each cluster becomes a hull.
#pragma once

#include <cstddef>

#include "core/mesh.h"

namespace sylva {

// The trunk + crown triangles the hull count assumes where the budget keeps every triangle
// (a crown drawn as hulls without a reduction).
inline constexpr std::size_t kCrownHullBudget = 400;

// A game crown's budget buys about one hull per this many trunk + crown triangles unless the
// template says (crown_lump_triangles): 11 lumps at 800, each with enough triangles to read
// as a faceted volume. Fewer hulls fill the crown's hollows, as under a drooping crown, so
// curtains and tiers (willow, spruce) ask for more. reduce_tree (tree/lowpoly_tree.h) also
// tries half as many again at small budgets.
inline constexpr std::size_t kTrianglesPerHull = 70;

// The crown's vertices split into `hulls` clusters (k-means, seeded by farthest points, so
// deterministic; on the positions, or with heights counting 1.5 times where those clusters'
// hulls fill a quarter less of the sky between the crown's parts, tree/hull_gap.h: flat
// clusters that keep to one tier of an umbrella), a cluster split again where its vertices lie on
// surface pieces apart (each piece of at least a tenth of it, the largest first, up to `pieces`
// clusters in all: a hull over two curtains or two blobs would bridge the gap between them), and
// the convex hull of each (core/convex_hull.h's extreme_point_hull: at most 124 triangles each), as
// one mesh: every hull closed, 2-manifold and outward, within the crown's bounding box. Clusters
// are near-disjoint in space, so neighbouring hulls overlap only where they meet. A crown with
// fewer than 4 vertices, or a cluster that spans no volume (flat), gives `crown` back unchanged; so
// does `hulls` 0.
Mesh crown_hulls(const Mesh& crown, std::size_t hulls, std::size_t pieces);

}  // namespace sylva
