// A game mesh's branches drawn as prisms straight from the skeleton (lowpoly/prism_tube.h),
// the way a low-poly artist builds a tree: a few-sided prism per branch, tapering with it
// and ending in a point at a tip, each branch a closed piece that starts inside its parent.
// A budget can hardly ever give a branch more facets around than that (at 800 triangles a
// facet is wider than most branches are round), and a reduction of the marching-cubes
// surface flattens such branches into blades and folds them through each other; prisms keep
// every branch round-ish, straight-edged and apart, and cost no meshing or reduction time.
// The budget sets the sides and how closely a prism follows its branch's bends; where it
// cannot draw every branch, the ones that show least go first (twigs before limbs, never a
// branch without the one it grows from).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "core/mesh.h"
#include "core/skeleton.h"
#include "lowpoly/prism_tube.h"

namespace sylva {

// One branch from its base (on its parent's axis) to its end.
struct BranchAxis {
    TubeAxis axis;      // pointed when it ends in a tip of the skeleton
    int parent = -1;    // the axis it grows from (an earlier index), -1 for a root
    float area = 0.0f;  // what it shows from the side: twice its radius times its length,
                        // summed over its segments
};

struct BranchAxes {
    std::vector<BranchAxis> axes;  // parents before their children
    float extent = 0.0f;           // the largest side of the skeleton's box
    float thickest = 0.0f;         // the largest radius of any axis
};

// The segments with shown[i] != 0 (one flag per segment) as branch axes. A segment
// continues its parent's axis when it is, among the parent's shown children within 60
// degrees of its direction, the thickest at its base (then the straightest); every other
// child starts an axis of its own, whose parent is the axis of its nearest shown ancestor.
// Radii are raised to `min_radius`, the thinnest branch the full-detail mesh draws, so a
// game mesh keeps the full tree's outline. Deterministic.
BranchAxes branch_axes(const Skeleton& skeleton, std::span<const std::uint8_t> shown,
                       float min_radius);

// How a budget of trunk + crown triangles draws branches: the most sides any prism gets (the
// thickest branch; a thinner one as many as keep its facets as wide, at least three),
// and how far a prism may stray from its branch's bends, relative to the skeleton's extent.
struct PrismLook {
    int max_sides = 6;
    float tolerance = 0.0f;  // metres
};
PrismLook prism_look(const BranchAxes& axes, std::size_t budget);

struct BranchPrisms {
    Mesh mesh;                 // closed, 2-manifold, outward pieces; empty without axes
    std::size_t drawn = 0;     // axes drawn
    std::size_t left_out = 0;  // axes that did not fit (with every axis growing from them)
};

// Which axes a budget too small for all of them draws.
enum class PrismOrder {
    // The largest first, each as fine as fits: where a crown hides the small ones.
    LargestFirst,
    // Every axis first, each as coarse as the look allows (four times its tolerance; the
    // first, the trunk, with its short point), then the largest refined first: where
    // nothing hides a branch (a sparse crown, tree/sparse_crown.h), a coarse branch shows
    // more than a finer one's refinement.
    EveryAxisFirst,
};

// A pointed axis whose last segment is longer than this many times its end's radius ends,
// when every axis is drawn and triangles are left, in a short point (a ring half its radius
// before the end): a point over the whole segment shows half of it.
inline constexpr float kShortTipSegment = 3.0f;

// The axes as prisms for a game mesh of `budget` trunk + crown triangles, with at most
// `max_triangles` of them: the axes by what they show (BranchAxis::area) in `order`, each
// drawn when it and the axis it grows from fit, simplified further (up to four times the
// look's tolerance) where that makes it fit. The first axis (the trunk) is always drawn,
// however coarse, even past `max_triangles`. Where every axis is drawn, triangles left
// give long last segments short points (kShortTipSegment), largest axis first. Same axes
// and numbers, same mesh.
BranchPrisms branch_prisms(const BranchAxes& axes, std::size_t budget,
                           std::size_t max_triangles = std::numeric_limits<std::size_t>::max(),
                           PrismOrder order = PrismOrder::LargestFirst);

// The triangles every axis takes at four times the look's tolerance of `budget`, the first
// with its short point: the least that PrismOrder::EveryAxisFirst draws them all with.
std::size_t fewest_prism_triangles(const BranchAxes& axes, std::size_t budget);

}  // namespace sylva
