#include "marching/vdb_mesher.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Prune.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/geometric.hpp>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/errors.h"
#include "marching/grid.h"
#include "marching/meshing_run.h"

namespace sylva {
namespace {

using detail::MeshingRun;
using Leaf = openvdb::FloatTree::LeafNodeType;
constexpr int kDim = int(Leaf::DIM);  // 8: one sampling block is one OpenVDB leaf

// Progress is split between the phases by their typical share of the run time: sampling
// takes about 80% with a cone cloud (resolutions 64-400), volumeToMesh about 75% with a
// cheap analytic sphere.
constexpr float kSampledFraction = 0.6f;
constexpr float kMeshedFraction = 0.95f;

// Smallest sample magnitude, in cells (see Sampler::away_from_zero).
constexpr double kMinFraction = 0.01;

// What sampling found for one 8^3 block of grid nodes (one OpenVDB leaf).
struct Block {
    std::unique_ptr<Leaf> leaf;  // near the surface: the nodes there sampled
    bool inside = false;         // all nodes deep inside: an inactive -background tile
};

// Samples the field into per-block leaves. Far from the surface a block is decided by its
// centre value alone; near it, by the centres of its eight 4^3 sub-blocks, so only the
// sub-blocks the band passes through are sampled node by node (about 40% fewer evaluations
// than whole blocks for a band of 3 cells, for 8 more per block).
class Sampler {
  public:
    Sampler(const BatchField& field, MeshingRun& run, const Grid& grid, float band,
            float background)
        : field_(field),
          run_(run),
          grid_(grid),
          band_(band),
          background_(background),
          min_magnitude_(float(kMinFraction * grid.h)) {
        for (int a = 0; a < 3; ++a) blocks_[a] = (grid.nodes[a] + kDim - 1) / kDim;
    }

    std::size_t block_count() const { return std::size_t(blocks_[0]) * blocks_[1] * blocks_[2]; }

    openvdb::Coord block_origin(std::size_t b) const {
        const int i = int(b % blocks_[0]);
        const int j = int(b / blocks_[0] % blocks_[1]);
        const int k = int(b / (std::size_t(blocks_[0]) * blocks_[1]));
        return openvdb::Coord(i * kDim, j * kDim, k * kDim);
    }

    // Samples blocks [begin, end) into out[begin, end); the run counts the evaluations.
    void sample(std::size_t begin, std::size_t end, std::vector<Block>& out) const {
        Scratch scratch;
        // All block centres of the range in one batch.
        for (std::size_t b = begin; b < end; ++b) add_centre(block_origin(b), kDim, scratch);
        evaluate(scratch);
        const std::vector<float> centres = scratch.values;

        for (std::size_t b = begin; b < end; ++b) {
            const openvdb::Coord o = block_origin(b);
            switch (verdict(centres[b - begin], o, kDim)) {
                case Verdict::Outside:
                    break;
                case Verdict::Inside:
                    out[b].inside = true;
                    break;
                case Verdict::Sample:
                    sample_block(o, out[b], scratch);
                    break;
            }
        }
    }

  private:
    static constexpr int kSub = kDim / 2;  // sub-block edge, in nodes

    struct Scratch {
        std::vector<glm::vec3> points;
        std::vector<float> values;
    };

    enum class Verdict { Outside, Inside, Sample };

    void add_centre(const openvdb::Coord& o, int size, Scratch& scratch) const {
        const double c = 0.5 * (size - 1);
        scratch.points.emplace_back(grid_.origin + (glm::dvec3(o.x(), o.y(), o.z()) + c) * grid_.h);
    }

    void evaluate(Scratch& scratch) const {
        scratch.values.resize(scratch.points.size());
        run_.evaluate(field_, scratch.points, scratch.values);
    }

    // What the centre value of the cube of size^3 nodes at `o` proves about its nodes.
    Verdict verdict(float centre, const openvdb::Coord& o, int size) const {
        if (beyond_grid(o)) return Verdict::Outside;
        // No node of the cube is farther than this from its centre.
        const double half_diagonal = std::sqrt(3.0) * 0.5 * (size - 1) * grid_.h;
        // The 1-Lipschitz bound puts every node farther than the band from the surface, on
        // the centre's side. An inside cube at the grid border is still sampled: its border
        // nodes count as outside, so the surface is capped there.
        if (!std::isfinite(centre) || std::abs(centre) <= half_diagonal + band_) {
            return Verdict::Sample;
        }
        if (centre > 0.0f) return Verdict::Outside;
        return touches_border(o, size) ? Verdict::Sample : Verdict::Inside;
    }

    bool beyond_grid(const openvdb::Coord& o) const {
        for (int a = 0; a < 3; ++a) {
            if (o[a] >= grid_.nodes[a]) return true;
        }
        return false;
    }

    // Whether the cube holds a border node or the inside neighbour of one.
    bool touches_border(const openvdb::Coord& o, int size) const {
        for (int a = 0; a < 3; ++a) {
            if (o[a] == 0 || o[a] + size >= grid_.nodes[a] - 1) return true;
        }
        return false;
    }

    // The nodes of the cube of size^3 nodes at `o` that lie in the grid, in a fixed order.
    template <typename F>
    void for_each_node(const openvdb::Coord& o, int size, F&& f) const {
        std::array<int, 3> count{};
        for (int a = 0; a < 3; ++a) count[a] = std::min(size, grid_.nodes[a] - o[a]);
        for (int i = 0; i < count[0]; ++i) {
            for (int j = 0; j < count[1]; ++j) {
                for (int k = 0; k < count[2]; ++k) f(o.offsetBy(i, j, k));
            }
        }
    }

    void sample_block(const openvdb::Coord& o, Block& block, Scratch& scratch) const {
        std::array<openvdb::Coord, 8> subs;
        scratch.points.clear();
        for (int s = 0; s < 8; ++s) {
            subs[s] = o.offsetBy((s & 1) * kSub, (s >> 1 & 1) * kSub, (s >> 2 & 1) * kSub);
            add_centre(subs[s], kSub, scratch);
        }
        evaluate(scratch);
        std::array<Verdict, 8> verdicts;
        int outside = 0, inside = 0;
        for (int s = 0; s < 8; ++s) {
            verdicts[s] = verdict(scratch.values[s], subs[s], kSub);
            outside += verdicts[s] == Verdict::Outside;
            inside += verdicts[s] == Verdict::Inside;
        }
        if (outside == 8) return;
        if (inside == 8) {
            block.inside = true;
            return;
        }

        // The sub-blocks near the surface, all in one batch.
        scratch.points.clear();
        for (int s = 0; s < 8; ++s) {
            if (verdicts[s] != Verdict::Sample) continue;
            for_each_node(subs[s], kSub, [&](const openvdb::Coord& ijk) {
                scratch.points.emplace_back(grid_.node(ijk.x(), ijk.y(), ijk.z()));
            });
        }
        evaluate(scratch);

        // Nodes beyond the grid keep the outside background.
        block.leaf = std::make_unique<Leaf>(o, background_, false);
        Leaf& leaf = *block.leaf;
        std::size_t m = 0;
        for (int s = 0; s < 8; ++s) {
            if (verdicts[s] == Verdict::Inside) {
                for_each_node(subs[s], kSub, [&](const openvdb::Coord& ijk) {
                    leaf.setValueOnly(Leaf::coordToOffset(ijk), -background_);
                });
            } else if (verdicts[s] == Verdict::Sample) {
                for_each_node(subs[s], kSub, [&](const openvdb::Coord& ijk) {
                    set_sample(leaf, ijk, scratch.values[m++]);
                });
            }
        }
    }

    void set_sample(Leaf& leaf, const openvdb::Coord& ijk, float v) const {
        const openvdb::Index n = Leaf::coordToOffset(ijk);
        if (std::isnan(v) || v == -std::numeric_limits<float>::infinity() ||
            (is_border(ijk) && v < 0.0f)) {
            // Outside whatever the field says, as in marching_cubes(). Active, so
            // volumeToMesh sees the sign change to a deep inside neighbour that is itself
            // outside the band (it only looks at edges with an active end).
            leaf.setValueOn(n, background_);
        } else if (std::abs(v) < band_) {
            leaf.setValueOn(n, away_from_zero(v));
        } else {
            leaf.setValueOnly(n, v < 0.0f ? -background_ : background_);
        }
    }

    // A node whose value is (nearly) zero pulls every crossing on its edges onto itself, and
    // volumeToMesh then builds triangles of no area around it: the vertices of the cells
    // that meet there all land on the node (seen with cone tips grazing a node). Keeping
    // samples at least 1% of a cell from zero, on their own side (zero is outside, as in
    // marching_cubes()), keeps crossings about 1% of a cell off the nodes; it moves the
    // surface by at most that much.
    float away_from_zero(float v) const {
        if (std::abs(v) >= min_magnitude_) return v;
        return v < 0.0f ? -min_magnitude_ : min_magnitude_;
    }

    bool is_border(const openvdb::Coord& ijk) const {
        for (int a = 0; a < 3; ++a) {
            if (ijk[a] == 0 || ijk[a] == grid_.nodes[a] - 1) return true;
        }
        return false;
    }

    const BatchField& field_;
    MeshingRun& run_;
    const Grid& grid_;
    const float band_;
    const float background_;
    const float min_magnitude_;
    std::array<int, 3> blocks_{};
};

void add_triangle(Mesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    mesh.triangles.push_back({a, b, c});
}

// Adds one of volumeToMesh's polygons (n = 3 or 4 corners) as triangles.
void add_polygon(Mesh& mesh, const std::array<std::uint32_t, 4>& ids, int n) {
    // Read backwards: OpenVDB's polygons are clockwise seen from outside (Houdini's
    // convention: a sphere meshed as is has a negative enclosed volume), Sylva's are
    // counter-clockwise. A repeated corner (never seen from volumeToMesh so far, adaptive or
    // not, but cheap to guard) is dropped; that cannot open the mesh, since each edge lost
    // with it is also used, the other way, by the polygon's neighbours across it, which
    // then pair with each other.
    std::array<std::uint32_t, 4> corners{};
    int kept = 0;
    for (int m = n - 1; m >= 0; --m) {
        if (kept == 0 || corners[kept - 1] != ids[m]) corners[kept++] = ids[m];
    }
    if (kept > 1 && corners[kept - 1] == corners[0]) --kept;
    if (kept == 3) {
        add_triangle(mesh, corners[0], corners[1], corners[2]);
    } else if (kept == 4) {
        const auto& p = mesh.positions;
        if (glm::distance(p[corners[0]], p[corners[2]]) <=
            glm::distance(p[corners[1]], p[corners[3]])) {
            add_triangle(mesh, corners[0], corners[1], corners[2]);
            add_triangle(mesh, corners[0], corners[2], corners[3]);
        } else {
            add_triangle(mesh, corners[1], corners[2], corners[3]);
            add_triangle(mesh, corners[1], corners[3], corners[0]);
        }
    }
}

Mesh to_mesh(const std::vector<openvdb::Vec3s>& points,
             const std::vector<openvdb::Vec3I>& triangles,
             const std::vector<openvdb::Vec4I>& quads) {
    if (points.size() > std::numeric_limits<std::uint32_t>::max()) {
        throw std::length_error("vdb_mesh: more than 2^32 - 1 vertices");
    }
    Mesh mesh;
    mesh.positions.reserve(points.size());
    for (const auto& p : points) mesh.positions.emplace_back(p.x(), p.y(), p.z());
    mesh.triangles.reserve(2 * quads.size() + triangles.size());
    for (const auto& q : quads) add_polygon(mesh, {q[0], q[1], q[2], q[3]}, 4);
    for (const auto& t : triangles) add_polygon(mesh, {t[0], t[1], t[2], 0}, 3);
    return mesh;
}

// Drops vertices no triangle uses (after a collapsed polygon), keeping OpenVDB's order.
void drop_unused_vertices(Mesh& mesh) {
    std::vector<std::uint32_t> remap(mesh.positions.size(), 0);
    for (const auto& t : mesh.triangles) {
        for (std::uint32_t id : t) remap[id] = 1;
    }
    if (std::find(remap.begin(), remap.end(), 0u) == remap.end()) return;
    std::uint32_t kept = 0;
    for (std::size_t v = 0; v < remap.size(); ++v) {
        if (remap[v] == 0) continue;
        mesh.positions[kept] = mesh.positions[v];
        remap[v] = kept++;
    }
    mesh.positions.resize(kept);
    for (auto& t : mesh.triangles) {
        for (auto& id : t) id = remap[id];
    }
}

// Samples, meshes and fills the stats, in the run's arena.
Mesh sample_and_mesh(const BatchField& field, const Grid& grid, const MeshSettings& settings,
                     MeshingRun& run) {
    const VdbSettings& vdb = settings.vdb;
    const float band = float(vdb.band_voxels * grid.h);
    const float background = band;

    // Sampling: blocks are independent and their results land in fixed slots, so the tree
    // built from them does not depend on the schedule.
    const Sampler sampler(field, run, grid, band, background);
    const std::size_t block_count = sampler.block_count();
    std::vector<Block> blocks(block_count);
    constexpr std::size_t kBlocksPerTask = 64;
    run.begin_phase(0.0f, kSampledFraction, block_count);
    run.for_each((block_count + kBlocksPerTask - 1) / kBlocksPerTask, [&](std::size_t task) {
        const std::size_t begin = task * kBlocksPerTask;
        const std::size_t end = std::min(begin + kBlocksPerTask, block_count);
        sampler.sample(begin, end, blocks);
        run.advance(end - begin);
    });

    openvdb::FloatGrid::Ptr level_set = openvdb::FloatGrid::create(background);
    openvdb::math::Transform::Ptr transform =
        openvdb::math::Transform::createLinearTransform(grid.h);
    transform->postTranslate(openvdb::Vec3d(grid.origin.x, grid.origin.y, grid.origin.z));
    level_set->setTransform(transform);
    level_set->setGridClass(openvdb::GRID_LEVEL_SET);
    auto& tree = level_set->tree();
    std::size_t sampled_blocks = 0;
    for (std::size_t b = 0; b < block_count; ++b) {
        if (blocks[b].leaf) {
            tree.addLeaf(blocks[b].leaf.release());
            ++sampled_blocks;
        } else if (blocks[b].inside) {
            tree.addTile(1, sampler.block_origin(b), -background, false);
        }
    }
    blocks = std::vector<Block>();
    // Merges the inside tiles (and leaves with nothing active) into coarser tiles.
    openvdb::tools::pruneLevelSet(tree);
    // volumeToMesh is one unit: it cannot report or poll, so the run does both around it.
    run.begin_phase(kSampledFraction, kMeshedFraction - kSampledFraction, 1);
    run.throw_if_cancelled();

    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    std::vector<openvdb::Vec4I> quads;
    openvdb::tools::volumeToMesh(*level_set, points, triangles, quads, 0.0, vdb.adaptivity);
    level_set.reset();
    run.advance();
    run.throw_if_cancelled();

    Mesh mesh = to_mesh(points, triangles, quads);
    drop_unused_vertices(mesh);
    if (settings.stats) {
        settings.stats->evaluations = run.evaluations();
        settings.stats->blocks_total = block_count;
        settings.stats->blocks_meshed = sampled_blocks;
    }
    return mesh;
}

// vdb_mesh() itself: this file is the module marching/vdb_module.cpp loads.
Mesh vdb_mesh_here(const BatchField& field, const Box& box, const MeshSettings& settings) {
    const Grid grid = make_grid(box, settings);
    const VdbSettings& vdb = settings.vdb;
    if (!(vdb.adaptivity >= 0.0 && vdb.adaptivity <= 1.0)) {
        throw InputError("vdb_mesh: adaptivity must be in [0, 1], got " +
                         std::to_string(vdb.adaptivity));
    }
    if (!(vdb.band_voxels >= 1.0f && std::isfinite(vdb.band_voxels))) {
        throw InputError("vdb_mesh: band_voxels must be at least 1, got " +
                         std::to_string(vdb.band_voxels));
    }
    static std::once_flag initialized;
    std::call_once(initialized, [] { openvdb::initialize(); });

    // The arena also bounds OpenVDB's own parallel loops to settings.threads.
    MeshingRun run(settings, false);
    run.throw_if_cancelled();
    Mesh mesh = run.execute([&] { return sample_and_mesh(field, grid, settings, run); });
    run.finish();
    return mesh;
}

}  // namespace
}  // namespace sylva

extern "C" __attribute__((visibility("default"))) sylva::VdbMeshFunction sylva_vdb_mesh_entry() {
    return sylva::vdb_mesh_here;
}
