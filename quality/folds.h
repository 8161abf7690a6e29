// How much of a surface folds sharply inwards: the creases a reduction leaves where it
// collapsed an edge across a concave spot (a branch fork pinched into a slit, a crown blob
// caved in). A made-by-hand low-poly mesh has sharp convex edges but few sharp inward ones,
// so this share tells a crumpled reduction from a clean one.
#pragma once

#include <cstddef>

#include "core/mesh.h"

namespace sylva {

struct Folds {
    // folded_length / interior_length; 0 without interior edges.
    double share = 0.0;
    double folded_length = 0.0;    // the concave folds sharper than the threshold
    double interior_length = 0.0;  // every interior edge
    std::size_t folded_edges = 0;
    std::size_t interior_edges = 0;
};

// An interior edge is one that exactly two faces share once vertices at the same position
// are welded (quality/weld.h) and faces of no area are left out. It folds inwards when the
// far corner of one face lies on the outer side of the other face's plane, and more
// than `degrees` when the angle between the two face normals exceeds it (a cube's edges
// fold 90 degrees, outwards). Needs faces counter-clockwise seen from outside (core/mesh.h),
// as on a closed, outward-oriented mesh; an interior edge whose two faces run it the same
// way (orientation flips there) counts in interior_length but never as a fold. Lengths are
// weights, so the share does not change when a mesh is scaled or its faces split.
// Deterministic; safe to call from several threads at once.
Folds measure_folds(const Mesh& mesh, double degrees = 90.0);

// measure_folds(mesh, degrees).share: in 0..1.
double concave_fold_share(const Mesh& mesh, double degrees = 90.0);

}  // namespace sylva
