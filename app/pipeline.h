// The pipeline, read top to bottom in one place: template -> word -> skeleton -> trunk
// field -> trunk mesh. Each stage lives in its own module; this file only wires them.
#pragma once

#include "app/tree_params.h"
#include "marching/mesh.h"
#include "turtle/skeleton.h"
#include "turtle/turtle.h"
#include "turtle/word.h"

#include <string>
#include <vector>

namespace sylva {

struct TreeTemplate {
    std::string name;
    std::string description;
    std::string grammar;  // SPEC section 1 syntax
    TurtleMode mode = TurtleMode::Abop;
    WidthModel width_model = WidthModel::Taper;
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

// Runs the whole pipeline on a template (its params as the caller set them).
// Throws GrammarError (turtle/) or InputError on bad input.
Tree generate_tree(const TreeTemplate& tree);

// The first stage alone: the template's grammar derived `generations` steps.
Word derive_word(const TreeTemplate& tree);

// The first stages alone: grammar -> word -> skeleton (for `sylva skeleton`, the GUI's
// skeleton view and tests).
Skeleton grow_skeleton(const TreeTemplate& tree, StageTimes* times = nullptr);

struct Sphere {
    glm::vec3 center{0.0f};
    float radius = 0.0f;
};

// Seed 001's crown primitives: a sphere of diameter sphere_diameter at every tip's end,
// raised by crown_offset on Y.
std::vector<Sphere> crown_spheres(const Skeleton& skeleton, const TreeParams& params);

// The padded box around the skeleton's segments (radii included) that the trunk is meshed in.
Box skeleton_bounds(const Skeleton& skeleton);

}  // namespace sylva
