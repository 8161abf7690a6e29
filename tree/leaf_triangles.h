// Leaves as a game mesh draws them when there are about as many as its budget has
// triangles: one triangle per leaf, where the leaf lies. Cards stand for a patch of leaves
// each and cover the gaps between them too; where the leaves are few and large (a palm's
// leaflets, a row of them along each frond) a card per two or three leaves fills the comb
// that the frond's silhouette is. A triangle per leaf keeps every leaf's own place, size and
// direction for half of what a quad leaf costs.
//
// Pure functions of their inputs; safe on any thread.
#pragma once

#include <cstddef>

#include "core/mesh.h"

namespace sylva {

// At most this many leaves per triangle of the budget are drawn a triangle each (the rest,
// a third at most, thinned out); more leaves than that read better as cards.
inline constexpr double kLeavesPerTriangle = 1.5;

// Whether `leaves` (tree/leaves.h: no two share a vertex) are drawn a triangle each within
// `max_triangles`: they do not fit as they are, each leaf is a quad or a triangle (larger
// outlines lose too much of their shape in one triangle), they are large (their median
// length at least a tenth of the foliage's extent: seen one by one, where smaller leaves
// read as foliage that cards draw well) and there are at most kLeavesPerTriangle of them
// per triangle.
bool leaves_fit_as_triangles(const Mesh& leaves, std::size_t max_triangles);

// The leaves in at most `max_triangles`, one triangle each: a leaf's largest triangle of its
// own corners, moved to the leaf's centroid and scaled to the leaf's area, its corner
// nearest the leaf's base first (tree/leaves.h's layout, so UVs and wind apply to it) and
// facing as the leaf's first triangle. Leaves are taken in thin_leaves()' rank order (a
// smaller budget keeps a subset): where there are more leaves than triangles, the first
// max_triangles are kept and each grows by the area of those left out, so the foliage's
// area stays the same; where there are fewer, the triangles left over keep leaves whole, in
// that order while they fit. Same leaves, same triangles; no leaves or no budget give none.
Mesh leaf_triangles(const Mesh& leaves, std::size_t max_triangles);

}  // namespace sylva
