// From the colonization's node graph to a skeleton (Liebemann 2017, 3.4 steps 3-4 and 3.5):
// successors drawn together, straight runs reduced (eq. 3.6), and Murray radii (eq. 3.4).
#pragma once

#include "colonization/space_colonization.h"
#include "core/skeleton.h"

namespace sylva {

// 3.4 step 3: the successors of every branching node turn towards their mean direction
// by `amount` (0 = unchanged, 1 = all along the mean), narrowing the branching angles as
// real forks are. Edge lengths stay; a moved node's subtree stays where it grew.
void draw_successors_together(ColonizationGraph& graph, float amount);

// Eq. 3.6: a node with one predecessor and one successor is removed when the directions
// into and out of it have a dot product above `max_dot`, so straight runs become one
// edge. max_dot >= 1 removes nothing. Keeps parents before children and recounts
// successors.
void reduce_curves(ColonizationGraph& graph, float max_dot);

// One segment per edge (the root has none), branch depth Z as the segment depth, radii by
// the pipe model with r0 = tip_radius and Murray's exponent.
Skeleton to_skeleton(const ColonizationGraph& graph, float tip_radius, float exponent);

}  // namespace sylva
