// The parameters every growth method shares (after Heuer 2022, table 4.3), with their
// defaults: meshing, crown, leaves, game mesh and variation. A growth method's own
// parameters (the L-system's generations and angles, colonization's envelope) live in a
// block of its own (`blocks`, core/param_blocks.h); each module's table lists its
// parameters' keys and ranges (core/param_table.h), and tree/parameters.h reads and writes
// any of them by key.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>

#include "core/crown_shape.h"
#include "core/param_blocks.h"

namespace sylva {

// Choices of the `crown_blend` parameter.
enum class CrownBlend { Root = 0, Pasko = 1 };
// Choices of the `leaf_shape` parameter.
enum class LeafShape { Round = 0, Oak = 1, Needle = 2, Frond = 3 };
// Choices of the `polygon_part` parameter: the turtle's { } polygons fanned into the leaves
// (thinned with them), or into the organs part with their colours (tree/organs.h).
enum class PolygonPart { Leaves = 0, Organs = 1 };
// Choices of the `branch_style` parameter: how a game mesh draws the trunk and branches.
enum class BranchStyle {
    Automatic = 0,  // prisms, unless the template blends its joints (joint_blend > 0)
    Prisms = 1,     // a few-sided prism per branch from the skeleton (tree/branch_prisms.h)
    Surface = 2,    // the trunk field's surface, meshed and reduced with the crown
};
// Choices of the `leaf_style` parameter: how leaves are drawn.
enum class LeafStyle {
    Cards = 0,     // a game mesh over its leaf budget draws cards (tree/leaf_cards.h)
    Leaves = 1,    // a game mesh keeps some of the tree's own leaves, grown (leaf_thinning.h)
    None = 2,      // no leaves at all: the crown alone, flat coloured
    Textured = 3,  // cards, always, with a texture of leaves (export/leaf_atlas.h)
};

struct TreeParams {
    int trunk_resolution = 96;     // P_Tres: marching-cubes cells along the longest side
    int crown_resolution = 64;     // P_Cres
    double sphere_diameter = 0.3;  // P_Sdia
    double crown_offset = 0.06;    // P_Soff
    double crown_fusion = 0.01;    // P_Cfus
    double tip_width = 0.02;       // pipe width model: diameter at the tips, meters
    double pipe_exponent = 2.5;    // pipe width model: Murray's exponent g
    double joint_blend = 0.0;      // trunk joints: smooth-union radius, meters (0 = hard union)
    CrownBlend crown_blend = CrownBlend::Root;  // how crown spheres fuse
    bool crown_mesh = true;      // mesh the crown; off: leaves only (Heuer 2022, B.6)
    bool crown_merge = true;     // low budgets merge crown blobs (tree/crown_merge.h)
    bool drop_hidden = false;    // game meshes leave out what the crown hides (hidden_branches.h)
    double leaf_density = 60.0;  // leaves per cubic meter of crown
    double leaf_size = 0.25;     // leaf length, meters
    LeafShape leaf_shape = LeafShape::Round;
    PolygonPart polygon_part = PolygonPart::Leaves;  // where the turtle's { } polygons go
    int triangle_budget = 800;  // export: trunk + crown reduced to this (0 = no reduction)
    CrownShape crown_shape = CrownShape::Automatic;  // how the game mesh draws the crown
    int crown_lump_triangles = 70;  // hulls: game-mesh triangles per lump (fewer, larger)
    BranchStyle branch_style = BranchStyle::Automatic;  // how the game mesh draws the branches
    LeafStyle leaf_style = LeafStyle::Cards;            // how the game mesh draws the leaves
    // T: space colonization adds it to each growth direction (Liebemann 2017, eq. 3.2); the
    // L-system turtle bends towards it (ABOP), towards -Y while it is 0.
    glm::dvec3 tropism_vector{0.0};
    // Variation and age (core/noise.h, core/tree_age.h). The defaults change nothing.
    double age = 1.0;                // 0: a seedling, 1: the mature tree the template describes
    double bend_frequency = 0.5;     // noise cycles per meter along a branch
    double tropism_variation = 0.0;  // tropism vector plus this * a noise vector
    double color_variation = 0.0;    // part colours shifted per seed by up to this
    std::uint64_t seed = 1;
    // The parameters of each growth method, by the type of its block (LSystemParams,
    // ColonizationParams, ...).
    ParamBlocks blocks;
};

class ParamTable;

// The branch style `params` resolve to (never Automatic).
BranchStyle branch_style(const TreeParams& params);

// The table of the shared parameters above (seed aside: it is not a number a slider or a
// range can hold, and every reader treats it on its own).
const ParamTable& shared_param_table();

}  // namespace sylva
