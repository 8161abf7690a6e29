// The parameters of docs/parameters.md (after Heuer 2022, table 4.3), with their ranges and
// defaults.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sylva {

struct TreeParams {
    int trunk_resolution = 96;      // P_Tres: marching-cubes cells along the longest side
    int crown_resolution = 64;      // P_Cres
    double branch_length = 0.5;     // P_Bl: default step of F and f, meters
    double branch_width = 0.1;      // P_Bw: starting width (diameter) of the trunk, meters
    double trunk_taper = 0.95;      // P_r1: width factor per trunk segment
    double branch_taper = 0.8;      // P_r2: width factor per branch level and segment
    double sphere_diameter = 0.3;   // P_Sdia
    double crown_offset = 0.06;     // P_Soff
    double crown_fusion = 0.01;     // P_Cfus
    int generations = 6;            // P_Tgen: derivation steps
    double pitch_angle = 22.5;      // P_alpha, degrees: & ^
    double yaw_angle = 22.5;        // P_beta, degrees: + - (and roll \ /)
    double tropism = 0.0;           // elasticity e of the bend towards gravity (ABOP)
    double tip_width = 0.02;        // pipe width model: diameter at the tips, meters
    double pipe_exponent = 2.5;     // pipe width model: Murray's exponent g
    double joint_blend = 0.0;       // trunk joints: smooth-union radius, meters (0 = hard union)
    int crown_blend = 0;            // CrownBlend: how crown spheres fuse
    int crown_mesh = 1;             // 1: mesh the crown; 0: leaves only (Heuer 2022, B.6)
    int crown_merge = 1;            // 1: low budgets merge crown blobs (tree/crown_merge.h)
    int drop_hidden = 0;            // 1: game meshes leave out what the crown hides (pipeline.h)
    double leaf_density = 60.0;     // leaves per cubic meter of crown
    double leaf_size = 0.25;        // leaf length, meters
    int leaf_shape = 0;             // LeafShape
    int polygon_part = 0;           // PolygonPart: where the turtle's { } polygons go
    int triangle_budget = 800;      // export: trunk + crown reduced to this (0 = no reduction)
    int crown_shape = 0;            // CrownShape: how the game mesh draws the crown
    int crown_lump_triangles = 70;  // hulls: game-mesh triangles per lump (fewer, larger)
    int branch_style = 0;           // BranchStyle: how the game mesh draws the branches
    int leaf_style = 0;             // LeafStyle: how the game mesh draws the leaves
    // Space colonization (growth = "colonization", Liebemann 2017, chapter 3); the L-system
    // ignores these.
    int attraction_points = 2000;    // N
    double influence_radius = 1.5;   // d_i, meters
    double kill_distance = 0.4;      // d_k, meters
    double step_size = 0.25;         // D, meters
    int max_iterations = 300;        // iterations before growth stops
    int envelope = 1;                // Envelope shape (colonization/envelope.h)
    double envelope_size_x = 6.0;    // the envelope's width, meters
    double envelope_size_y = 5.0;    // its height
    double envelope_size_z = 6.0;    // its depth
    double envelope_base = 2.5;      // height of the envelope's bottom
    double envelope_offset_x = 0.0;  // the envelope's axis moved off the root, meters
    double envelope_offset_z = 0.0;
    int envelope_template = 0;   // envelope = "template": the built-in template whose
                                 // crown is the envelope (kEnvelopeTemplates' index)
    double envelope_tilt = 0.0;  // degrees about Z; positive leans the top towards +x
    int obstacle = 0;            // ObstacleShape: none, sphere or box
    double obstacle_x = 0.0;     // the obstacle's centre, meters
    double obstacle_y = 0.0;
    double obstacle_z = 0.0;
    double obstacle_size_x = 1.0;  // its full extents, meters
    double obstacle_size_y = 1.0;
    double obstacle_size_z = 1.0;
    int roots = 1;               // trees grown from a circle of roots, sharing the points
    double root_spread = 0.5;    // radius of that circle, meters (ignored for one root)
    int point_distribution = 0;  // PointDistribution: uniform or halton
    double trunk_height = 2.0;   // the trunk grows at least this high first
    // T: colonization adds it to each growth direction (eq. 3.2); the L-system turtle bends
    // towards it (ABOP), towards -Y while it is 0.
    double tropism_vector_x = 0.0;
    double tropism_vector_y = 0.0;
    double tropism_vector_z = 0.0;
    int max_degree = 0;            // max_grad: successors per node (0 = no limit)
    int max_depth = 0;             // max_Z: branch depth (0 = no limit)
    int max_no_grow = 0;           // max_NG: idle iterations before a node stops (0 = never)
    int weighted_growth = 0;       // 1: step 2D on the trunk down to D at max_depth
    double curve_reduction = 1.0;  // eq. 3.6 dot-product threshold (1 = keep every node)
    double angle_smoothing = 0.0;  // successors drawn together (0 = not at all, 1 = fully)
    // Variation and age (core/noise.h, core/tree_age.h). The defaults change nothing.
    double age = 1.0;                // 0: a seedling, 1: the mature tree the template describes
    double bend = 0.0;               // degrees per meter of curvature noise along branches
    double bend_frequency = 0.5;     // noise cycles per meter along a branch
    int noise_kind = 0;              // NoiseKind (core/noise.h): expressions' and variation's noise
    double jitter = 0.0;             // per-branch angles and lengths times 1 +- jitter
    double width_variation = 0.0;    // widths times 1 + this * noise along the branch
    double tropism_variation = 0.0;  // tropism vector plus this * a noise vector
    double color_variation = 0.0;    // part colours shifted per seed by up to this
    std::uint64_t seed = 1;
};

// Choices of the `crown_blend` parameter.
enum class CrownBlend { Root = 0, Pasko = 1 };
// Choices of the `leaf_shape` parameter.
enum class LeafShape { Round = 0, Oak = 1, Needle = 2, Frond = 3 };
// Choices of the `polygon_part` parameter: the turtle's { } polygons fanned into the leaves
// (thinned with them), or into the organs part with their colours (tree/organs.h).
enum class PolygonPart { Leaves = 0, Organs = 1 };
// Choices of the `crown_shape` parameter: how a reduced crown is drawn (tree/crown_hulls.h).
enum class CrownShape {
    Automatic = 0,  // hulls in a game mesh when the crown has handles (blobs touching in
                    // rings), else blobs
    Blobs = 1,      // the crown's own surface, reduced
    Hulls = 2,      // the convex hulls of a few clusters of the crown, reduced
};

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

// The branch style `params` resolve to (never Automatic).
BranchStyle branch_style(const TreeParams& params);

// Choices of the `envelope_template` parameter: the built-in templates (by name) whose
// crown a colonization envelope can be. Core cannot ask the template library, so the names
// are listed here; tests/tree checks each is a built-in template.
std::span<const std::string_view> envelope_template_names();
// The `envelope` choice that takes the crown of `envelope_template`; lower values are the
// simple solids (colonization/envelope.h's EnvelopeShape).
constexpr int kEnvelopeTemplate = 5;

// One parameter's key, meaning and valid range, for --set, sliders and validation.
struct ParamInfo {
    std::string_view key;
    std::string_view help;
    double min;
    double max;
    bool integer;
    // For a choice parameter: the names of its values 0, 1, ... (empty for numbers).
    std::span<const std::string_view> choices = {};
};

const std::vector<ParamInfo>& param_infos();

// Value of a parameter by key, as double (integers included). nullopt for an unknown key.
std::optional<double> get_param(const TreeParams& params, std::string_view key);

// Sets a parameter from text ("key=value" style input); a choice parameter takes a name of
// its choices or its index. Throws InputError naming the key and its range for an unknown
// key, a non-number, NaN/inf, an out-of-range value or a fraction for an integer parameter.
void set_param(TreeParams& params, std::string_view key, std::string_view value);

// Sets a parameter from a number, with the same checks as set_param.
void set_param(TreeParams& params, std::string_view key, double value);

// Text of a parameter's value: a number, or a choice's name.
std::string param_text(const TreeParams& params, const ParamInfo& info);

}  // namespace sylva
