#include "tree/trunk_pieces.h"

#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <glm/geometric.hpp>
#include <iterator>

#include "lowpoly/decimate.h"
#include "tree/field_grid.h"

namespace sylva {
namespace {

// A trunk without a joint blend, a hard union (the min is exact however the fold starts), is
// exact within 2 cells, still more than marching cubes interpolates along a cell's edge: its
// bins are smaller and list fewer cones, so it meshes faster into the same bytes. With a
// joint blend, values near the surface blend with where the fold starts (the mesh would
// change), so it keeps kFieldMarginInCells.
constexpr float kHardUnionMarginInCells = 2.0f;

// One capped cone per segment with a width, its radii raised to kMinRadiusInCells cells.
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

// The surface shares of the groups before the rest (trunk_pieces in the header).
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

}  // namespace

std::optional<ConeField> trunk_field(std::span<const Segment> segments, float cell,
                                     float joint_blend, CancelFlag cancel) {
    std::vector<CappedCone> cones = resolvable_cones(segments, cell);
    if (cones.empty()) return std::nullopt;
    return std::optional<ConeField>(
        std::in_place, std::move(cones),
        (joint_blend > 0.0f ? kFieldMarginInCells : kHardUnionMarginInCells) * cell + joint_blend,
        joint_blend, cancel);
}

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

}  // namespace sylva
