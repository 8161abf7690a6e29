#include "core/tree_params.h"

#include <charconv>
#include <cmath>
#include <iterator>
#include <sstream>

#include "core/errors.h"

namespace sylva {
namespace {

// One table drives lookup, validation and help, so a new parameter is added in one place.
struct Field {
    ParamInfo info;
    double TreeParams::*real = nullptr;
    int TreeParams::*integer = nullptr;
};

constexpr std::string_view kCrownBlends[] = {"root", "pasko"};
constexpr std::string_view kLeafShapes[] = {"round", "oak", "needle", "frond"};
constexpr std::string_view kPolygonParts[] = {"leaves", "organs"};
constexpr std::string_view kNoiseKinds[] = {"gradient", "value_linear", "value_cosine",
                                            "value_cubic"};
constexpr std::string_view kCrownShapes[] = {"auto", "blobs", "hulls"};
constexpr std::string_view kBranchStyles[] = {"auto", "prisms", "surface"};
constexpr std::string_view kLeafStyles[] = {"cards", "leaves", "none", "textured"};
constexpr std::string_view kEnvelopes[] = {"sphere",   "ellipsoid",  "cone",
                                           "cylinder", "hemisphere", "template"};
constexpr std::string_view kEnvelopeTemplates[] = {
    "oak",     "spruce", "fir",  "palm", "birch", "willow", "pine",     "baobab",
    "cypress", "honda",  "bush", "elm",  "maple", "hedge",  "windswept"};
constexpr std::string_view kObstacles[] = {"none", "sphere", "box"};
constexpr std::string_view kPointDistributions[] = {"uniform", "halton"};

Field real(std::string_view key, std::string_view help, double min, double max,
           double TreeParams::*member) {
    return {{key, help, min, max, false}, member, nullptr};
}
Field whole(std::string_view key, std::string_view help, double min, double max,
            int TreeParams::*member) {
    return {{key, help, min, max, true}, nullptr, member};
}

const std::vector<Field>& fields() {
    static const std::vector<Field> table = {
        {{"trunk_resolution",
          "P_Tres: marching-cubes cells along the longest side of the trunk box", 4, 2000, true},
         nullptr,
         &TreeParams::trunk_resolution},
        {{"crown_resolution",
          "P_Cres: marching-cubes cells along the longest side of the crown box", 4, 2000, true},
         nullptr,
         &TreeParams::crown_resolution},
        {{"branch_length", "P_Bl: length of F and f without a parameter, meters", 0.001, 100,
          false},
         &TreeParams::branch_length,
         nullptr},
        {{"branch_width", "P_Bw: starting trunk width (diameter), meters", 0.0, 10, false},
         &TreeParams::branch_width,
         nullptr},
        {{"trunk_taper", "P_r1: width factor per trunk segment", 0, 1, false},
         &TreeParams::trunk_taper,
         nullptr},
        {{"branch_taper", "P_r2: width factor per branch segment", 0, 1, false},
         &TreeParams::branch_taper,
         nullptr},
        {{"sphere_diameter", "P_Sdia: diameter of the crown spheres at the branch tips, meters", 0,
          10, false},
         &TreeParams::sphere_diameter,
         nullptr},
        {{"crown_offset",
          "P_Soff: crown spheres raised by this on Y, meters (negative lowers them)", -10, 10,
          false},
         &TreeParams::crown_offset,
         nullptr},
        {{"crown_fusion", "P_Cfus: how strongly the crown spheres blend", 1e-3, 1e-1, false},
         &TreeParams::crown_fusion,
         nullptr},
        {{"generations", "P_Tgen: derivation steps of the grammar", 0, 15, true},
         nullptr,
         &TreeParams::generations},
        {{"pitch_angle", "P_alpha: default angle of & and ^, degrees", 0, 360, false},
         &TreeParams::pitch_angle,
         nullptr},
        {{"yaw_angle", "P_beta: default angle of + - \\ /, degrees", 0, 360, false},
         &TreeParams::yaw_angle,
         nullptr},
        {{"tropism",
          "elasticity of the bend towards gravity (or tropism_vector) after each F (0 = none, "
          "negative bends away)",
          -1, 1, false},
         &TreeParams::tropism,
         nullptr},
        {{"tip_width", "pipe width model: diameter at the branch tips, meters", 0, 10, false},
         &TreeParams::tip_width,
         nullptr},
        {{"pipe_exponent", "pipe width model: Murray's exponent (r^g = sum of the children's r^g)",
          1, 4, false},
         &TreeParams::pipe_exponent,
         nullptr},
        {{"joint_blend", "smooth-union radius at trunk joints, meters (0 = hard union)", 0, 1,
          false},
         &TreeParams::joint_blend,
         nullptr},
        {{"crown_blend",
          "how crown spheres fuse: root (seed 001's root smooth min) or pasko (Pasko-Savchenko)", 0,
          1, true, kCrownBlends},
         nullptr,
         &TreeParams::crown_blend},
        {{"crown_mesh", "1: mesh the crown; 0: leaves only", 0, 1, true},
         nullptr,
         &TreeParams::crown_mesh},
        {{"crown_merge",
          "1: at low triangle budgets, grow crown blobs until a few shapes remain; 0: never", 0, 1,
          true},
         nullptr,
         &TreeParams::crown_merge},
        {{"drop_hidden",
          "1: the crown hides most of the trunk: the game mesh leaves out the branches and "
          "twigs it hides and meshes the trunk at the budget's resolution (2-5x fewer raw "
          "triangles); 0: keeps them all at trunk_resolution",
          0, 1, true},
         nullptr,
         &TreeParams::drop_hidden},
        {{"leaf_density", "leaves per cubic meter of crown (0 = none)", 0, 20000, false},
         &TreeParams::leaf_density,
         nullptr},
        {{"leaf_size", "leaf length, meters", 0.01, 2, false}, &TreeParams::leaf_size, nullptr},
        {{"leaf_shape", "round, oak, needle or frond", 0, 3, true, kLeafShapes},
         nullptr,
         &TreeParams::leaf_shape},
        {{"polygon_part",
          "where the turtle's { } polygons go: leaves (fanned into the leaf part, thinned with "
          "it) or organs (their own part, coloured by index, with flowers and fruit)",
          0, 1, true, kPolygonParts},
         nullptr,
         &TreeParams::polygon_part},
        {{"triangle_budget",
          "export: trunk + crown reduced to this many triangles (0 = keep every marching-cubes "
          "triangle)",
          0, 10000000, true},
         nullptr,
         &TreeParams::triangle_budget},
        {{"crown_shape",
          "game mesh crown: auto (convex hulls when blobs touch in rings, else blobs), blobs "
          "(its own surface) or hulls",
          0, 2, true, kCrownShapes},
         nullptr,
         &TreeParams::crown_shape},
        whole("crown_lump_triangles",
              "game mesh crown as hulls: triangles of the budget per lump (more: fewer, larger "
              "lumps)",
              10, 1000, &TreeParams::crown_lump_triangles),
        {{"branch_style",
          "game mesh branches: prisms (a few-sided prism per branch, pointed at the tips), "
          "surface (the trunk's smooth surface reduced with the crown) or auto (surface when "
          "joint_blend blends the joints, else prisms)",
          0, 2, true, kBranchStyles},
         nullptr,
         &TreeParams::branch_style},
        {{"leaf_style",
          "leaves: cards (a game mesh over its leaf budget draws a card per patch of foliage), "
          "leaves (it keeps some of the tree's own leaves, grown), none (no leaves, the crown "
          "alone) or textured (cards with a texture of leaves, for alpha-tested engines)",
          0, 3, true, kLeafStyles},
         nullptr,
         &TreeParams::leaf_style},
        // Space colonization (Liebemann 2017, chapter 3).
        whole("attraction_points", "colonization: number of attraction points N", 1, 1000000,
              &TreeParams::attraction_points),
        real("influence_radius", "colonization: d_i, a point attracts nodes this close, meters",
             0.001, 100, &TreeParams::influence_radius),
        real("kill_distance",
             "colonization: d_k, a point dies when a node is this close, meters (<= d_i)", 0.001,
             100, &TreeParams::kill_distance),
        real("step_size", "colonization: D, distance of a new node from its parent, meters", 0.001,
             10, &TreeParams::step_size),
        whole("max_iterations", "colonization: iterations before growth stops", 1, 100000,
              &TreeParams::max_iterations),
        {{"envelope",
          "colonization: the crown's shape: sphere, ellipsoid, cone, cylinder, hemisphere, or "
          "template (the crown of envelope_template)",
          0, 5, true, kEnvelopes},
         nullptr,
         &TreeParams::envelope},
        {{"envelope_template",
          "colonization: with envelope = template, the built-in template whose crown is the "
          "envelope",
          0, std::size(kEnvelopeTemplates) - 1.0, true, kEnvelopeTemplates},
         nullptr,
         &TreeParams::envelope_template},
        real("envelope_size_x", "colonization: the envelope's width (x), meters", 0.01, 100,
             &TreeParams::envelope_size_x),
        real("envelope_size_y", "colonization: the envelope's height (y), meters", 0.01, 100,
             &TreeParams::envelope_size_y),
        real("envelope_size_z", "colonization: the envelope's depth (z), meters", 0.01, 100,
             &TreeParams::envelope_size_z),
        real("envelope_base", "colonization: height of the envelope's bottom, meters", -50, 100,
             &TreeParams::envelope_base),
        real("envelope_offset_x", "colonization: the envelope moved off the root along x, meters",
             -50, 50, &TreeParams::envelope_offset_x),
        real("envelope_offset_z", "colonization: the envelope moved off the root along z, meters",
             -50, 50, &TreeParams::envelope_offset_z),
        real("envelope_tilt",
             "colonization: the envelope leans by this many degrees about Z (positive: top "
             "towards +x)",
             -90, 90, &TreeParams::envelope_tilt),
        {{"obstacle",
          "colonization: none, sphere or box: a solid with no attraction points that no branch "
          "grows into",
          0, 2, true, kObstacles},
         nullptr,
         &TreeParams::obstacle},
        real("obstacle_x", "colonization: the obstacle's centre, x, meters", -50, 50,
             &TreeParams::obstacle_x),
        real("obstacle_y", "colonization: the obstacle's centre, y (height), meters", -50, 100,
             &TreeParams::obstacle_y),
        real("obstacle_z", "colonization: the obstacle's centre, z, meters", -50, 50,
             &TreeParams::obstacle_z),
        real("obstacle_size_x", "colonization: the obstacle's width (x), meters", 0.01, 100,
             &TreeParams::obstacle_size_x),
        real("obstacle_size_y", "colonization: the obstacle's height (y), meters", 0.01, 100,
             &TreeParams::obstacle_size_y),
        real("obstacle_size_z", "colonization: the obstacle's depth (z), meters", 0.01, 100,
             &TreeParams::obstacle_size_z),
        whole("roots", "colonization: trees grown from a circle of roots, sharing the points", 1,
              64, &TreeParams::roots),
        real("root_spread", "colonization: radius of the circle of roots, meters", 0, 50,
             &TreeParams::root_spread),
        {{"point_distribution",
          "colonization: attraction points uniform (random) or halton (low discrepancy)", 0, 1,
          true, kPointDistributions},
         nullptr,
         &TreeParams::point_distribution},
        real("trunk_height", "colonization: the trunk grows at least this high first, meters", 0,
             100, &TreeParams::trunk_height),
        real("tropism_vector_x",
             "tropism T along x: colonization adds T to each growth direction; the L-system "
             "turtle bends towards T by `tropism` after each F (T = 0: straight down)",
             -2, 2, &TreeParams::tropism_vector_x),
        real("tropism_vector_y",
             "tropism T along y (negative: gravity, positive: light; see tropism_vector_x)", -2, 2,
             &TreeParams::tropism_vector_y),
        real("tropism_vector_z", "tropism T along z (see tropism_vector_x)", -2, 2,
             &TreeParams::tropism_vector_z),
        whole("max_degree", "colonization: max_grad, successors per node (0 = no limit)", 0, 100,
              &TreeParams::max_degree),
        whole("max_depth", "colonization: max_Z, branch depth (eq. 3.5; 0 = no limit)", 0, 1000,
              &TreeParams::max_depth),
        whole("max_no_grow",
              "colonization: max_NG, iterations without growth before a node stops attracting "
              "(0 = never)",
              0, 100000, &TreeParams::max_no_grow),
        whole("weighted_growth",
              "colonization: 1: step 2D at branch depth 0 down to D at max_depth; 0: always D", 0,
              1, &TreeParams::weighted_growth),
        real("curve_reduction",
             "colonization: eq. 3.6, a node on a run straighter than this dot product is removed "
             "(1 = keep all)",
             0, 1, &TreeParams::curve_reduction),
        real("angle_smoothing",
             "colonization: successors drawn towards their mean direction (0 = not, 1 = fully)", 0,
             1, &TreeParams::angle_smoothing),
        // Variation and age.
        real("age",
             "tree age: 0 a seedling, 1 the mature tree; grows continuously along the branches", 0,
             1, &TreeParams::age),
        real("bend",
             "L-system: branches curve coherently, by up to this many degrees per meter (noise "
             "along each branch; 0 = straight)",
             0, 360, &TreeParams::bend),
        real("bend_frequency",
             "noise cycles per meter along a branch for bend, width_variation and "
             "tropism_variation (colonization: per meter of space)",
             0.01, 20, &TreeParams::bend_frequency),
        {{"noise_kind",
          "the noise of noise(), fbm() and noise_loop() in rules and of bend, width and tropism "
          "variation: gradient (Perlin) or value noise with linear, cosine or cubic "
          "interpolation (Limbach 2004)",
          0, 3, true, kNoiseKinds},
         nullptr,
         &TreeParams::noise_kind},
        real("jitter",
             "L-system: each branch's angles and lengths times a factor in 1 +- jitter, drawn "
             "per branch from the seed",
             0, 0.9, &TreeParams::jitter),
        real("width_variation",
             "L-system: widths swell and thin by up to this share along each branch (noise)", 0,
             0.9, &TreeParams::width_variation),
        real("tropism_variation",
             "the tropism vector plus up to this much noise, along each branch (L-system) or "
             "through space (colonization: branches bend coherently)",
             0, 2, &TreeParams::tropism_variation),
        real("color_variation",
             "trunk, crown and leaf colours shifted per seed in brightness and hue by up to this "
             "share (0 = the template's colours)",
             0, 1, &TreeParams::color_variation),
    };
    return table;
}

const Field* find_field(std::string_view key) {
    for (const Field& f : fields())
        if (f.info.key == key) return &f;
    return nullptr;
}

std::string range_text(const ParamInfo& info) {
    std::ostringstream out;
    if (!info.choices.empty()) {
        for (size_t i = 0; i < info.choices.size(); ++i) out << (i ? ", " : "") << info.choices[i];
        return out.str();
    }
    out << info.min << " to " << info.max;
    return out.str();
}

}  // namespace

BranchStyle branch_style(const TreeParams& params) {
    const auto style = static_cast<BranchStyle>(params.branch_style);
    if (style != BranchStyle::Automatic) return style;
    return params.joint_blend > 0.0 ? BranchStyle::Surface : BranchStyle::Prisms;
}

std::span<const std::string_view> envelope_template_names() {
    return kEnvelopeTemplates;
}

const std::vector<ParamInfo>& param_infos() {
    static const std::vector<ParamInfo> infos = [] {
        std::vector<ParamInfo> out;
        for (const Field& f : fields()) out.push_back(f.info);
        return out;
    }();
    return infos;
}

std::optional<double> get_param(const TreeParams& params, std::string_view key) {
    const Field* f = find_field(key);
    if (!f) return std::nullopt;
    return f->real ? params.*(f->real) : static_cast<double>(params.*(f->integer));
}

const Field& known_field(std::string_view key) {
    const Field* f = find_field(key);
    if (!f) {
        std::string known;
        for (const Field& g : fields())
            known += (known.empty() ? "" : ", ") + std::string(g.info.key);
        throw InputError("unknown parameter '" + std::string(key) + "' (known: " + known + ")");
    }
    return *f;
}

void set_param(TreeParams& params, std::string_view key, double value) {
    const Field& f = known_field(key);
    const ParamInfo& info = f.info;
    // The shortest text that reads back as `value`: 10.0000000001 is not shown as "10".
    char digits[32];
    const std::string shown(digits, std::to_chars(digits, digits + sizeof digits, value).ptr);
    if (!std::isfinite(value) || value < info.min || value > info.max)
        throw InputError("parameter " + std::string(key) + " = " + shown + " is out of range " +
                         range_text(info));
    if (info.integer) {
        if (value != std::floor(value))
            throw InputError("parameter " + std::string(key) + " must be a whole number, not " +
                             shown);
        params.*(f.integer) = static_cast<int>(value);
    } else {
        params.*(f.real) = value;
    }
}

void set_param(TreeParams& params, std::string_view key, std::string_view text) {
    const ParamInfo& info = known_field(key).info;
    for (size_t i = 0; i < info.choices.size(); ++i)
        if (info.choices[i] == text) return set_param(params, key, static_cast<double>(i));
    double value = 0.0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || text.empty())
        throw InputError("parameter " + std::string(key) + ": '" + std::string(text) + "' is not " +
                         (info.choices.empty() ? "a number" : "one of the choices") + " (" +
                         range_text(info) + ")");
    set_param(params, key, value);
}

std::string param_text(const TreeParams& params, const ParamInfo& info) {
    double value = *get_param(params, info.key);
    if (!info.choices.empty()) return std::string(info.choices[static_cast<size_t>(value)]);
    std::ostringstream out;
    out << value;
    return out.str();
}

}  // namespace sylva
