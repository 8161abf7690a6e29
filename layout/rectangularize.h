// Refining an orthogonal angle graph until every face is a rectangle (the rectangular
// refinement of Tamassia 1987, as Di Battista et al. 1999 present it), so that any positive
// edge lengths that close the faces draw it without crossings: a drawing whose faces are all
// rectangles, framed by a rectangle, is a subdivision of that frame.
//
// Inside a face, a reflex corner followed (along the face, straight corners aside) by two
// convex corners has its incoming edge extended into the face, to a new vertex on the edge
// after the second convex corner; that cuts a rectangle off. An inner face with reflex
// corners always has such a pattern, so inner faces end as rectangles. The outside face is
// refined the same way, then framed: each remaining reflex corner (seen from outside) is
// extended to a new vertex on the side of an enclosing rectangle its incoming edge points
// at, which leaves only rectangles between the graph and the frame.
//
// Pure function; thread-safe.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "layout/angle_graph.h"

namespace sylva::layout {

// True when every direction is a multiple of 90 degrees from the first (and so all four
// occur): the graphs rectangularize() refines.
bool orthogonal(const Directions& dirs);

struct Refinement {
    // The input's vertices first, with the same indices, then the added ones. Added edges
    // have the colour of the face they cut on both sides.
    AngleGraph graph;
    // For every dart of `graph`: the input dart (vertex, dart) in the same direction whose
    // edge it is a part of, or (-1, -1) for an added edge.
    std::vector<std::vector<std::pair<int, int>>> origin;
};

// nullopt when the graph is not a complete planar orthogonal graph (or the refinement ends
// with a face that is not a rectangle, which the method rules out).
std::optional<Refinement> rectangularize(const AngleGraph& g, const Directions& dirs);

}  // namespace sylva::layout
