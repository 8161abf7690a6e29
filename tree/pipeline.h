// The pipeline, read top to bottom in one place: template -> word -> skeleton -> trunk and
// crown fields -> meshes. Each stage lives in its own module; this file only wires them.
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/box.h"
#include "core/growth.h"
#include "core/mesh.h"
#include "core/skeleton.h"
#include "core/tree_params.h"
#include "core/tree_template.h"
#include "marching/mesher.h"
#include "sdf/cone_field.h"
#include "sdf/sphere_field.h"
#include "tree/branch_prisms.h"
#include "tree/budget_resolution.h"
#include "tree/organs.h"

namespace sylva {

struct Tree {
    Skeleton skeleton;
    Mesh trunk;
    Mesh crown;        // empty without tips, with sphere_diameter 0 or crown_mesh 0
    Mesh leaves;       // open quads by design (two triangles up, two down per leaf); may be empty
    OrganMesh organs;  // flowers, fruit, cones (tree/organs.h); empty for most trees
    // Struts added between crown blobs so a low budget can draw the crown (crown_merge.h);
    // 0 when the crown is meshed as grown.
    std::size_t crown_bridges = 0;
    // Segments a game mesh left out of the trunk because the crown hides them (drop_hidden).
    std::size_t hidden_segments = 0;
    // A game mesh whose branches are prisms (BranchStyle::Prisms): the branches it may draw,
    // and `trunk` is every one of them as prisms for the budget (branch_prisms()); a
    // reduction draws as many as its own budget buys. Empty when the trunk is the field's
    // surface.
    BranchAxes branch_axes;
    // The template's crown_shape: how a game mesh draws the crown unless its budget says.
    CrownShape crown_shape = CrownShape::Automatic;
    // The template's leaf_style: how a game mesh draws the leaves.
    LeafStyle leaf_style = LeafStyle::Cards;
    LeafShape leaf_shape = LeafShape::Round;  // the template's: textured cards draw it
    // The template's crown_lump_triangles: triangles of the budget per hull.
    std::size_t crown_lump_triangles = 70;
    // derive, turtle (or the growth method's stages), fields, trunk mesh, crown mesh, leaves;
    // the last three are made beside each other, each with its own time (stages_wall_ms)
    std::vector<StageTime> times;
    // What the tree lacks of what its template asks for, each a sentence for the user that
    // says why and what to change (a crown whose spheres are smaller than its grid's cells);
    // empty as a rule. Callers show them: a result unlike the request is never silent.
    std::vector<std::string> notes;
};

// The wall time of `times`: the stages made beside each other (StageTime::beside_others:
// the trunk mesh, the crown mesh and the leaves) count as the longest of them.
double stages_wall_ms(const std::vector<StageTime>& times);

// How the fields become meshes; none of this changes the tree's shape beyond the mesher's
// own sampling (all meshers share one grid).
struct MeshOptions {
    Mesher mesher = Mesher::Sparse;
    double vdb_adaptivity = 0.0;
    int threads = 0;  // 0 = all cores
    // Called with the finished fraction of the whole meshing stage, from any thread.
    std::function<void(float)> progress;
    // Called with the finished fraction of the growth (GrowthContext::progress), before any
    // meshing progress.
    std::function<void(float)> growth_progress;
    // Reaches every stage (growth, meshing, leaves); once it is true, generate_tree throws
    // Cancelled.
    CancelFlag cancel = nullptr;
    // The trunk + crown triangles the meshes will be reduced to (0: not reduced). It sets
    // the crown's resolution (crown_resolution_for_budget) and, with drop_hidden, the
    // trunk's (trunk_resolution_for_budget), and a low budget merges a
    // many-blob crown into a few pieces (crown_merge.h).
    std::size_t budget = 0;
    // What the growth may cost: a method that counts its work (colonization) stops with
    // InputError past these. None by default; the CLI sets its --max-* limits.
    GrowthLimits growth_limits;
};

// Runs the whole pipeline on a template (its params as the caller set them).
// Throws InputError (GrammarError for the grammar) on bad input, Cancelled when cancelled.
Tree generate_tree(const TreeTemplate& tree, const MeshOptions& options = {});

// The trunk's and the crown's fields with the boxes they are meshed in: what the meshers
// see (exposed for benchmarks and tests).
struct TreeFields {
    Box trunk_box;
    float trunk_cell = 0.0f;         // the trunk's cell (its box is a whole number of them)
    std::optional<ConeField> trunk;  // empty when no segment has a width
    // A game mesh's trunk in pieces instead (TrunkField::Pieces): whole subtrees of the
    // skeleton, meshed apart so the reduction can work on them on both cores.
    std::vector<ConeField> trunk_pieces;
    Box crown_box;
    std::optional<SphereField> crown;  // empty without tips or with sphere_diameter 0
};
// Cell sizes to mesh at instead of the resolutions' (0: from the resolution). A younger tree
// (core/tree_age.h) is meshed with its mature tree's cells: each box then grows on its
// longest side to a whole number of those cells (at least 4), and that number is the
// resolution the meshing must use (cells_along()).
struct FieldCells {
    float trunk = 0.0f;
    float crown = 0.0f;
};
// Which trunk field tree_fields() builds: the whole trunk's, a game mesh's pieces (from
// about 8,000 triangles; one piece below), or none (the trunk's box and cell only, for a
// caller that builds it from the segments it keeps).
enum class TrunkField { Whole, Pieces, None };
// Throws Cancelled once `cancel` is set (building the trunk's field takes a while on a
// tree of many thousand segments).
TreeFields tree_fields(const Skeleton& skeleton, const TreeParams& params,
                       const FieldCells& cells = {}, CancelFlag cancel = nullptr,
                       TrunkField trunk = TrunkField::Whole);

// The tree's leaves (generate_tree's last stage): scattered over the crown's field, or where
// the crown is meshed in a shell one leaf deep under its surface, then the turtle's
// polygons (unless polygon_part puts them among the organs). `params` as generate_tree meshes with
// (the budget's crown resolution). Throws Cancelled once `cancel` is set.
Mesh tree_leaves(const Skeleton& skeleton, const TreeFields& fields, const TreeParams& params,
                 CancelFlag cancel = nullptr);

// The resolution that meshes `box` with cells of `cell` (its longest side over the cell).
int cells_along(const Box& box, float cell);

// Heuer's (2022) crown primitives: a sphere of diameter sphere_diameter at every tip's end,
// raised by crown_offset on Y.
std::vector<Ball> crown_spheres(const Skeleton& skeleton, const TreeParams& params);

// The box around the skeleton's segments, radii included (the trunk is meshed in it,
// grown by the mesher's padding).
Box skeleton_bounds(const Skeleton& skeleton);

}  // namespace sylva
