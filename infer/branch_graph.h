// The branch graph of a skeleton (Godin and Caraglio 1998's multiscale tree graph, at two
// scales): segments, and axes, the chains of segments one branch is made of. Each segment
// has at most one continuation (the child on its own axis); its other children start
// lateral axes one order higher. Built once, read by the rule inference and the fit report.
#pragma once

#include <span>
#include <vector>

#include "core/skeleton.h"

namespace sylva {

struct Axis {
    std::vector<int> segments;  // from the base to the tip
    int order = 0;              // 0 for a root axis (the trunk), parent's + 1 for a lateral
    int parent_segment = -1;    // the segment it branches from, -1 for a root axis
};

struct BranchGraph {
    std::vector<std::vector<int>> children;  // per segment, in index order
    std::vector<int> continuation;           // per segment: its child on the same axis, or -1
    std::vector<int> axis_of;                // per segment: its axis
    std::vector<int> height;                 // per segment: segments on the longest path to a
                                             // tip, itself included (1 at a tip)
    std::vector<Axis> axes;                  // root axes first, then laterals by parent
    std::vector<int> roots;                  // segments without a parent
};

// The continuation of a segment is, in this order of preference: `hint`'s entry when it
// names one of its children (a cylinder table's "extension"); the child with the same
// branch depth when the skeleton's depths are known (Sylva's turtle gives a lateral depth
// + 1); else the child whose direction turns least, when it turns less than 45 degrees.
// An axis's order is its first segment's depth when known, else its parent axis's + 1.
// Requires parents before children (ExampleTree guarantees it). Linear in the segments.
BranchGraph build_branch_graph(const Skeleton& skeleton, std::span<const int> hint = {});

}  // namespace sylva
