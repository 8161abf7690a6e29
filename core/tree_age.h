// Tree age (Heuer's 2022 outlook: one "tree age" parameter driving many): a mature
// skeleton grown back to a younger one, continuously. Every growth method's skeleton goes
// through here (tree/growth.cpp), so L-system and colonization templates age alike.
//
// The model is a growth front moving out from the roots along the branches: a point of the
// mature tree at path distance d from its root has grown once the front f passed it, where
// f = (kSeedlingFront + (1 - kSeedlingFront) * age) * (the longest root-to-tip path). A
// segment the front cuts is drawn up to the front. Widths follow what a part has grown of
// what it will carry: a point's radius is the mature radius times the grown share of the
// path beyond it, (min(f, D) - d) / (D - d) with D its farthest tip, never thinner than the
// mature tips. So nothing pops: every length and width is continuous in age, and a part only
// grows (height and the drawn surface rise monotonically). A fully grown limb keeps its
// mature shape while the trunk still thickens.
#pragma once

#include "core/skeleton.h"

namespace sylva {

// The front at age 0, as a share of the longest path: a seedling, never an empty tree.
inline constexpr double kSeedlingFront = 0.05;

// The skeleton at `age` in [0, 1] (clamped); age 1 returns `mature` unchanged. Leaf
// polygons appear once the front reaches the nearest segment end and grow in over one
// segment's length. Segments keep their order (indices remapped), depth, colour and
// iteration. Parents must come before their children (every growth method's order).
Skeleton skeleton_at_age(const Skeleton& mature, double age);

// How crown spheres (and the crown's raise) scale with age: 0.25 at 0 to 1 at 1, so a
// sapling's crown is a few small blobs, not mature ones on a stick.
double crown_scale_at_age(double age);

}  // namespace sylva
