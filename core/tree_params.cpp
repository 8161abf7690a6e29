#include "core/tree_params.h"

#include "core/param_table.h"

namespace sylva {
namespace {

constexpr std::string_view kCrownBlends[] = {"root", "pasko"};
constexpr std::string_view kLeafShapes[] = {"round", "oak", "needle", "frond"};
constexpr std::string_view kPolygonParts[] = {"leaves", "organs"};
constexpr std::string_view kBranchStyles[] = {"auto", "prisms", "surface"};
constexpr std::string_view kLeafStyles[] = {"cards", "leaves", "none", "textured"};

}  // namespace

BranchStyle branch_style(const TreeParams& params) {
    if (params.branch_style != BranchStyle::Automatic) return params.branch_style;
    return params.joint_blend > 0.0 ? BranchStyle::Surface : BranchStyle::Prisms;
}

const ParamTable& shared_param_table() {
    using P = TreeParams;
    using enum ParamGroup;
    static const ParamTable table = ParamTable::shared({
        param("trunk_resolution", &P::trunk_resolution, 4, 2000, GameMesh,
              "marching-cubes cells along the longest side of the trunk box")
            .symbol("P_Tres"),
        param("crown_resolution", &P::crown_resolution, 4, 2000, GameMesh,
              "marching-cubes cells along the longest side of the crown box")
            .symbol("P_Cres"),
        param("sphere_diameter", &P::sphere_diameter, 0, 10, Crown,
              "diameter of the crown spheres at the branch tips, meters")
            .symbol("P_Sdia"),
        param("crown_offset", &P::crown_offset, -10, 10, Crown,
              "crown spheres raised by this on Y, meters (negative lowers them)")
            .symbol("P_Soff"),
        param("crown_fusion", &P::crown_fusion, 1e-3, 1e-1, Crown,
              "how strongly the crown spheres blend")
            .symbol("P_Cfus"),
        param("tip_width", &P::tip_width, 0, 10, Branches,
              "pipe width model: diameter at the branch tips, meters"),
        param("pipe_exponent", &P::pipe_exponent, 1, 4, Branches,
              "pipe width model: Murray's exponent (r^g = sum of the children's r^g)"),
        param("joint_blend", &P::joint_blend, 0, 1, Branches,
              "smooth-union radius at trunk joints, meters (0 = hard union)"),
        param("crown_blend", &P::crown_blend, kCrownBlends, Crown,
              "how crown spheres fuse: Heuer's root smooth min or Pasko-Savchenko's blend"),
        param("crown_mesh", &P::crown_mesh, Crown, "1: mesh the crown; 0: leaves only"),
        param("crown_merge", &P::crown_merge, GameMesh,
              "1: at low triangle budgets, grow crown blobs until a few shapes remain; 0: never"),
        param("drop_hidden", &P::drop_hidden, GameMesh,
              "1: the crown hides most of the trunk: the game mesh leaves out the branches and "
              "twigs it hides and meshes the trunk at the budget's resolution (2-5x fewer raw "
              "triangles); 0: keeps them all at trunk_resolution"),
        param("leaf_density", &P::leaf_density, 0, 20000, Leaves,
              "leaves per cubic meter of crown (0 = none)"),
        param("leaf_size", &P::leaf_size, 0.01, 2, Leaves, "leaf length, meters"),
        param("leaf_shape", &P::leaf_shape, kLeafShapes, Leaves, "the outline of every leaf"),
        param("polygon_part", &P::polygon_part, kPolygonParts, Leaves,
              "where the turtle's { } polygons go: leaves (fanned into the leaf part, thinned "
              "with it) or organs (their own part, coloured by index, with flowers and fruit)"),
        param("triangle_budget", &P::triangle_budget, 0, 10000000, GameMesh,
              "export: trunk + crown reduced to this many triangles (0 = keep every "
              "marching-cubes triangle)"),
        param("crown_shape", &P::crown_shape, crown_shape_names(), GameMesh,
              "how the game mesh draws the crown: auto (convex hulls when blobs touch in "
              "rings, else blobs), blobs (its own surface) or hulls (a few convex lumps)"),
        param("crown_lump_triangles", &P::crown_lump_triangles, 10, 1000, GameMesh,
              "game mesh crown as hulls: triangles of the budget per lump (more: fewer, larger "
              "lumps)"),
        param("branch_style", &P::branch_style, kBranchStyles, GameMesh,
              "game mesh branches: prisms (a few-sided prism per branch, pointed at the tips), "
              "surface (the trunk's smooth surface reduced with the crown) or auto (surface when "
              "joint_blend blends the joints, else prisms)"),
        param("leaf_style", &P::leaf_style, kLeafStyles, Leaves,
              "leaves: cards (a game mesh over its leaf budget draws a card per patch of "
              "foliage), leaves (it keeps some of the tree's own leaves, grown), none (no "
              "leaves, the crown alone) or textured (cards with a texture of leaves, for "
              "alpha-tested engines)"),
        param("age", &P::age, 0, 1, Shape,
              "tree age: 0 a seedling, 1 the mature tree; grows continuously along the branches"),
        param("tropism_vector_x", &P::tropism_vector, 0, -2, 2, Shape,
              "tropism T along x: colonization adds T to each growth direction; the L-system "
              "turtle bends towards T by `tropism` after each F (T = 0: straight down)")
            .symbol("T"),
        param("tropism_vector_y", &P::tropism_vector, 1, -2, 2, Shape,
              "tropism T along y (negative: gravity, positive: light; see tropism_vector_x)")
            .symbol("T"),
        param("tropism_vector_z", &P::tropism_vector, 2, -2, 2, Shape,
              "tropism T along z (see tropism_vector_x)")
            .symbol("T"),
        param("bend_frequency", &P::bend_frequency, 0.01, 20, Variation,
              "noise cycles per meter along a branch for bend, width_variation and "
              "tropism_variation (colonization: per meter of space)"),
        param("tropism_variation", &P::tropism_variation, 0, 2, Variation,
              "the tropism vector plus up to this much noise, along each branch (L-system) or "
              "through space (colonization: branches bend coherently)"),
        param("color_variation", &P::color_variation, 0, 1, Variation,
              "trunk, crown and leaf colours shifted per seed in brightness and hue by up to "
              "this share (0 = the template's colours)"),
    });
    return table;
}

}  // namespace sylva
