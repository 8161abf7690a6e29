// What space colonization costs: estimated before a run from its settings and the points'
// box, and counted during one (ColonizationWork). Its work is the grid queries each new node
// makes over the attraction points within the influence radius, so it grows with points x
// nodes; a kill distance far below the step leaves every point alive and the crown fills
// with nodes about a step apart. Fitted on this project's colonization templates with
// 1,400 to 1,000,000 points (sylva-bench-colonization --cost prints estimate against count).
#pragma once

#include <cstddef>

#include "colonization/space_colonization.h"
#include "core/box.h"

namespace sylva {

struct ColonizationCost {
    double nodes = 0;       // the graph's nodes (about the skeleton's segments)
    double iterations = 0;  // growth passes
    double scans = 0;       // as ColonizationWork
    double visits = 0;
    double seconds = 0;  // on one core (the growth is serial)
    double bytes = 0;    // points, their grids and the nodes
};

// Before a run: `points` attraction points in `bounds` (the envelope's box), `roots` roots on
// the ground below it. Rough by design (a guide, fitted, not a bound): where the growth can
// go further than the model says (points handed on by max_no_grow, an envelope far from
// a box), ColonizationSettings::work_done is what holds a limit.
ColonizationCost estimate_colonization_cost(const Box& bounds, std::size_t points, int roots,
                                            const ColonizationSettings& settings);

// What a run has cost so far: `work` as counted, with `points` points in `bounds`.
ColonizationCost colonization_cost(const ColonizationWork& work, std::size_t points,
                                   const Box& bounds, const ColonizationSettings& settings);

}  // namespace sylva
