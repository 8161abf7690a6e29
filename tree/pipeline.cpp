#include "tree/pipeline.h"

#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/parallel_invoke.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <mutex>
#include <optional>
#include <set>
#include <span>

#include "core/errors.h"
#include "core/stopwatch.h"
#include "core/tree_age.h"
#include "lowpoly/merge_meshes.h"
#include "marching/mesher.h"
#include "sdf/cone_field.h"
#include "tree/crown_bridges.h"
#include "tree/field_grid.h"
#include "tree/growth.h"
#include "tree/hidden_branches.h"
#include "tree/leaves.h"
#include "tree/trunk_pieces.h"

namespace sylva {
namespace {

// Meshes a field with the chosen mesher, reporting its progress to options.progress.
template <class Field>
Mesh mesh_field(const Field& field, const Box& box, int resolution, const MeshOptions& options) {
    const BatchField batch = [&field](std::span<const glm::vec3> points, std::span<float> values) {
        field.evaluate(points, values);
    };
    MeshSettings settings;
    settings.mesher = options.mesher;
    settings.vdb.adaptivity = options.vdb_adaptivity;
    settings.resolution = resolution;
    settings.threads = options.threads;
    settings.cancel = options.cancel;
    settings.progress = options.progress;
    return mesh(batch, box, settings);
}

Box crown_bounds(const std::vector<Ball>& balls) {
    Box box{glm::vec3(std::numeric_limits<float>::max()),
            glm::vec3(std::numeric_limits<float>::lowest())};
    for (const Ball& b : balls) {
        box.min = glm::min(box.min, b.center - glm::vec3(b.radius));
        box.max = glm::max(box.max, b.center + glm::vec3(b.radius));
    }
    return box;
}

// Snaps `box` outwards to the world lattice of `cell`s (so trees of different ages sample the
// same grid points) with at least 4 cells on its longest side; a cell of 0 leaves it. Returns
// the cell the box is then meshed with.
float fit_to_cells(Box& box, float cell, int resolution) {
    if (!(cell > 0.0f)) return cell_size(box, resolution);
    box.min = glm::floor(box.min / cell) * cell;
    box.max = glm::ceil(box.max / cell) * cell;
    const glm::vec3 extent = box.max - box.min;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                     : extent.y >= extent.z                       ? 1
                                                                  : 2;
    box.max[axis] = std::max(box.max[axis], box.min[axis] + 4.0f * cell);
    return cell;
}

// The crown's field over `balls`, and the box it is meshed in.
void add_crown_field(TreeFields& fields, std::vector<Ball> balls, const TreeParams& p,
                     float fixed_cell) {
    float fusion = static_cast<float>(p.crown_fusion);
    // The root smooth min swells the union by up to fusion / 2 where spheres meet.
    fields.crown_box = crown_bounds(balls);
    fields.crown_box.min -= glm::vec3(fusion);
    fields.crown_box.max += glm::vec3(fusion);
    float crown_cell = fit_to_cells(fields.crown_box, fixed_cell, p.crown_resolution);
    balls = merge_coincident_balls(std::move(balls), kMergeToleranceInCells * crown_cell);
    float margin = kFieldMarginInCells * crown_cell + 4.0f * fusion;
    if (p.crown_blend == CrownBlend::Pasko) {
        // Equation 2.13's alpha: 1 is the hard union; the strongest fusion (0.1) gives 0.
        float alpha = std::clamp(1.0f - 10.0f * fusion, 0.0f, 1.0f);
        fields.crown.emplace(std::move(balls), alpha, margin, SphereBlend::PaskoSavchenko);
    } else {
        fields.crown.emplace(std::move(balls), fusion, margin);
    }
}

// Sylva models trees, not continents: a segment that ends farther out than this (or at a
// non-finite point, from F(1e39) say) is bad input, found before any grid is sized by it.
constexpr float kMaxExtent = 1.0e5f;  // metres

void check_extent(const Skeleton& skeleton) {
    for (std::size_t i = 0; i < skeleton.segments.size(); ++i) {
        const Segment& s = skeleton.segments[i];
        for (const glm::vec3& p : {s.a, s.b}) {
            if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) &&
                std::abs(p.x) <= kMaxExtent && std::abs(p.y) <= kMaxExtent &&
                std::abs(p.z) <= kMaxExtent && std::isfinite(s.ra) && std::isfinite(s.rb) &&
                s.ra <= kMaxExtent && s.rb <= kMaxExtent)
                continue;
            throw InputError("segment " + std::to_string(i) + " of the skeleton reaches (" +
                             std::to_string(p.x) + ", " + std::to_string(p.y) + ", " +
                             std::to_string(p.z) + ") with radius " + std::to_string(s.rb) +
                             ": a tree must stay within " + std::to_string(int(kMaxExtent)) +
                             " m of its root with finite widths (check the F lengths, widths "
                             "and branch_length)");
        }
    }
}

}  // namespace

std::vector<Ball> crown_spheres(const Skeleton& skeleton, const TreeParams& params) {
    std::vector<Ball> out;
    // Tips that end at the same point (brackets that redraw a branch) give one sphere: the
    // copies would add nothing but a visit each at every sample near them (the crown's field
    // merges near ones too, within its cell).
    std::set<std::array<float, 3>> seen;
    for (int tip : tips(skeleton)) {
        const Segment& s = skeleton.segments[static_cast<size_t>(tip)];
        const glm::vec3 centre =
            s.b + glm::vec3(0.0f, static_cast<float>(params.crown_offset), 0.0f);
        if (!seen.insert({centre.x, centre.y, centre.z}).second) continue;
        out.push_back({centre, static_cast<float>(params.sphere_diameter * 0.5)});
    }
    return out;
}

Box skeleton_bounds(const Skeleton& skeleton) {
    Box box{glm::vec3(std::numeric_limits<float>::max()),
            glm::vec3(std::numeric_limits<float>::lowest())};
    for (const Segment& s : skeleton.segments) {
        float r = std::max(s.ra, s.rb);
        box.min = glm::min(box.min, glm::min(s.a, s.b) - glm::vec3(r));
        box.max = glm::max(box.max, glm::max(s.a, s.b) + glm::vec3(r));
    }
    return box;
}

int cells_along(const Box& box, float cell) {
    const glm::vec3 extent = box.max - box.min;
    return static_cast<int>(std::lround(std::max({extent.x, extent.y, extent.z}) / cell));
}

TreeFields tree_fields(const Skeleton& skeleton, const TreeParams& p, const FieldCells& cells,
                       CancelFlag cancel, TrunkField trunk) {
    TreeFields fields;
    // The joint blend swells the union by up to joint_blend / 4 where cones meet.
    float joint_blend = static_cast<float>(p.joint_blend);
    fields.trunk_box = skeleton_bounds(skeleton);
    fields.trunk_box.min -= glm::vec3(joint_blend);
    fields.trunk_box.max += glm::vec3(joint_blend);
    fields.trunk_cell = fit_to_cells(fields.trunk_box, cells.trunk, p.trunk_resolution);
    throw_if_cancelled(cancel);
    // The two fields share nothing: each is built beside the other (their bins are mostly
    // serial work).
    tbb::parallel_invoke(
        [&] {
            if (trunk == TrunkField::Whole)
                fields.trunk =
                    trunk_field(skeleton.segments, fields.trunk_cell, joint_blend, cancel);
            if (trunk == TrunkField::Pieces)
                fields.trunk_pieces =
                    trunk_pieces(skeleton, std::vector<std::uint8_t>(skeleton.segments.size(), 1),
                                 fields.trunk_cell, joint_blend, cancel);
        },
        [&] {
            std::vector<Ball> balls = crown_spheres(skeleton, p);
            if (!balls.empty() && p.sphere_diameter > 0.0)
                add_crown_field(fields, std::move(balls), p, cells.crown);
        });
    throw_if_cancelled(cancel);
    return fields;
}

namespace {

// A younger tree (core/tree_age.h) is meshed with the mature tree's cells, not with as many
// cells as the mature one over its smaller box: the sapling then shows the detail per meter
// the grown tree does, and its triangles rise with its size instead of staying flat (or
// wobbling with a rounded resolution). Its crown spheres shrink with age.
FieldCells apply_age(TreeParams& p, const Skeleton& mature) {
    FieldCells cells;
    const float joint_blend = static_cast<float>(p.joint_blend);
    Box trunk = skeleton_bounds(mature);
    trunk.min -= glm::vec3(joint_blend);
    trunk.max += glm::vec3(joint_blend);
    cells.trunk = cell_size(trunk, p.trunk_resolution);
    const std::vector<Ball> balls = crown_spheres(mature, p);
    if (!balls.empty() && p.sphere_diameter > 0.0) {
        Box crown = crown_bounds(balls);
        crown.min -= glm::vec3(static_cast<float>(p.crown_fusion));
        crown.max += glm::vec3(static_cast<float>(p.crown_fusion));
        cells.crown = cell_size(crown, p.crown_resolution);
    }
    const double crown_scale = crown_scale_at_age(p.age);
    p.sphere_diameter *= crown_scale;
    p.crown_offset *= crown_scale;
    return cells;
}

// The thinnest branch the full-detail trunk draws (kMinRadiusInCells at the template's own
// resolution): what prisms widen thinner branches to, so a game mesh keeps its outline.
float full_detail_radius(const Skeleton& skeleton, const TreeParams& template_params) {
    Box box = skeleton_bounds(skeleton);
    const float joint_blend = static_cast<float>(template_params.joint_blend);
    box.min -= glm::vec3(joint_blend);
    box.max += glm::vec3(joint_blend);
    return kMinRadiusInCells * cell_size(box, template_params.trunk_resolution);
}

}  // namespace

Mesh tree_leaves(const Skeleton& skeleton, const TreeFields& fields, const TreeParams& p,
                 CancelFlag cancel) {
    Mesh out;
    if (fields.crown && p.leaf_density > 0.0) {
        LeafSettings leaves;
        leaves.density = p.leaf_density;
        leaves.size = p.leaf_size;
        leaves.shape = p.leaf_shape;
        leaves.seed = p.seed;
        leaves.cancel = cancel;
        const SphereField& crown = *fields.crown;
        leaves.inside_is_distance_bound = crown.is_distance_bound();
        // Behind a meshed crown only the leaves near its surface are ever seen: they fill a
        // shell one leaf deep, so the crown wears its leaves instead of hiding them (and the
        // hidden ones cost no triangles). The shell needs a distance bound (not Pasko's blend).
        const float shell = static_cast<float>(p.leaf_size);
        if (p.crown_mesh && crown.is_distance_bound() && shell > 0.0f)
            out = scatter_leaves(
                [&crown, shell](const glm::vec3& q) {
                    return std::abs(crown(q) + 0.5f * shell) - 0.5f * shell;
                },
                fields.crown_box, leaves);
        else
            out = scatter_leaves([&crown](const glm::vec3& q) { return crown(q); },
                                 fields.crown_box, leaves);
    }
    if (p.polygon_part == PolygonPart::Leaves) add_polygon_leaves(out, skeleton.polygons);
    return out;
}

namespace {

// Why a crown that was asked for has no surface: spheres smaller than a cell of a grid over
// a crown box that tips far apart make large.
std::string vanished_crown(const TreeParams& p, const Box& box) {
    const glm::vec3 extent = box.max - box.min;
    char text[400];
    std::snprintf(text, sizeof text,
                  "the crown was left out: its spheres (sphere_diameter %.3g m) fall between the "
                  "points of its grid, %.3g m apart (%d cells along %.3g m, the box of every "
                  "tip); raise sphere_diameter or crown_resolution, or set crown_mesh = 0 for "
                  "leaves alone",
                  p.sphere_diameter, static_cast<double>(cell_size(box, p.crown_resolution)),
                  p.crown_resolution,
                  static_cast<double>(std::max({extent.x, extent.y, extent.z})));
    return text;
}

}  // namespace

double stages_wall_ms(const std::vector<StageTime>& times) {
    double wall = 0.0, beside = 0.0;
    for (const StageTime& stage : times) {
        if (stage.beside_others)
            beside = std::max(beside, stage.ms);
        else
            wall += stage.ms;
    }
    return wall + beside;
}

namespace {

// A game mesh's trunk once the crown's field says which segments it draws: without the
// branches the crown hides (drop_hidden), as pieces (trunk_pieces) or as prism axes
// (prisms); the trunk of a game mesh with prisms alone as axes. Returns the box the trunk is
// meshed in: the field's, or the one around the segments it keeps.
Box game_trunk(Tree& out, TreeFields& fields, const TreeParams& p,
               const TreeParams& template_params, bool drop_hidden, bool prisms,
               CancelFlag cancel) {
    const float joint_blend = static_cast<float>(p.joint_blend);
    const std::vector<Segment>& segments = out.skeleton.segments;
    Box trunk_box = fields.trunk_box;
    float trunk_cell = fields.trunk_cell;
    if (drop_hidden) {
        std::vector<std::uint8_t> shown(segments.size(), 1);
        if (fields.crown) {
            std::vector<std::uint8_t> visible = visible_segments(
                out.skeleton, *fields.crown, cell_size(fields.trunk_box, p.trunk_resolution));
            Skeleton kept;
            for (std::size_t i = 0; i < segments.size(); ++i)
                if (visible[i]) kept.segments.push_back(segments[i]);
            if (!kept.segments.empty() && kept.segments.size() < segments.size()) {
                out.hidden_segments = segments.size() - kept.segments.size();
                shown = std::move(visible);
                trunk_box = skeleton_bounds(kept);
                trunk_box.min -= glm::vec3(joint_blend);
                trunk_box.max += glm::vec3(joint_blend);
                trunk_cell = cell_size(trunk_box, p.trunk_resolution);
            }
        }
        if (!prisms)
            fields.trunk_pieces =
                trunk_pieces(out.skeleton, shown, trunk_cell, joint_blend, cancel);
        else
            out.branch_axes =
                branch_axes(out.skeleton, shown, full_detail_radius(out.skeleton, template_params));
    } else if (prisms) {
        out.branch_axes = branch_axes(out.skeleton, std::vector<std::uint8_t>(segments.size(), 1),
                                      full_detail_radius(out.skeleton, template_params));
    }
    return trunk_box;
}

// Throws InputError when the tree has nothing to draw a trunk from.
void require_trunk(const Tree& out, const TreeFields& fields, bool prisms) {
    if (prisms && out.branch_axes.axes.empty())
        throw InputError(
            "the tree has no trunk: the derived word draws no segment with a "
            "width above zero (it needs F, and a width from branch_width or !)");
    if (!prisms && !fields.trunk && fields.trunk_pieces.empty())
        throw InputError(
            "the tree has no trunk: the derived word draws no segment with a "
            "width above zero (it needs F, and a width from branch_width or !)");
}

// The meshing stage's progress: the trunk's share of what its pieces have done on average
// plus the crown's of what it has done, reported one at a time so that it only rises. Each
// slot's callback may run on any thread; the object must outlive the meshing.
class MeshingProgress {
  public:
    MeshingProgress(const MeshOptions& options, std::size_t trunk_slots, float trunk_share)
        : options_(options),
          trunk_slots_(trunk_slots),
          trunk_share_(trunk_share),
          done_(trunk_slots + 1, 0.0f) {}

    // `options_` reporting as slot `slot`: a trunk piece, or trunk_slots for the crown.
    MeshOptions options_for(std::size_t slot) {
        MeshOptions part = options_;
        if (options_.progress)
            part.progress = [this, slot](float f) {
                const std::lock_guard<std::mutex> one_at_a_time(reporting_);
                done_[slot] = f;
                float trunk = 0.0f;
                for (std::size_t k = 0; k < trunk_slots_; ++k) trunk += done_[k];
                options_.progress(trunk_share_ * trunk / static_cast<float>(trunk_slots_) +
                                  (1.0f - trunk_share_) * done_[trunk_slots_]);
            };
        return part;
    }

  private:
    const MeshOptions& options_;
    const std::size_t trunk_slots_;
    const float trunk_share_;
    std::vector<float> done_;  // each trunk piece's fraction, the crown's
    std::mutex reporting_;
};

// The trunk's mesh: a game mesh's prisms for the budget, its pieces meshed beside each other
// and merged, or the whole trunk's field meshed.
Mesh mesh_trunk(const Tree& out, const TreeFields& fields, const Box& trunk_box, int resolution,
                const MeshOptions& options, MeshingProgress& progress, bool prisms,
                bool mesh_crown) {
    if (prisms) {
        Mesh trunk = branch_prisms(out.branch_axes, options.budget).mesh;
        if (!mesh_crown && options.progress) options.progress(1.0f);
        return trunk;
    }
    if (options.budget > 0) {
        // The pieces meshed beside each other too.
        const std::vector<ConeField>& pieces = fields.trunk_pieces;
        std::vector<Mesh> meshed(pieces.size());
        tbb::parallel_for(std::size_t{0}, pieces.size(), [&](std::size_t k) {
            meshed[k] = mesh_field(pieces[k], trunk_box, resolution, progress.options_for(k));
        });
        std::vector<const Mesh*> all;
        for (const Mesh& m : meshed) all.push_back(&m);
        return merge_meshes(all);
    }
    return mesh_field(*fields.trunk, trunk_box, resolution, progress.options_for(0));
}

// The crown's mesh, with the bridges a low budget needs (crown_bridges.h); `bridges_made` is
// set to their number.
Mesh mesh_bridged_crown(const TreeFields& fields, const TreeParams& p, MeshOptions crown_options,
                        std::size_t budget, std::size_t& bridges_made) {
    // Skipping empty space needs a distance bound; the Pasko-Savchenko blend is not one.
    if (!fields.crown->is_distance_bound() && crown_options.mesher != Mesher::Dense)
        crown_options.mesher = Mesher::Dense;
    std::vector<CappedCone> bridges =
        crown_bridge_cones(*fields.crown, budget, p, fields.crown_box);
    bridges_made = bridges.size();
    if (bridges.empty())
        return mesh_field(*fields.crown, fields.crown_box, p.crown_resolution, crown_options);
    const float cell = cell_size(fields.crown_box, p.crown_resolution);
    const ConeField struts(std::move(bridges), kFieldMarginInCells * cell);
    return mesh_field(BridgedCrown{*fields.crown, struts}, fields.crown_box, p.crown_resolution,
                      crown_options);
}

// The trunk, the crown and the leaves, made beside each other: each reads the fields alone,
// and what one leaves of the cores (the crown's bridges, a mesher's last blocks) the others
// take. Each stage's time is its own, so they overlap.
void mesh_parts(Tree& out, const TreeFields& fields, const TreeParams& p, const Box& trunk_box,
                const MeshOptions& options, bool prisms, bool mesh_crown) {
    // Prisms are drawn, not meshed: the crown's meshing is all the progress there is.
    const float trunk_share = prisms ? 0.0f : mesh_crown ? 0.5f : 1.0f;
    const std::size_t trunk_slots = std::max<std::size_t>(fields.trunk_pieces.size(), 1);
    MeshingProgress progress(options, trunk_slots, trunk_share);
    double trunk_ms = 0.0, crown_ms = 0.0, leaves_ms = 0.0;
    auto trunk = [&] {
        Stopwatch own;
        out.trunk = mesh_trunk(out, fields, trunk_box, p.trunk_resolution, options, progress,
                               prisms, mesh_crown);
        trunk_ms = own.lap_ms();
    };
    auto crown = [&] {
        if (!mesh_crown) return;
        Stopwatch own;
        out.crown = mesh_bridged_crown(fields, p, progress.options_for(trunk_slots), options.budget,
                                       out.crown_bridges);
        crown_ms = own.lap_ms();
    };
    auto leaves = [&] {
        if (out.leaf_style == LeafStyle::None) return;
        Stopwatch own;
        out.leaves = tree_leaves(out.skeleton, fields, p, options.cancel);
        leaves_ms = own.lap_ms();
    };
    tbb::parallel_invoke(trunk, crown, leaves);
    if (mesh_crown && out.crown.triangles.empty())
        out.notes.push_back(vanished_crown(p, fields.crown_box));
    out.times.push_back({"trunk mesh", trunk_ms, true});
    if (mesh_crown) out.times.push_back({"crown mesh", crown_ms, true});
    if (out.leaf_style != LeafStyle::None) out.times.push_back({"leaves", leaves_ms, true});
}

}  // namespace

Tree generate_tree(const TreeTemplate& tree, const MeshOptions& options) {
    Tree out;
    Skeleton mature;
    GrowthContext growth{options.cancel, &out.times};
    growth.progress = options.growth_progress;
    growth.limits = options.growth_limits;
    out.skeleton = grow(tree, growth, &mature);
    out.crown_shape = tree.params.crown_shape;
    out.crown_lump_triangles = static_cast<std::size_t>(tree.params.crown_lump_triangles);
    out.leaf_style = tree.params.leaf_style;
    out.leaf_shape = tree.params.leaf_shape;
    TreeParams p = tree.params;
    p.crown_resolution = crown_resolution_for_budget(p.crown_resolution, options.budget);
    p.trunk_resolution = trunk_resolution_for_budget(p, options.budget);
    const FieldCells cells = p.age < 1.0 ? apply_age(p, mature) : FieldCells{};

    check_extent(out.skeleton);
    out.organs = tree_organs(out.skeleton, p);  // small; an unknown organ fails before meshing
    throw_if_cancelled(options.cancel);         // each stage below starts only when still wanted
    Stopwatch clock;
    const bool crown_wanted = p.crown_mesh;
    // A game mesh's trunk leaves out the branches the crown hides (drop_hidden) and comes in
    // groups (trunk_pieces): its fields are built once the crown's says which segments it
    // draws, not twice.
    const bool game_mesh = options.budget > 0;
    const bool drop_hidden = crown_wanted && game_mesh && p.drop_hidden;
    // A game mesh's branches as prisms need no trunk field at all, only the segments.
    const bool prisms = game_mesh && branch_style(p) == BranchStyle::Prisms;
    TreeFields fields = tree_fields(out.skeleton, p, cells, options.cancel,
                                    !game_mesh              ? TrunkField::Whole
                                    : drop_hidden || prisms ? TrunkField::None
                                                            : TrunkField::Pieces);
    if (cells.trunk > 0.0f) p.trunk_resolution = cells_along(fields.trunk_box, cells.trunk);
    if (cells.crown > 0.0f && fields.crown)
        p.crown_resolution = cells_along(fields.crown_box, cells.crown);
    throw_if_cancelled(options.cancel);
    const bool mesh_crown = fields.crown && crown_wanted;
    const Box trunk_box =
        game_trunk(out, fields, p, tree.params, drop_hidden, prisms, options.cancel);
    out.times.push_back({"fields", clock.lap_ms()});
    throw_if_cancelled(options.cancel);
    require_trunk(out, fields, prisms);
    mesh_parts(out, fields, p, trunk_box, options, prisms, mesh_crown);
    return out;
}

}  // namespace sylva
