// The pipe model of branch widths (Liebemann 2017, 3.4, after Murray 1926): a branch's radius r
// satisfies r^g = sum of its children's r^g; tips get r0. Computed on a finished skeleton,
// so both the turtle and space colonization can use it.
#pragma once

#include "core/skeleton.h"

namespace sylva {

// Sets every segment's radii: ra is the segment's own pipe radius, rb the largest of its
// children's (r0 at a tip), so unbranched chains keep one radius and every segment tapers
// towards its thickest continuation. Requires parents to precede their children.
void apply_pipe_model(Skeleton& skeleton, float tip_radius, float exponent);

}  // namespace sylva
