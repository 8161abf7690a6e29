#include "colonization/colonization_cost.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace sylva {
namespace {

// Fitted with sylva-bench-colonization --cost (thread CPU time): a grid visit is a random
// read of a point or node and a distance, slower once the points outgrow the caches (7 ns
// at 100,000 points, 10-14 at a million); a scan reads arrays in order.
constexpr double kSecondsPerVisit = 7.0e-9;
constexpr double kSecondsPerVisitPerMillionPoints = 5.0e-9;
constexpr double kSecondsPerScan = 1.5e-9;
// A point: its position (the caller's and the run's copy), nearest node, distance, flags
// and grid entry; a node: itself, its grid entry and the per-pass arrays; a grid cell: an
// empty vector.
constexpr double kBytesPerPoint = 48.0;
constexpr double kBytesPerNode = 100.0;
constexpr double kBytesPerCell = 24.0;
// Nodes stay half a step apart (crowding), and a grown crown holds about this many per
// step^3 of its padded box; a branch kills the points within d_k of it, so a crown that
// uses up its points needs about this many nodes per pi d_k^2 D of it.
constexpr double kNodesPerStepCubed = 1.5;
constexpr double kNodesPerKillTube = 1.5;
// The growth front moves a step per pass; the crown is filled after about twice its
// extent in steps.
constexpr double kPassesPerExtentStep = 2.0;
constexpr double kMaxGridCells = 2e6;  // CellGrid's cap

double grid_cells(const glm::dvec3& extent, double cell) {
    const double volume_cells = (extent.x / cell) * (extent.y / cell) * (extent.z / cell);
    if (volume_cells > kMaxGridCells) cell *= std::cbrt(volume_cells / kMaxGridCells);
    return std::ceil(extent.x / cell) * std::ceil(extent.y / cell) * std::ceil(extent.z / cell);
}

// Bytes of a run with `nodes` nodes: what the points, the nodes and both grids hold.
double run_bytes(double points, double nodes, const glm::dvec3& extent, double radius) {
    const glm::dvec3 grid = extent + glm::dvec3(2.0 * radius);  // padded by d_i
    const double cells =
        grid_cells(grid, std::max(0.5 * radius, 1e-6)) + grid_cells(grid, std::max(radius, 1e-6));
    return kBytesPerPoint * points + kBytesPerNode * nodes + kBytesPerCell * cells;
}

double seconds(double visits, double scans, double points) {
    const double per_visit =
        kSecondsPerVisit + kSecondsPerVisitPerMillionPoints * std::min(1.0, points / 1e6);
    return per_visit * visits + kSecondsPerScan * scans;
}

glm::dvec3 extent_of(const Box& bounds) {
    return glm::max(glm::dvec3(bounds.max) - glm::dvec3(bounds.min), glm::dvec3(1e-3));
}

}  // namespace

ColonizationCost estimate_colonization_cost(const Box& bounds, std::size_t count, int roots,
                                            const ColonizationSettings& s) {
    ColonizationCost cost;
    const double points = static_cast<double>(count);
    const glm::dvec3 extent = extent_of(bounds);
    const double step = std::max(static_cast<double>(s.step_size), 1e-6);
    const double kill = std::max(static_cast<double>(s.kill_distance), 1e-6);
    const double radius = std::max(static_cast<double>(s.influence_radius), kill);
    const double max_passes = std::max(1.0, static_cast<double>(s.max_iterations));
    const double longest = std::max({extent.x, extent.y, extent.z});
    cost.iterations = std::min(max_passes, kPassesPerExtentStep * longest / step +
                                               (s.max_no_grow > 0 ? 2.0 * s.max_no_grow : 0.0));
    // Where nodes can be: the box and a step around it, as far as the passes reach.
    const double farthest = cost.iterations * step * (s.weighted_growth ? 2.0 : 1.0);
    const glm::dvec3 reach = glm::min(extent, glm::dvec3(2.0 * farthest)) + glm::dvec3(2.0 * step);
    const double volume = reach.x * reach.y * reach.z;
    const double packed = kNodesPerStepCubed * volume / (step * step * step);
    const double tubes = kNodesPerKillTube * volume / (3.14159265358979 * kill * kill * step);
    // Each pass grows at most one node per point.
    const double grown = std::min({packed, tubes, max_passes * points});
    const double trunk =
        std::max(1, roots) *
        (std::max(static_cast<double>(s.trunk_height), static_cast<double>(bounds.min.y)) / step +
         1.0);
    cost.nodes = grown + trunk;
    // A query looks at the cells (d_i / 2 wide) of a cube 2 d_i across: that share of the
    // points along each axis.
    const glm::dvec3 grid = extent + glm::dvec3(2.0 * radius);
    const double cell = std::max(0.5 * radius, std::cbrt(grid.x * grid.y * grid.z / kMaxGridCells));
    const double query = 2.0 * radius + cell;
    const double share = std::min(1.0, query / extent.x) * std::min(1.0, query / extent.y) *
                         std::min(1.0, query / extent.z);
    cost.visits = grown * points * share;
    cost.scans = cost.iterations * (points + 2.0 * cost.nodes) + std::max(1, roots) * points;
    // max_no_grow: a node that stalls hands its points on (a pass over the points near it,
    // and for each of its own a look at the nodes near that), about once per max_no_grow
    // passes.
    if (s.max_no_grow > 0) {
        const double releases = grown * cost.iterations / static_cast<double>(s.max_no_grow);
        cost.scans += 2.0 * releases * points * share;
    }
    cost.seconds = seconds(cost.visits, cost.scans, points);
    cost.bytes = run_bytes(points, cost.nodes, extent, radius);
    return cost;
}

ColonizationCost colonization_cost(const ColonizationWork& work, std::size_t points,
                                   const Box& bounds, const ColonizationSettings& s) {
    ColonizationCost cost;
    cost.nodes = static_cast<double>(work.nodes);
    cost.iterations = work.iterations;
    cost.scans = static_cast<double>(work.scans);
    cost.visits = static_cast<double>(work.visits);
    cost.seconds = seconds(cost.visits, cost.scans, static_cast<double>(points));
    cost.bytes = run_bytes(static_cast<double>(points), cost.nodes, extent_of(bounds),
                           std::max(s.influence_radius, s.kill_distance));
    return cost;
}

}  // namespace sylva
