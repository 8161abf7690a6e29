#include "tree/lowpoly_tree.h"

#include <oneapi/tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <optional>
#include <utility>

#include "core/mesh_checks.h"
#include "lowpoly/handle_cutting.h"
#include "lowpoly/inner_shells.h"
#include "lowpoly/merge_meshes.h"
#include "lowpoly/piece_scaling.h"
#include "lowpoly/surface_sampling.h"
#include "lowpoly/triangle_bvh.h"
#include "tree/crown_bridges.h"
#include "tree/crown_hulls.h"
#include "tree/leaf_cards.h"
#include "tree/leaf_thinning.h"
#include "tree/leaf_triangles.h"
#include "tree/sparse_crown.h"

namespace sylva {
namespace {

// The trunk + crown triangles of `budget`: its total, or the parts' sum.
std::size_t solid_budget(const TreeBudget& budget) {
    return budget.trunk || budget.crown ? budget.trunk.value_or(0) + budget.crown.value_or(0)
                                        : budget.total;
}

void append_note(std::string& notes, const std::string& part, const std::string& note) {
    if (note.empty()) return;
    if (!notes.empty()) notes += "; ";
    notes += part.empty() ? note : part + ": " + note;
}

// One part to its budget; 0 keeps every triangle, as `--budget 0` does for the whole tree.
DecimateResult reduce_part(const Mesh& part, std::size_t budget, const DecimateSettings& settings) {
    if (budget == 0) {
        DecimateResult kept;
        kept.parts = {part};
        kept.triangles = part.triangles.size();
        kept.within_budget = true;
        return kept;
    }
    DecimateSettings s = settings;
    s.max_triangles = budget;
    return decimate(part, s);
}

// Trunk and crown reduced to their own budgets.
ReducedTree reduce_parts(const Mesh& trunk, const Mesh& crown, std::size_t trunk_budget,
                         std::size_t crown_budget, const DecimateSettings& settings) {
    DecimateResult t = reduce_part(trunk, trunk_budget, settings);
    DecimateResult c = reduce_part(crown, crown_budget, settings);
    ReducedTree out;
    out.trunk = std::move(t.parts[0]);
    out.crown = std::move(c.parts[0]);
    out.within_budget = t.within_budget && c.within_budget;
    out.backoffs = t.backoffs + c.backoffs;
    out.handles_cut = t.handles_cut + c.handles_cut;
    out.crossing_pairs = t.crossing_pairs + c.crossing_pairs;
    append_note(out.note, "trunk", t.note);
    append_note(out.note, "crown", c.note);
    return out;
}

// Trunk and crown to the budget (leaves untouched).
ReducedTree reduce_solids(const Mesh& trunk, const Mesh& crown, const TreeBudget& budget,
                          const DecimateSettings& settings) {
    ReducedTree out;
    if (budget.total == 0 && !budget.trunk && !budget.crown) {  // only the leaves budgeted
        out.trunk = trunk;
        out.crown = crown;
    } else if (budget.trunk || budget.crown) {
        const std::size_t trunk_budget =
            budget.trunk ? *budget.trunk : budget.total - std::min(budget.total, *budget.crown);
        const std::size_t crown_budget =
            budget.crown ? *budget.crown : budget.total - std::min(budget.total, *budget.trunk);
        out = reduce_parts(trunk, crown, trunk_budget, crown_budget, settings);
    } else {
        DecimateSettings s = settings;
        s.max_triangles = budget.total;
        // The shared budget follows the quadric error, which at small budgets would starve a
        // part down to a token (a four-triangle trunk beside a 90-triangle crown): each part
        // that has more keeps at least a quarter of the budget.
        s.part_floor = budget.total / 4;
        const Mesh* parts[] = {&trunk, &crown};
        DecimateResult r = decimate(parts, s);
        out.trunk = std::move(r.parts[0]);
        out.crown = std::move(r.parts[1]);
        out.within_budget = r.within_budget;
        out.backoffs = r.backoffs;
        out.handles_cut = r.handles_cut;
        out.crossing_pairs = r.crossing_pairs;
        out.note = r.note;
    }
    out.triangles = out.trunk.triangles.size() + out.crown.triangles.size();
    return out;
}

// The larger of the two one-sided distances between a mesh and `source` (2,000 samples each
// way): a reduced crown's Hausdorff distance from the crown it was made from. The source's
// nearest-triangle tree and samples are made once for every candidate measured against it.
class SampledHausdorff {
  public:
    explicit SampledHausdorff(const Mesh& source)
        : near_source_(source), source_samples_(sample_surface(source, kSamples)) {}

    float operator()(const Mesh& mesh) const {
        const TriangleBvh near_mesh(mesh);
        float far2 = 0.0f;  // squared; a sample nearer than the farthest so far is not searched
        for (const glm::vec3& p : sample_surface(mesh, kSamples))
            far2 = std::max(far2, near_source_.distance_squared_beyond(p, far2));
        for (const glm::vec3& p : source_samples_)
            far2 = std::max(far2, near_mesh.distance_squared_beyond(p, far2));
        return std::sqrt(far2);
    }

  private:
    static constexpr std::size_t kSamples = 2000;
    TriangleBvh near_source_;
    std::vector<glm::vec3> source_samples_;
};

// A reduced crown piece grows by at most this linear factor (an octahedron inscribed in a
// ball needs 1.35 to show the ball's mean outline).
constexpr float kMostPieceGrowth = 2.0f;

// A crown reduced alone (its branches drawn as prisms) to fewer triangles than this is
// drawn as hulls in the automatic mode even without handles.
constexpr std::size_t kTinyCrownBudget = 100;

// Trunk and crown to the budget, the crown drawn as crown_hull_count() says. In the
// automatic mode only a crown with handles (genus above 0) becomes hulls: where blobs touch in
// rings the reduction must keep each tunnel (a dozen triangles) or cut it, and spends the budget on
// spikes and slabs; a crown of sphere-like pieces (a conifer's cone) reads better as its
// own surface reduced (measured with sylva-bench-lowpoly: the blobs won on exactly the
// templates whose crown has no handle). The shared reduction runs on the hulls (they need
// fewer triangles than the blobs; the trunk's branches get the rest); then half as many
// hulls again, reduced alone to the same triangles, replace them when they keep closer to
// the crown (a sampled Hausdorff distance): a long hedge wants more hulls than an
// umbrella. Hulls are a few hundred triangles, so that costs little.
// `hull_source` is the crown the hulls are made of and measured against: the crown itself,
// or in a LOD chain the finest level's (a coarser level's crown, already hulls, has as many
// pieces as the level before kept, more than a smaller budget can draw).
// `hull_count` is crown_hull_count(budget) unless the caller counts the lumps on a larger
// budget (a prism trunk's tree counts them on the whole tree's, not on the crown's rest).
// `grow_pieces`: a crown reduced as itself (no hulls) has its pieces grown back to the area
// they had (not a crown of bridged blobs).
ReducedTree reduce_shaped(const Mesh& trunk, const Mesh& crown, const Mesh& hull_source,
                          const TreeBudget& budget, const DecimateSettings& settings,
                          bool grow_pieces, std::optional<std::size_t> lumps = std::nullopt) {
    const std::size_t hull_count = lumps.value_or(crown_hull_count(budget));
    // Clusters split where the crown parts (crown_hulls) add up to half as many hulls again
    // while the hulls are few; past kMostHullsToSplit the clusters are small enough that few
    // bridge a gap, and a split-off piece's small hull, reduced, folds (a spruce at 3000).
    constexpr std::size_t kMostHullsToSplit = 32;
    const std::size_t hull_pieces =
        hull_count <= kMostHullsToSplit ? hull_count * 3 / 2 : hull_count;
    const bool only_with_handles =
        crown_shape_info(budget.crown_shape.value_or(CrownShape::Automatic)).hulls ==
        CrownHulls::WithHandles;
    // Blobs reduced to very few triangles fold into spikes as surely as blobs with handles.
    const bool tiny = solid_budget(budget) < kTinyCrownBudget && trunk.triangles.empty();
    if (hull_count == 0 || (only_with_handles && !tiny && genus(hull_source) == 0)) {
        ReducedTree out = reduce_solids(trunk, crown, budget, settings);
        // Blobs reduced to a few triangles each are inscribed polyhedra showing little more
        // than half their outline: grown back to the area of `hull_source`'s (the finest
        // crown, so a LOD level does not grow on the level before's growth;
        // lowpoly/piece_scaling.h). Not bridged blobs: grown, their struts would fill more
        // of the gaps between them.
        if (grow_pieces) restore_piece_areas(out.crown, hull_source, kMostPieceGrowth);
        return out;
    }
    // From kCrownHullBudget on the budget draws the hulls well, and half as many again kept
    // no closer: they alone.
    if (solid_budget(budget) >= kCrownHullBudget)
        return reduce_solids(trunk, crown_hulls(hull_source, hull_count, hull_pieces), budget,
                             settings);
    // Half as many hulls again and the source's samples are made on one core while the
    // other makes the hulls and starts their reduction.
    Mesh hulls, more_hulls;
    std::optional<SampledHausdorff> from_source;
    ReducedTree out;
    tbb::parallel_invoke(
        [&] {
            hulls = crown_hulls(hull_source, hull_count, hull_pieces);
            out = reduce_solids(trunk, hulls, budget, settings);
        },
        [&] {
            more_hulls = crown_hulls(hull_source, hull_count * 3 / 2, hull_count * 3 / 2);
            from_source.emplace(hull_source);
        });
    if (out.crown.triangles.empty() || more_hulls.triangles.size() <= hulls.triangles.size())
        return out;
    DecimateSettings alone = settings;
    alone.progress = nullptr;
    alone.max_triangles = out.crown.triangles.size();
    DecimateResult more = decimate(more_hulls, alone);
    if (!more.within_budget || more.crossing_pairs > 0) return out;
    float more_far = 0.0f, out_far = 0.0f;  // measured on a core each
    tbb::parallel_invoke([&] { more_far = (*from_source)(more.parts[0]); },
                         [&] { out_far = (*from_source)(out.crown); });
    if (more_far < out_far) {
        out.crown = std::move(more.parts[0]);
        out.triangles = out.trunk.triangles.size() + out.crown.triangles.size();
    }
    return out;
}

// The trunk's share of `total` triangles when its branches are prisms: all of it without a
// crown, else in proportion to the branches' side area against the crown's surface, between a
// quarter and three quarters (the crown and the branches each need some to read at all).
std::size_t prism_allowance(const Tree& tree, std::size_t total) {
    if (tree.crown.triangles.empty()) return total;
    double branches = 0.0;
    for (const BranchAxis& axis : tree.branch_axes.axes)
        branches += 0.5 * std::numbers::pi * axis.area;  // pi (r0 + r1) L, a cone's side
    const double share =
        std::clamp(branches / std::max(branches + surface_area(tree.crown), 1e-12), 0.25, 0.75);
    return static_cast<std::size_t>(std::lround(share * static_cast<double>(total)));
}

// A sparse crown (tree/sparse_crown.h) whose rest of the budget gives each piece fewer than
// this many triangles is drawn as polyhedra, not reduced: a reduction of many tiny blobs
// at once gives some a tetrahedron and others a dozen triangles.
constexpr std::size_t kMostPolyhedronTriangles = 12;

// The trunk's share of `total` triangles beside a sparse crown of `pieces` pieces: what the
// crown's polyhedra leave (octahedra, else bipyramids, else tetrahedra) where that still draws
// every branch (fewest_prism_triangles()), else `allowance`: a sparse crown's tufts are a
// fair part of its outline, and without its branches such a tree does not read at all.
std::size_t sparse_crown_allowance(const Tree& tree, std::size_t total, std::size_t pieces,
                                   std::size_t allowance) {
    const std::size_t fewest = fewest_prism_triangles(tree.branch_axes, total);
    for (const std::size_t each : {8, 6, 4})
        if (total >= pieces * each + fewest) return total - pieces * each;
    return allowance;
}

// A tree whose branches are prisms (Tree::branch_axes): as many branches as the trunk's
// share of the budget buys (at most `most_branch_triangles`, a LOD level's trunk at most
// the level before's), the crown reduced alone to the rest, drawn as `budget` says; a sparse
// crown with few triangles a piece as polyhedra, beside every branch drawn coarse before
// any is refined (PrismOrder::EveryAxisFirst).
ReducedTree reduce_with_prisms(const Tree& tree, const Mesh& crown, const Mesh& hull_source,
                               const TreeBudget& budget, const DecimateSettings& settings,
                               std::size_t most_branch_triangles) {
    const std::size_t total = solid_budget(budget);
    if (total == 0) {  // no reduction: every branch the tree has, the crown as it is
        ReducedTree out;
        out.trunk = tree.trunk;
        out.crown = crown;
        out.triangles = out.trunk.triangles.size() + out.crown.triangles.size();
        return out;
    }
    // A crown is sparse only unbridged and where the budget keeps its blobs apart
    // (crown_bridges.h); below, it is drawn as its hulls or bridged slabs.
    const std::size_t pieces = tree.crown_bridges == 0 && keeps_sparse_crown_apart(total)
                                   ? sparse_crown_pieces(hull_source)
                                   : 0;
    const bool sparse = pieces > 0;
    std::size_t allowance = budget.trunk ? *budget.trunk : prism_allowance(tree, total);
    if (sparse && !budget.trunk && !budget.crown)
        allowance = sparse_crown_allowance(tree, total, pieces, allowance);
    BranchPrisms prisms =
        branch_prisms(tree.branch_axes, total, std::min(allowance, most_branch_triangles),
                      sparse ? PrismOrder::EveryAxisFirst : PrismOrder::LargestFirst);
    TreeBudget rest = budget;
    rest.trunk = rest.crown = std::nullopt;
    const std::size_t drawn = prisms.mesh.triangles.size();
    rest.total = budget.crown ? *budget.crown : (total > drawn + 4 ? total - drawn : 4);
    // The lumps are counted on the whole budget (one per lump_triangles of it, as without
    // prisms), not on the crown's rest: half the lumps, each twice as large, bridge the gaps
    // between tiers and curtains the crown's outline shows (a willow at 800 kept 0.85 of its
    // silhouette with them, 0.87 with these).
    const std::size_t lumps = crown_hull_count(rest) > 0 ? crown_hull_count(budget) : 0;
    ReducedTree out;
    if (sparse && rest.total < pieces * kMostPolyhedronTriangles)
        out.crown = sparse_crown_polyhedra(hull_source, rest.total);
    else
        out = reduce_shaped(Mesh{}, crown, hull_source, rest, settings, tree.crown_bridges == 0,
                            lumps);
    out.trunk = std::move(prisms.mesh);
    out.triangles = out.trunk.triangles.size() + out.crown.triangles.size();
    out.within_budget = out.within_budget && out.triangles <= total;
    return out;
}

// The budget with its crown shape decided: its own, else the tree's (its template's).
TreeBudget shaped_for(TreeBudget budget, const Tree& tree) {
    budget.crown_shape = budget.crown_shape.value_or(tree.crown_shape);
    budget.lump_triangles = budget.lump_triangles.value_or(tree.crown_lump_triangles);
    return budget;
}

// The tree's trunk and crown without inner shells: hollows are invisible and only cost
// triangles (lowpoly/inner_shells.h). A part without any (most) is the tree's own, not a
// copy; the tree must outlive this.
class SolidsToReduce {
  public:
    explicit SolidsToReduce(const Tree& tree) : trunk_(&tree.trunk), crown_(&tree.crown) {
        tbb::parallel_invoke([&] { own_trunk_ = without_inner_shells(tree.trunk); },
                             [&] { own_crown_ = without_inner_shells(tree.crown); });
        if (own_trunk_) trunk_ = &*own_trunk_;
        if (own_crown_) crown_ = &*own_crown_;
    }
    SolidsToReduce(const SolidsToReduce&) = delete;
    SolidsToReduce& operator=(const SolidsToReduce&) = delete;

    const Mesh& trunk() const { return *trunk_; }
    const Mesh& crown() const { return *crown_; }

  private:
    std::optional<Mesh> own_trunk_, own_crown_;  // made only for a part with inner shells
    const Mesh* trunk_;
    const Mesh* crown_;
};

float lowest_y(const Mesh& mesh) {
    float y = std::numeric_limits<float>::max();
    for (const glm::vec3& p : mesh.positions) y = std::min(y, p.y);
    return y;
}

// Moves the trunk's lowest point to `ground` by stretching (or squeezing) its bottom: a
// vertex at the lowest point moves the whole way, one `span` above it not at all, linearly
// in between. The span is at least twice the move, so heights keep their order and no
// triangle folds over.
void pin_to_ground(Mesh& trunk, float ground) {
    if (trunk.positions.empty()) return;
    const float low = lowest_y(trunk);
    const float move = ground - low;
    if (std::abs(move) < 1e-5f) return;
    float high = low;
    for (const glm::vec3& p : trunk.positions) high = std::max(high, p.y);
    const float span = std::max(2.0f * std::abs(move), 0.1f * (high - low));
    for (glm::vec3& p : trunk.positions)
        if (p.y < low + span) p.y += move * (1.0f - (p.y - low) / span);
    // The lowest vertices land exactly on the ground, whatever the rounding.
    for (glm::vec3& p : trunk.positions)
        if (p.y < ground) p.y = ground;
}

// The settings with the trunk's foot (DecimateSettings::foot_height): what lies within half
// a percent of the trunk's height above its lowest point, the base it stands on.
DecimateSettings with_foot(DecimateSettings settings, const Mesh& trunk) {
    if (trunk.positions.empty()) return settings;
    float high = std::numeric_limits<float>::lowest();
    for (const glm::vec3& p : trunk.positions) high = std::max(high, p.y);
    const float ground = lowest_y(trunk);
    settings.foot_height = ground + 0.005f * (high - ground);
    return settings;
}

}  // namespace

Mesh game_leaves(const Tree& tree, std::size_t budget) {
    const bool textured = tree.leaf_style == LeafStyle::Textured;
    if (tree.leaves.triangles.size() <= budget && !textured) return tree.leaves;
    switch (tree.leaf_style) {
        case LeafStyle::None:
            return {};
        case LeafStyle::Leaves:
            return thin_leaves(tree.leaves, budget);
        case LeafStyle::Cards:
            if (leaves_fit_as_triangles(tree.leaves, budget))
                return leaf_triangles(tree.leaves, budget);
            break;
        case LeafStyle::Textured:
            break;
    }
    LeafCardSettings cards;
    cards.max_triangles = budget;
    cards.crown = &tree.crown;
    return leaf_cards(tree.leaves, cards);
}

std::size_t leaf_budget(const TreeBudget& budget) {
    if (budget.leaves) return *budget.leaves;
    return budget.total > 0 ? budget.total : std::numeric_limits<std::size_t>::max();
}

std::size_t crown_hull_count(const TreeBudget& budget) {
    const std::size_t total = solid_budget(budget);
    const CrownHulls rule =
        crown_shape_info(budget.crown_shape.value_or(CrownShape::Automatic)).hulls;
    if (rule == CrownHulls::Never || (rule == CrownHulls::WithHandles && total == 0)) return 0;
    const std::size_t per =
        std::max<std::size_t>(1, budget.lump_triangles.value_or(kTrianglesPerHull));
    return std::max<std::size_t>(1, (total > 0 ? total : kCrownHullBudget) / per);
}

ReducedTree reduce_tree(const Tree& tree, const TreeBudget& budget,
                        const DecimateSettings& settings) {
    const SolidsToReduce solids(tree);
    ReducedTree out =
        tree.branch_axes.axes.empty()
            ? reduce_shaped(solids.trunk(), solids.crown(), solids.crown(),
                            shaped_for(budget, tree), with_foot(settings, tree.trunk),
                            tree.crown_bridges == 0)
            : reduce_with_prisms(tree, solids.crown(), solids.crown(), shaped_for(budget, tree),
                                 settings, std::numeric_limits<std::size_t>::max());
    pin_to_ground(out.trunk, lowest_y(tree.trunk));
    out.leaves = game_leaves(tree, leaf_budget(budget));
    return out;
}

std::vector<std::size_t> lod_budgets(std::size_t finest, std::size_t levels) {
    std::vector<std::size_t> budgets;
    for (std::size_t i = 0; i < levels; ++i)
        budgets.push_back(std::max<std::size_t>(finest >> i, 4));
    return budgets;
}

std::vector<TreeBudget> lod_budgets(const TreeBudget& finest, std::size_t levels) {
    std::vector<TreeBudget> budgets;
    const std::size_t leaves = leaf_budget(finest);
    for (std::size_t i = 0; i < levels; ++i) {
        TreeBudget b;
        b.total = std::max<std::size_t>(finest.total >> i, 4);
        b.leaves = i < 64 ? leaves >> i : 0;  // SIZE_MAX (every leaf) halves like a number
        b.crown_shape = finest.crown_shape;
        b.lump_triangles = finest.lump_triangles;
        budgets.push_back(b);
    }
    return budgets;
}

std::vector<ReducedTree> make_lod_chain(const Tree& tree, std::span<const TreeBudget> budgets,
                                        const DecimateSettings& settings,
                                        std::optional<ReducedTree> level0) {
    std::vector<ReducedTree> levels;
    if (level0 && !budgets.empty()) levels.push_back(std::move(*level0));
    const float ground = lowest_y(tree.trunk);
    const SolidsToReduce finest(tree);
    for (const TreeBudget& budget : budgets.subspan(levels.size())) {
        const Mesh& trunk = levels.empty() ? finest.trunk() : levels.back().trunk;
        const Mesh& crown = levels.empty() ? finest.crown() : levels.back().crown;
        ReducedTree level =
            tree.branch_axes.axes.empty()
                ? reduce_shaped(trunk, crown, finest.crown(), shaped_for(budget, tree),
                                with_foot(settings, tree.trunk), tree.crown_bridges == 0)
                : reduce_with_prisms(tree, crown, finest.crown(), shaped_for(budget, tree),
                                     settings, trunk.triangles.size());
        // A reduction only removes triangles, but cutting a handle caps it with new ones.
        if (level.trunk.triangles.size() > trunk.triangles.size()) level.trunk = trunk;
        if (level.crown.triangles.size() > crown.triangles.size()) level.crown = crown;
        level.triangles = level.trunk.triangles.size() + level.crown.triangles.size();
        pin_to_ground(level.trunk, ground);
        level.leaves = game_leaves(tree, leaf_budget(budget));
        levels.push_back(std::move(level));
    }
    return levels;
}

Mesh reference_surface(const TreeTemplate& tree, int resolution, const MeshOptions& options) {
    TreeTemplate fine = tree;
    fine.params.trunk_resolution = resolution;
    fine.params.crown_resolution = resolution;
    const Tree t = generate_tree(fine, options);
    const Mesh* parts[] = {&t.trunk, &t.crown};
    return merge_meshes(parts);
}

Fidelity measure_tree_fidelity(const Mesh& trunk, const Mesh& crown, const Mesh& reference,
                               const FidelitySettings& settings) {
    const Mesh* parts[] = {&trunk, &crown};
    return measure_fidelity(merge_meshes(parts), reference, settings);
}

Fidelity measure_tree_loss(const Mesh& trunk, const Mesh& crown, const Mesh& reference,
                           double height) {
    const Mesh* parts[] = {&trunk, &crown};
    FidelitySettings settings;
    settings.height = height;
    return measure_fidelity(reference, merge_meshes(parts), settings);
}

}  // namespace sylva
