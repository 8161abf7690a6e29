// The pipeline, read top to bottom in one place: template -> word -> skeleton -> trunk and
// crown fields -> meshes. Each stage lives in its own module; this file only wires them.
#pragma once

#include "app/tree_params.h"
#include "marching/marching_cubes.h"
#include "marching/mesh.h"
#include "sdf/cone_field.h"
#include "sdf/sphere_field.h"
#include "turtle/skeleton.h"
#include "turtle/turtle.h"
#include "turtle/word.h"

#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sylva {

// Base colours of the parts, linear RGB in [0, 1].
struct PartColors {
    glm::vec3 trunk{0.36f, 0.24f, 0.15f};
    glm::vec3 crown{0.22f, 0.45f, 0.18f};
    glm::vec3 leaves{0.30f, 0.55f, 0.20f};
};

struct TreeTemplate {
    std::string name;
    std::string description;
    std::string grammar;  // SPEC section 1 syntax
    TurtleMode mode = TurtleMode::Abop;
    WidthModel width_model = WidthModel::Taper;
    TreeParams params;
    PartColors colors;
};

// The built-in default tree (template_library.h), compiled into the binary.
const TreeTemplate& default_template();

struct StageTimes {
    double derive_ms = 0, turtle_ms = 0, trunk_mesh_ms = 0, crown_mesh_ms = 0, leaves_ms = 0;
};

struct Tree {
    Skeleton skeleton;
    Mesh trunk;
    Mesh crown;   // empty without tips, with sphere_diameter 0 or crown_mesh 0
    Mesh leaves;  // open quads by design (two triangles up, two down per leaf); may be empty
    StageTimes times;
};

// How the fields become meshes; none of this changes the tree's shape beyond the mesher's
// own sampling (all meshers share one grid).
struct MeshOptions {
    Mesher mesher = Mesher::Sparse;
    double vdb_adaptivity = 0.0;
    int threads = 0;  // 0 = all cores
    // Called with the finished fraction of the whole meshing stage, from any thread.
    std::function<void(float)> progress;
    // When it becomes true, generate_tree throws MeshingCancelled.
    const std::atomic<bool>* cancel = nullptr;
};

// Runs the whole pipeline on a template (its params as the caller set them).
// Throws GrammarError (turtle/) or InputError on bad input.
Tree generate_tree(const TreeTemplate& tree, const MeshOptions& options = {});

// "dense", "sparse" or "vdb"; nullopt otherwise.
std::optional<Mesher> mesher_from_name(std::string_view name);

// The first stage alone: the template's grammar derived `generations` steps.
Word derive_word(const TreeTemplate& tree);

// The first stages alone: grammar -> word -> skeleton (for `sylva skeleton`, the GUI's
// skeleton view and tests).
Skeleton grow_skeleton(const TreeTemplate& tree, StageTimes* times = nullptr);

// The trunk's and the crown's fields with the boxes they are meshed in: what the meshers
// see (exposed for benchmarks and tests).
struct TreeFields {
    Box trunk_box;
    std::optional<ConeField> trunk;   // empty when no segment has a width
    Box crown_box;
    std::optional<SphereField> crown; // empty without tips or with sphere_diameter 0
};
TreeFields tree_fields(const Skeleton& skeleton, const TreeParams& params);

// Seed 001's crown primitives: a sphere of diameter sphere_diameter at every tip's end,
// raised by crown_offset on Y.
std::vector<Ball> crown_spheres(const Skeleton& skeleton, const TreeParams& params);

// The box around the skeleton's segments, radii included (the trunk is meshed in it,
// grown by the mesher's padding).
Box skeleton_bounds(const Skeleton& skeleton);

}  // namespace sylva
