// The pipeline, read top to bottom in one place: template -> word -> skeleton -> trunk
// field -> trunk mesh. Each stage lives in its own module; this file only wires them.
#pragma once

#include "app/tree_params.h"
#include "marching/mesh.h"
#include "turtle/skeleton.h"

#include <string>

namespace sylva {

struct TreeTemplate {
    std::string name;
    std::string description;
    std::string grammar;  // SPEC section 1 syntax
    TreeParams params;
};

// The built-in default tree, compiled into the binary.
const TreeTemplate& default_template();

struct StageTimes {
    double derive_ms = 0, turtle_ms = 0, trunk_mesh_ms = 0;
};

struct Tree {
    Skeleton skeleton;
    Mesh trunk;
    StageTimes times;
};

// Runs the whole pipeline. Throws GrammarError (turtle/) or InputError on bad input.
Tree generate_tree(const std::string& grammar, const TreeParams& params);

// The padded box around the skeleton's segments (radii included) that the trunk is meshed in.
Box skeleton_bounds(const Skeleton& skeleton);

}  // namespace sylva
