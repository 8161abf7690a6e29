#include "tree/pipeline.h"

#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/parallel_invoke.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
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
#include "lowpoly/decimate.h"
#include "lowpoly/merge_meshes.h"
#include "marching/mesher.h"
#include "sdf/cone_field.h"
#include "tree/crown_merge.h"
#include "tree/growth.h"
#include "tree/leaves.h"

namespace sylva {
namespace {

// One capped cone per segment with a width. Branches thinner than the grid can sample
// would break into disconnected crumbs, so radii are raised to kMinRadiusInCells cells:
// a ball that wide always holds a grid node (the cubic lattice's covering radius is
// sqrt(3)/2 = 0.87 cells), which keeps every branch in one piece. Finer twigs need a
// higher trunk_resolution.
constexpr float kMinRadiusInCells = 0.9f;

// Primitives closer than this to an earlier one are merged into it (cone_field.h,
// sphere_field.h).
constexpr float kMergeToleranceInCells = 0.125f;

std::vector<CappedCone> resolvable_cones(std::span<const Segment> segments, float cell) {
    const float min_radius = kMinRadiusInCells * cell;
    std::vector<CappedCone> cones;
    cones.reserve(segments.size());
    for (const Segment& s : segments)
        if (std::max(s.ra, s.rb) > 0.0f)
            cones.push_back({s.a, s.b, std::max(s.ra, min_radius), std::max(s.rb, min_radius)});
    // Copies of one segment (brackets that redraw it, with or without tiny turns) add
    // nothing the grid can show but cost every sample near them a visit each; an eighth of a
    // cell is below what it resolves.
    return merge_coincident_cones(std::move(cones), kMergeToleranceInCells * cell);
}

// The trunk's field over `segments` meshed with cells of `cell`; empty when no segment has a
// width.
std::optional<ConeField> trunk_field(std::span<const Segment> segments, float cell,
                                     float joint_blend, CancelFlag cancel);

// The culled fields are exact within this many cells of the surface (all marching cubes
// interpolates) and a lower bound of the distance beyond it, which is all the sparse mesher
// needs to skip empty blocks: |f(centre)| above a block's half-diagonal proves it empty.
constexpr float kFieldMarginInCells = 3.0f;
// A trunk without a joint blend, a hard union (the min is exact however the fold starts), is
// exact within 2 cells, still more than marching cubes interpolates along a cell's edge: its
// bins are smaller and list fewer cones, so it meshes faster into the same bytes. With a
// joint blend, values near the surface blend with where the fold starts (the mesh would
// change), so it keeps kFieldMarginInCells.
constexpr float kHardUnionMarginInCells = 2.0f;

float cell_size(const Box& box, int resolution) {
    glm::vec3 extent = box.max - box.min;
    return std::max({extent.x, extent.y, extent.z}) / static_cast<float>(resolution);
}

std::optional<ConeField> trunk_field(std::span<const Segment> segments, float cell,
                                     float joint_blend, CancelFlag cancel) {
    std::vector<CappedCone> cones = resolvable_cones(segments, cell);
    if (cones.empty()) return std::nullopt;
    return std::optional<ConeField>(
        std::in_place, std::move(cones),
        (joint_blend > 0.0f ? kFieldMarginInCells : kHardUnionMarginInCells) * cell + joint_blend,
        joint_blend, cancel);
}

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

// The bridges that let a budget of `budget` trunk + crown triangles draw the crown: with
// crown_merge on and more blobs than half the budget leaves kTrianglesPerCrownPiece each,
// struts between the nearest blobs (crown_merge.h), each a cone from one sphere's centre to
// the other's, 0.6 times as thick as its sphere (and at least a cell, so the grid sees it).
std::vector<CappedCone> crown_bridge_cones(const SphereField& crown, std::size_t budget,
                                           const TreeParams& p, const Box& box) {
    if (budget == 0 || !p.crown_merge) return {};
    const std::vector<Ball>& balls = crown.balls();
    if (count_crown_pieces(balls, 0.0f) * kTrianglesPerCrownPiece <= budget / 2) return {};
    const std::size_t max_pieces = std::max<std::size_t>(1, budget / 2 / kTrianglesPerMergedPiece);
    const float cell = cell_size(box, p.crown_resolution);
    std::vector<CappedCone> cones;
    for (const auto& [i, j] : crown_bridges(balls, max_pieces))
        cones.push_back({balls[i].center, balls[j].center, std::max(balls[i].radius, cell),
                         std::max(balls[j].radius, cell)});
    return cones;
}

// The crown and its bridges as one field: the hard union of two distance bounds, still a
// distance bound, so the sparse meshers may skip space.
struct BridgedCrown {
    const SphereField& crown;
    const ConeField& bridges;
    void evaluate(std::span<const glm::vec3> points, std::span<float> values) const {
        crown.evaluate(points, values);
        std::vector<float> strut(points.size());
        bridges.evaluate(points, strut);
        for (std::size_t i = 0; i < values.size(); ++i) values[i] = std::min(values[i], strut[i]);
    }
    bool is_distance_bound() const { return crown.is_distance_bound(); }
};

// A game mesh needs no branch the crown hides (drop_hidden): such segments are left out of
// the trunk's field. A branch is hidden when every point of its axis (sampled at most half
// a radius apart) lies at least its radius inside the crown; a twig thinner than half a
// cell (drawn a cell wide) when its axis lies inside the crown. They are most of a dense
// crown's twigs, and where twigs cross they make the handles that cost a reduction most of
// its time.
std::vector<std::uint8_t> visible_segments(const Skeleton& skeleton, const SphereField& crown,
                                           float cell) {
    // Each segment on its own, in parallel: a conifer has thousands.
    std::vector<std::uint8_t> shown(skeleton.segments.size());
    tbb::parallel_for(std::size_t{0}, skeleton.segments.size(), [&](std::size_t i) {
        const Segment& s = skeleton.segments[i];
        const float r = std::max({s.ra, s.rb, kMinRadiusInCells * cell});
        const float depth = std::max(s.ra, s.rb) < 0.5f * cell ? 0.0f : r;
        const int samples = 2 + static_cast<int>(glm::distance(s.a, s.b) / (0.5f * r));
        bool hidden = true;
        for (int k = 0; k <= samples && hidden; ++k)
            hidden = crown(glm::mix(s.a, s.b, static_cast<float>(k) / samples)) < -depth;
        shown[i] = !hidden;
    });
    return shown;
}

// A game mesh's trunk is meshed as several solids that overlap where they meet: each is
// whole subtrees of the skeleton (a branch with all it carries), an eighth, an eighth, a
// quarter and the rest (with the root) of the surface, so that the reduction can deal them
// to both cores in any share of eighths (lowpoly/decimate.h: half the tree's triangles
// each, with the crown on one of them), and branches of different solids that cross make no
// handle. The surface is the hard union's either way; only where two solids meet, a
// branch's base lies inside its parent.
constexpr double kTrunkGroupShares[] = {0.125, 0.125, 0.25};
constexpr std::uint8_t kTrunkGroups = std::size(kTrunkGroupShares) + 1;

// Each segment's group (0-3, the last one the rest) among those `shown` (1 where the trunk
// draws it); all in the rest when the trunk is too small to split (the reduction would not
// split it), has a joint blend, or lists a child before its parent.
std::vector<std::uint8_t> trunk_groups(const Skeleton& skeleton,
                                       std::span<const std::uint8_t> shown, float cell,
                                       float joint_blend) {
    const std::vector<Segment>& segments = skeleton.segments;
    const std::size_t n = segments.size();
    constexpr std::uint8_t kRest = kTrunkGroups - 1;
    std::vector<std::uint8_t> group(n, kRest);
    // Marching cubes makes triangles in proportion to the surface: a cone's side, its radii
    // as the field widens them (resolvable_cones).
    const float min_radius = kMinRadiusInCells * cell;
    std::vector<double> own(n, 0.0);
    std::vector<std::vector<int>> children(n);
    std::vector<int> roots;
    double total = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const Segment& s = segments[i];
        if (s.parent >= static_cast<int>(i)) return group;
        (s.parent < 0 ? roots : children[s.parent]).push_back(static_cast<int>(i));
        if (shown[i] && std::max(s.ra, s.rb) > 0.0f)
            own[i] =
                (std::max(s.ra, min_radius) + std::max(s.rb, min_radius)) * glm::distance(s.a, s.b);
        total += own[i];
    }
    // (ra + rb) L is a cone side's area over pi; marching cubes makes 5-9 triangles per
    // square cell of it (on the built-in templates), about 8: a trunk of fewer square cells
    // than this makes fewer triangles than the reduction splits into lanes.
    constexpr double kTrianglesPerSquareCell = 8.0;
    constexpr double kGroupAtLeast =
        static_cast<double>(kLaneSplitTriangles) / kTrianglesPerSquareCell;  // square cells
    // A joint blend rounds every joint: pieces would lose the fillets where they meet.
    if (total < kGroupAtLeast * cell * cell || joint_blend > 0.0f) return group;
    // A piece starts where a branch leaves its parent, its base inside the parent's end,
    // never within a limb: there the reduced pieces would meet in a visible seam.
    auto starts_branch = [&](int i) {
        const int parent = segments[i].parent;
        return parent < 0 || segments[i].depth > segments[parent].depth;
    };
    std::vector<double> subtree(n);
    for (std::uint8_t g = 0; g < kRest; ++g) {
        // The surface still in the rest below each segment.
        for (std::size_t i = 0; i < n; ++i) subtree[i] = group[i] == kRest ? own[i] : 0.0;
        for (std::size_t i = n; i-- > 0;)
            if (segments[i].parent >= 0) subtree[segments[i].parent] += subtree[i];
        // Whole subtrees of the rest, the largest that fit what the group still needs first,
        // walking down into the largest that does not fit, until it holds its share (within
        // 2% of the trunk).
        double needed = kTrunkGroupShares[g] * total;
        const double close_enough = 0.02 * total;
        std::vector<int> level = roots;
        while (needed > close_enough && !level.empty()) {
            std::stable_sort(level.begin(), level.end(),
                             [&](int a, int b) { return subtree[a] > subtree[b]; });
            int down = -1;
            for (int root : level) {
                if (needed <= close_enough || subtree[root] == 0.0) break;
                if (subtree[root] > needed + close_enough || !starts_branch(root)) {
                    if (down < 0) down = root;
                    continue;
                }
                needed -= subtree[root];
                for (std::vector<int> stack{root}; !stack.empty();) {
                    const int i = stack.back();
                    stack.pop_back();
                    if (group[i] != kRest) continue;  // an earlier group's subtree
                    group[i] = g;
                    stack.insert(stack.end(), children[i].begin(), children[i].end());
                }
            }
            if (down < 0) break;
            level = children[down];
        }
    }
    return group;
}

// The fields of the trunk's groups (trunk_groups) that hold a segment with a width, built
// beside each other.
std::vector<ConeField> trunk_pieces(const Skeleton& skeleton, std::span<const std::uint8_t> shown,
                                    float cell, float joint_blend, CancelFlag cancel) {
    const std::vector<std::uint8_t> group = trunk_groups(skeleton, shown, cell, joint_blend);
    std::vector<Segment> of[kTrunkGroups];
    for (std::size_t i = 0; i < skeleton.segments.size(); ++i)
        if (shown[i]) of[group[i]].push_back(skeleton.segments[i]);
    std::optional<ConeField> fields[kTrunkGroups];
    tbb::parallel_for(std::size_t{0}, std::size_t{kTrunkGroups}, [&](std::size_t g) {
        fields[g] = trunk_field(of[g], cell, joint_blend, cancel);
    });
    std::vector<ConeField> pieces;
    for (std::optional<ConeField>& f : fields)
        if (f) pieces.push_back(std::move(*f));
    return pieces;
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

// `cells` rounded up, at least 24 (a coarser grid breaks thin parts apart) and at most
// `resolution`: what a budget meshes at instead of the template's resolution.
int capped(int resolution, double cells) {
    return std::min(resolution, std::max(24, static_cast<int>(std::ceil(cells))));
}

// The cells a part needs for its share (half) of `budget` triangles: about sqrt(share)
// vertices along it, and twice that many cells keeps fidelity (40 at 800).
double share_cells(std::size_t budget) {
    return 2.0 * std::sqrt(static_cast<double>(budget) / 2.0);
}

// The crown's cells for `budget` triangles: share_cells up to 800; above, 40 cells times the
// fourth root of budget / 800 (56 at 3000 instead of 78). A crown of blobs is smooth, and at
// such budgets the trunk sets the error: the coarser crown costs the mean error little
// (sylva-bench-lowpoly --budget 3000 --fidelity-only shows it) and the crowned trees export
// faster.
double crown_cells(std::size_t budget) {
    if (budget <= kTrunkDetailBudget) return share_cells(budget);
    return share_cells(kTrunkDetailBudget) *
           std::sqrt(
               std::sqrt(static_cast<double>(budget) / static_cast<double>(kTrunkDetailBudget)));
}

}  // namespace

int crown_resolution_for_budget(int resolution, std::size_t budget) {
    // At 800 the crown's 40 cells keep the mean error close to that of finer crowns and of
    // the template's resolution on every template (sylva-bench-lowpoly --fidelity-only), and
    // the crowned trees export faster.
    return budget == 0 ? resolution : capped(resolution, crown_cells(budget));
}

int trunk_resolution_for_budget(const TreeParams& params, std::size_t budget) {
    int resolution = params.trunk_resolution;
    if (budget == 0) return resolution;
    // Below 800 triangles the template's resolution draws detail no budget keeps: the cells
    // grow with the budget's square root (twice as wide at 200), which costs little fidelity
    // against the template's resolution (sylva-bench-lowpoly --budget 200 shows it).
    if (budget < kTrunkDetailBudget)
        resolution = capped(resolution, std::sqrt(static_cast<double>(budget) /
                                                  static_cast<double>(kTrunkDetailBudget)) *
                                            resolution);
    const bool hidden = params.drop_hidden && params.crown_mesh && params.sphere_diameter > 0.0;
    // With the hidden branches left out, these cells keep the mean error about that of the
    // template's resolution.
    if (hidden) resolution = capped(resolution, 1.5 * share_cells(budget));  // 60 at 800
    return resolution;
}

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

// The thinnest branch the full-detail trunk draws (resolvable_cones at the template's own
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
    // groups (trunk_groups): its fields are built once the crown's says which segments it
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
                trunk_pieces(out.skeleton, shown, trunk_cell, joint_blend, options.cancel);
        else
            out.branch_axes =
                branch_axes(out.skeleton, shown, full_detail_radius(out.skeleton, tree.params));
    } else if (prisms) {
        out.branch_axes = branch_axes(out.skeleton, std::vector<std::uint8_t>(segments.size(), 1),
                                      full_detail_radius(out.skeleton, tree.params));
    }
    out.times.push_back({"fields", clock.lap_ms()});
    throw_if_cancelled(options.cancel);
    if (prisms && out.branch_axes.axes.empty())
        throw InputError(
            "the tree has no trunk: the derived word draws no segment with a "
            "width above zero (it needs F, and a width from branch_width or !)");
    if (!prisms && !fields.trunk && fields.trunk_pieces.empty())
        throw InputError(
            "the tree has no trunk: the derived word draws no segment with a "
            "width above zero (it needs F, and a width from branch_width or !)");
    // The trunk, the crown and the leaves are made beside each other: each reads the fields
    // alone, and what one leaves of the cores (the crown's bridges, a mesher's last blocks)
    // the others take. Progress is the trunk's share of what its pieces have done on average
    // plus the crown's of what it has done, reported one at a time so that it only rises;
    // each stage's time is its own, so they overlap.
    // Prisms are drawn, not meshed: the crown's meshing is all the progress there is.
    const float trunk_share = prisms ? 0.0f : mesh_crown ? 0.5f : 1.0f;
    const std::vector<ConeField>& pieces = fields.trunk_pieces;
    const std::size_t trunk_slots = std::max<std::size_t>(pieces.size(), 1);
    std::vector<float> done(trunk_slots + 1, 0.0f);  // each trunk piece's fraction, the crown's
    std::mutex reporting;
    auto meshing_options = [&](std::size_t slot) {
        MeshOptions part = options;
        if (options.progress)
            part.progress = [&, slot](float f) {
                const std::lock_guard<std::mutex> one_at_a_time(reporting);
                done[slot] = f;
                float trunk = 0.0f;
                for (std::size_t k = 0; k < trunk_slots; ++k) trunk += done[k];
                options.progress(trunk_share * trunk / static_cast<float>(trunk_slots) +
                                 (1.0f - trunk_share) * done[trunk_slots]);
            };
        return part;
    };
    double trunk_ms = 0.0, crown_ms = 0.0, leaves_ms = 0.0;
    auto trunk = [&] {
        Stopwatch own;
        if (prisms) {
            out.trunk = branch_prisms(out.branch_axes, options.budget).mesh;
            if (!mesh_crown && options.progress) options.progress(1.0f);
        } else if (game_mesh) {
            // The pieces meshed beside each other too.
            std::vector<Mesh> meshed(pieces.size());
            tbb::parallel_for(std::size_t{0}, pieces.size(), [&](std::size_t k) {
                meshed[k] =
                    mesh_field(pieces[k], trunk_box, p.trunk_resolution, meshing_options(k));
            });
            std::vector<const Mesh*> all;
            for (const Mesh& m : meshed) all.push_back(&m);
            out.trunk = merge_meshes(all);
        } else {
            out.trunk =
                mesh_field(*fields.trunk, trunk_box, p.trunk_resolution, meshing_options(0));
        }
        trunk_ms = own.lap_ms();
    };
    auto crown = [&] {
        if (!mesh_crown) return;
        Stopwatch own;
        MeshOptions crown_options = meshing_options(trunk_slots);
        // Skipping empty space needs a distance bound; the Pasko-Savchenko blend is not one.
        if (!fields.crown->is_distance_bound() && options.mesher != Mesher::Dense)
            crown_options.mesher = Mesher::Dense;
        std::vector<CappedCone> bridges =
            crown_bridge_cones(*fields.crown, options.budget, p, fields.crown_box);
        out.crown_bridges = bridges.size();
        if (bridges.empty()) {
            out.crown =
                mesh_field(*fields.crown, fields.crown_box, p.crown_resolution, crown_options);
        } else {
            const float cell = cell_size(fields.crown_box, p.crown_resolution);
            const ConeField struts(std::move(bridges), kFieldMarginInCells * cell);
            out.crown = mesh_field(BridgedCrown{*fields.crown, struts}, fields.crown_box,
                                   p.crown_resolution, crown_options);
        }
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
    return out;
}

}  // namespace sylva
