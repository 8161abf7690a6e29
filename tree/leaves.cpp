#include "tree/leaves.h"

#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <numbers>
#include <vector>

#include "core/random.h"
#include "lowpoly/merge_meshes.h"

namespace sylva {

const std::vector<glm::vec2>& leaf_outline(LeafShape shape) {
    static const std::vector<glm::vec2> round = {{0, 0}, {0.5f, -0.35f}, {1, 0}, {0.5f, 0.35f}};
    static const std::vector<glm::vec2> needle = {{0, 0}, {0.5f, -0.05f}, {1, 0}, {0.5f, 0.05f}};
    // Three rounded lobes a side.
    static const std::vector<glm::vec2> oak = {
        {0, 0},         {0.15f, -0.12f}, {0.25f, -0.08f}, {0.38f, -0.22f},
        {0.5f, -0.12f}, {0.62f, -0.24f}, {0.75f, -0.1f},  {0.88f, -0.14f},
        {1, 0},         {0.88f, 0.14f},  {0.75f, 0.1f},   {0.62f, 0.24f},
        {0.5f, 0.12f},  {0.38f, 0.22f},  {0.25f, 0.08f},  {0.15f, 0.12f}};
    // A long blade cut into leaflets.
    static const std::vector<glm::vec2> frond = {
        {0, 0},         {0.2f, -0.16f},  {0.3f, -0.04f}, {0.45f, -0.18f}, {0.55f, -0.04f},
        {0.7f, -0.15f}, {0.78f, -0.03f}, {1, 0},         {0.78f, 0.03f},  {0.7f, 0.15f},
        {0.55f, 0.04f}, {0.45f, 0.18f},  {0.3f, 0.04f},  {0.2f, 0.16f}};
    switch (shape) {
        case LeafShape::Oak:
            return oak;
        case LeafShape::Needle:
            return needle;
        case LeafShape::Frond:
            return frond;
        case LeafShape::Round:
            break;
    }
    return round;
}

namespace {

// Appends one leaf: the outline fanned from its centre, facing one way only. The base
// (outline[0]) comes first, the centre last, so a leaf's first vertex is its base.
void add_leaf(Mesh& mesh, const std::vector<glm::vec2>& outline, const glm::vec3& base,
              const glm::vec3& along, const glm::vec3& across, float length) {
    const auto ring = static_cast<std::uint32_t>(mesh.positions.size());
    for (const glm::vec2& p : outline)
        mesh.positions.push_back(base + (along * p.x + across * p.y) * length);
    const auto n = static_cast<std::uint32_t>(outline.size());
    if (n == 4) {  // Heuer's (2022) quad: two triangles, no centre
        mesh.triangles.push_back({ring, ring + 1, ring + 2});
        mesh.triangles.push_back({ring, ring + 2, ring + 3});
        return;
    }
    const auto centre = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.push_back(base + along * (0.5f * length));
    for (std::uint32_t i = 0; i < n; ++i)
        mesh.triangles.push_back({centre, ring + i, ring + (i + 1) % n});
}

}  // namespace

void add_polygon_leaves(Mesh& leaves, const std::vector<std::vector<glm::vec3>>& polygons) {
    for (const auto& polygon : polygons) {
        if (polygon.size() < 3) continue;
        const auto first = static_cast<std::uint32_t>(leaves.positions.size());
        leaves.positions.insert(leaves.positions.end(), polygon.begin(), polygon.end());
        for (std::uint32_t i = 1; i + 1 < polygon.size(); ++i)
            leaves.triangles.push_back({first, first + i, first + i + 1});
    }
}

Mesh scatter_leaves(const std::function<float(const glm::vec3&)>& inside, const Box& box,
                    const LeafSettings& settings) {
    if (!(settings.density > 0.0) || !(settings.size > 0.0)) return {};
    glm::vec3 extent = box.max - box.min;
    double volume = double(extent.x) * extent.y * extent.z;
    if (!(volume > 0.0)) return {};
    // One candidate point per grid cell; the box's volume bounds the crown's, so a grid of
    // at most max_leaves cells keeps the count below the cap.
    double cell_volume = std::max(1.0 / settings.density, volume / double(settings.max_leaves));
    float spacing = static_cast<float>(std::cbrt(cell_volume));
    // Rounding up, and the one-cell minimum of a flat or needle-thin box, can multiply the
    // count far past the cap (a box 1e10 m long and 0.1 m wide): widen the spacing until the
    // grid itself has at most max_leaves cells.
    const double max_cells = double(std::max<std::size_t>(settings.max_leaves, 1));
    glm::vec3 cells_f;
    for (;;) {
        cells_f = glm::max(glm::ceil(extent / spacing), glm::vec3(1.0f));
        const double count = double(cells_f.x) * cells_f.y * cells_f.z;
        if (count <= max_cells) break;
        spacing *= static_cast<float>(std::max(1.01, std::cbrt(count / max_cells)));
    }
    const glm::ivec3 cells(cells_f);

    // Slabs of kBlock grid slices on a core each (the crown's field is the cost), each cell
    // with the random numbers it would draw in one pass over the grid: the same leaves in the
    // same order whatever the thread count. A block of kBlock^3 cells whose centre lies farther
    // outside than its half-diagonal holds no leaf when `inside` is 1-Lipschitz (a distance
    // bound): one sample instead of 8 where no leaf can be (blocks of 4 cells a side reach
    // too far for the crown's field, which is only exact near its surface).
    const std::vector<glm::vec2>& outline = leaf_outline(settings.shape);
    constexpr std::size_t kDrawsPerCell = 7;
    constexpr int kBlock = 2;
    const glm::ivec3 blocks = (cells + (kBlock - 1)) / kBlock;
    std::vector<Mesh> slabs(static_cast<std::size_t>(blocks.z));
    tbb::parallel_for(0, blocks.z, [&](int slab) {
        const int k0 = slab * kBlock, k1 = std::min(cells.z, k0 + kBlock);
        std::vector<char> may_hold(static_cast<std::size_t>(blocks.x) * blocks.y, 1);
        if (settings.inside_is_distance_bound)
            for (int bj = 0; bj < blocks.y; ++bj)
                for (int bi = 0; bi < blocks.x; ++bi) {
                    const glm::vec3 lo(bi * kBlock, bj * kBlock, k0);
                    const glm::vec3 hi(std::min(cells.x, (bi + 1) * kBlock),
                                       std::min(cells.y, (bj + 1) * kBlock), k1);
                    const float reach = 0.5f * glm::length(hi - lo) * spacing;
                    // The relative part guards the bound against the field's own rounding.
                    may_hold[static_cast<std::size_t>(bj) * blocks.x + bi] =
                        !(inside(box.min + 0.5f * (lo + hi) * spacing) > reach * 1.001f);
                }
        Mesh& out = slabs[static_cast<std::size_t>(slab)];
        for (int k = k0; k < k1; ++k)
            for (int j = 0; j < cells.y; ++j) {
                if (is_cancelled(settings.cancel)) return;
                for (int i = 0; i < cells.x; ++i) {
                    if (!may_hold[static_cast<std::size_t>(j / kBlock) * blocks.x + i / kBlock])
                        continue;
                    Random random(settings.seed ^ 0x1eaf5eedULL);
                    const auto cell = (static_cast<std::uint64_t>(k) * cells.y + j) * cells.x + i;
                    random.discard(kDrawsPerCell * cell);
                    std::array<double, kDrawsPerCell> u;
                    for (double& x : u) x = random.uniform();
                    // z, y, x: the order GCC drew them in when they were three uniform() calls
                    // as the vector's arguments (kept: the same seed keeps its leaves).
                    glm::vec3 jitter(u[2], u[1], u[0]);
                    double yaw = u[3] * 2.0 * std::numbers::pi;
                    double tilt = (u[4] - 0.5) * std::numbers::pi * 0.6;  // +-54 degrees
                    double roll = (u[5] - 0.5) * std::numbers::pi * 0.5;
                    float scale = static_cast<float>(0.8 + 0.4 * u[6]);
                    glm::vec3 p = box.min + (glm::vec3(i, j, k) + jitter) * spacing;
                    if (!(inside(p) < 0.0f)) continue;
                    glm::vec3 along(std::cos(yaw) * std::cos(tilt), std::sin(tilt),
                                    std::sin(yaw) * std::cos(tilt));
                    glm::vec3 side = glm::normalize(glm::cross(glm::vec3(0, 1, 0), along));
                    glm::vec3 normal = glm::cross(along, side);
                    glm::vec3 across =
                        side * float(std::cos(roll)) + normal * float(std::sin(roll));
                    add_leaf(out, outline, p, along, across,
                             static_cast<float>(settings.size) * scale);
                }
            }
    });
    throw_if_cancelled(settings.cancel);
    std::vector<const Mesh*> parts;
    for (const Mesh& slab : slabs) parts.push_back(&slab);
    return merge_meshes(parts);
}

}  // namespace sylva
