// Sparse marching cubes: the dense mesher's blocks and output, but space the distance bound
// proves empty is never sampled. Ranges of cells are refined coarse to fine, 32 -> 8 -> 4 -> 2
// cells a side, each evaluated once at its centre; a range whose centre value exceeds its
// half-diagonal holds no sign change and is dropped. The 8-cell blocks left are the meshing
// units; in them, only the nodes of surviving 2-cell cubes are evaluated.
//
// Phases, each parallel over runs of blocks: find the candidate blocks; find each one's
// surviving cubes; evaluate the needed nodes, each by the one block that owns it (the same
// half-open rule as for edge vertices), in one batch per block; mesh each block, taking the
// nodes on its upper faces from their owners. So a node is evaluated once (unless its owner
// was skipped as empty: then each block that needs it evaluates it), and no block waits
// for another within a phase.
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <glm/geometric.hpp>
#include <span>
#include <vector>

#include "marching/block_mesher.h"
#include "marching/grid.h"
#include "marching/marching_cubes.h"
#include "marching/meshing_run.h"

namespace sylva {
namespace {

using detail::BlockGrid;
using detail::BlockScratch;
using detail::CellRange;
using detail::ChunkMesh;
using detail::kBlockCells;
using detail::kBlockNodes;
using detail::kSubBlockCells;
using detail::kSubBlocksPerSide;
using detail::MeshingRun;

// Coarse ranges of 4^3 blocks: a true distance field skips most of the empty box there
// with one evaluation per 32^3 cells. A field clamped at a margin below their half-diagonal
// (27.7 cells) gains nothing from them and loses one evaluation per 32^3 cells.
constexpr int kCoarseCells = 4 * kBlockCells;
// Blocks meshed by one task, and stitched as one chunk.
constexpr std::size_t kBlocksPerChunk = 8;

// Node marks while a block is sampled.
constexpr std::uint8_t kUnknown = 0;
constexpr std::uint8_t kWanted = 1;  // needed by a surviving cube, to be evaluated
constexpr std::uint8_t kKnown = 2;   // value in hand: a range's centre, or evaluated

// A range of cells the bound could not prove empty, with the field at its centre.
struct Candidate {
    CellRange cells;
    float value = 0.0f;
};

// Scratch of one thread: the levels of refinement and the evaluation buffers.
struct SparseScratch {
    BlockScratch block;
    std::vector<Candidate> parents;
    std::vector<Candidate> children;
};

// Evaluates s.points into s.values.
void evaluate(const BatchField& field, MeshingRun& run, BlockScratch& s) {
    s.values.resize(s.points.size());
    run.evaluate(field, s.points, s.values);
}

// Replaces `out` by the children of side `size` cells of every range in `parents` that the
// bound cannot prove empty. A child is first tested with its parent's value (the parent's
// centre is a known distance away), and only then evaluated at its own centre, all children
// in one batch. Ranges must start at multiples of `size`.
void refine(const BlockGrid& g, const BatchField& field, MeshingRun& run,
            std::span<const Candidate> parents, int size, BlockScratch& s,
            std::vector<Candidate>& out) {
    out.clear();
    s.points.clear();
    for (const Candidate& parent : parents) {
        const glm::vec3 parent_centre = g.centre(parent.cells);
        const CellRange& p = parent.cells;
        for (int k = p.lo[2]; k < p.hi[2]; k += size) {
            for (int j = p.lo[1]; j < p.hi[1]; j += size) {
                for (int i = p.lo[0]; i < p.hi[0]; i += size) {
                    Candidate child;
                    child.cells.lo = {i, j, k};
                    child.cells.hi = {std::min(i + size, p.hi[0]), std::min(j + size, p.hi[1]),
                                      std::min(k + size, p.hi[2])};
                    const glm::vec3 centre = g.centre(child.cells);
                    const double offset =
                        glm::length(glm::dvec3(centre) - glm::dvec3(parent_centre));
                    if (g.proven_empty(child.cells, parent.value, offset)) continue;
                    out.push_back(child);
                    s.points.push_back(centre);
                }
            }
        }
    }
    evaluate(field, run, s);
    std::size_t kept = 0;
    for (std::size_t c = 0; c < out.size(); ++c) {
        if (g.proven_empty(out[c].cells, s.values[c])) continue;
        out[kept] = out[c];
        out[kept++].value = s.values[c];
    }
    out.resize(kept);
}

constexpr std::size_t kBlockNodeCount = std::size_t(kBlockNodes) * kBlockNodes * kBlockNodes;

constexpr std::size_t local_node(int i, int j, int k) {
    return std::size_t(i) + kBlockNodes * (std::size_t(j) + kBlockNodes * std::size_t(k));
}

// The candidate blocks, sorted by id, and per block what the phases hand on: its mask of
// surviving 2-cell cubes, its node values and their marks (kBlockNodes^3 each, x fastest).
struct SparseBlocks {
    static constexpr std::size_t kNone = std::size_t(-1);

    std::vector<std::pair<std::uint64_t, Candidate>> blocks;
    std::vector<std::uint64_t> masks;
    std::vector<float> values;
    std::vector<std::uint8_t> marks;

    float* values_of(std::size_t i) { return values.data() + i * kBlockNodeCount; }
    std::uint8_t* marks_of(std::size_t i) { return marks.data() + i * kBlockNodeCount; }

    // The candidate at block coordinates b, or kNone (also outside the grid).
    std::size_t index_of(const BlockGrid& g, const std::array<int, 3>& b) const {
        for (int a = 0; a < 3; ++a) {
            if (b[a] < 0 || b[a] >= g.blocks[a]) return kNone;
        }
        const std::uint64_t id = g.block_id(b);
        const auto it = std::lower_bound(blocks.begin(), blocks.end(), id,
                                         [](const std::pair<std::uint64_t, Candidate>& c,
                                            std::uint64_t v) { return c.first < v; });
        return it != blocks.end() && it->first == id ? std::size_t(it - blocks.begin()) : kNone;
    }
};

// Calls f(i, j, k) for the local nodes of the cubes set in `mask` of a block of `size`
// cells, nodes shared by two cubes once per cube. On an axis where only[a] >= 0, only the
// nodes at that coordinate.
template <class F>
void for_masked_nodes(const std::array<int, 3>& size, std::uint64_t mask,
                      const std::array<int, 3>& only, F&& f) {
    for (int b = 0; b < 64; ++b) {
        if (!(mask >> b & 1u)) continue;
        const std::array<int, 3> cube{b % kSubBlocksPerSide,
                                      b / kSubBlocksPerSide % kSubBlocksPerSide,
                                      b / (kSubBlocksPerSide * kSubBlocksPerSide)};
        std::array<int, 3> lo{}, hi{};
        bool empty = false;
        for (int a = 0; a < 3; ++a) {
            lo[a] = cube[a] * kSubBlockCells;
            hi[a] = std::min(lo[a] + kSubBlockCells, size[a]);
            if (only[a] >= 0) {
                empty |= only[a] < lo[a] || only[a] > hi[a];
                lo[a] = hi[a] = only[a];
            }
        }
        if (empty) continue;
        for (int k = lo[2]; k <= hi[2]; ++k) {
            for (int j = lo[1]; j <= hi[1]; ++j) {
                for (int i = lo[0]; i <= hi[0]; ++i) f(i, j, k);
            }
        }
    }
}

std::array<int, 3> size_of(const CellRange& r) {
    return {r.hi[0] - r.lo[0], r.hi[1] - r.lo[1], r.hi[2] - r.lo[2]};
}

// The axes along which local node (i, j, k) of a block lies on the block's upper face and
// so belongs to the next block (bit a); 0 when the block owns it. The last block of an
// axis owns its upper face: there is no next block.
unsigned foreign_axes(const BlockGrid& g, const CellRange& r, int i, int j, int k) {
    const std::array<int, 3> local{i, j, k};
    unsigned axes = 0;
    for (int a = 0; a < 3; ++a) {
        if (local[a] == r.hi[a] - r.lo[a] && r.hi[a] < g.cells[a]) axes |= 1u << a;
    }
    return axes;
}

std::array<int, 3> step(const std::array<int, 3>& b, unsigned axes, int sign) {
    return {b[0] + sign * int(axes & 1u), b[1] + sign * int(axes >> 1 & 1u),
            b[2] + sign * int(axes >> 2 & 1u)};
}

// The candidates one step up (sign +1) or down (-1) along each set of axes (index = axis
// bits; entry 0 is block i itself), looked up once per block rather than once per node.
std::array<std::size_t, 8> neighbours(const BlockGrid& g, const SparseBlocks& sb, std::size_t i,
                                      int sign) {
    const std::array<int, 3> b = g.block_coords(sb.blocks[i].first);
    std::array<std::size_t, 8> out{};
    out[0] = i;
    for (unsigned axes = 1; axes < 8; ++axes) out[axes] = sb.index_of(g, step(b, axes, sign));
    return out;
}

// A range whose sides are an even number of cells is centred on a grid node, and its centre
// was computed exactly as that node is (origin + index * h, in double, rounded once), so
// its value is the node's: kept in the block's node values and marked as known.
void keep_centre_value(const CellRange& block, const Candidate& c, float* values,
                       std::uint8_t* marks) {
    std::array<int, 3> twice{};
    for (int a = 0; a < 3; ++a) {
        twice[a] = c.cells.lo[a] + c.cells.hi[a] - 2 * block.lo[a];
        if (twice[a] % 2 != 0) return;
    }
    const std::size_t n = local_node(twice[0] / 2, twice[1] / 2, twice[2] / 2);
    // Never a border node: a range's centre lies strictly inside it.
    values[n] = detail::usable_sample(c.value, false);
    marks[n] = kKnown;
}

// Phase 2: the cells of block i worth meshing, as a mask of 2-cell cubes (see mesh_block),
// or 0. Resets the block's marks and keeps the centre values it evaluates.
void find_surviving_cells(const BlockGrid& g, const BatchField& field, MeshingRun& run,
                          SparseBlocks& sb, std::size_t i, SparseScratch& s) {
    const Candidate& block = sb.blocks[i].second;
    float* values = sb.values_of(i);
    std::uint8_t* marks = sb.marks_of(i);
    std::fill(marks, marks + kBlockNodeCount, kUnknown);
    keep_centre_value(block.cells, block, values, marks);
    s.parents.assign(1, block);
    refine(g, field, run, s.parents, 2 * kSubBlockCells, s.block, s.children);
    for (const Candidate& c : s.children) keep_centre_value(block.cells, c, values, marks);
    std::swap(s.parents, s.children);
    refine(g, field, run, s.parents, kSubBlockCells, s.block, s.children);
    std::uint64_t mask = 0;
    for (const Candidate& c : s.children) {
        keep_centre_value(block.cells, c, values, marks);
        const int sx = (c.cells.lo[0] - block.cells.lo[0]) / kSubBlockCells;
        const int sy = (c.cells.lo[1] - block.cells.lo[1]) / kSubBlockCells;
        const int sz = (c.cells.lo[2] - block.cells.lo[2]) / kSubBlockCells;
        mask |= std::uint64_t(1) << (sx + kSubBlocksPerSide * (sy + kSubBlocksPerSide * sz));
    }
    sb.masks[i] = mask;
}

// Phase 3: evaluates, in one batch, the nodes block i owns that it or the blocks below it
// need, plus the nodes it needs whose owner is not a candidate (skipped as empty: it will
// not evaluate them). Writes only block i's values and marks.
void sample_owned_nodes(const BlockGrid& g, const BatchField& field, MeshingRun& run,
                        SparseBlocks& sb, std::size_t i, BlockScratch& s) {
    const CellRange& r = sb.blocks[i].second.cells;
    const std::array<int, 3> size = size_of(r);
    std::uint8_t* marks = sb.marks_of(i);
    const auto want = [&](int x, int y, int z) {
        std::uint8_t& mark = marks[local_node(x, y, z)];
        if (mark == kUnknown) mark = kWanted;
    };
    if (const std::uint64_t mask = sb.masks[i]) {
        const std::array<std::size_t, 8> above = neighbours(g, sb, i, +1);
        for_masked_nodes(size, mask, {-1, -1, -1}, [&](int x, int y, int z) {
            const unsigned axes = foreign_axes(g, r, x, y, z);
            if (axes == 0 || above[axes] == SparseBlocks::kNone) want(x, y, z);
        });
    }
    // A block below along the axes in `axes` needs the nodes of its upper faces; those on
    // this block's lower faces and inside its owned range are this block's to evaluate.
    const std::array<std::size_t, 8> below = neighbours(g, sb, i, -1);
    for (unsigned axes = 1; axes < 8; ++axes) {
        const std::size_t n = below[axes];
        if (n == SparseBlocks::kNone || sb.masks[n] == 0) continue;
        const CellRange& lower = sb.blocks[n].second.cells;
        std::array<int, 3> only{-1, -1, -1};
        for (int a = 0; a < 3; ++a) {
            if (axes >> a & 1u) only[a] = kBlockCells;  // the block below is full there
        }
        for_masked_nodes(size_of(lower), sb.masks[n], only, [&](int x, int y, int z) {
            const std::array<int, 3> here{x - int(axes & 1u) * kBlockCells,
                                          y - int(axes >> 1 & 1u) * kBlockCells,
                                          z - int(axes >> 2 & 1u) * kBlockCells};
            if (foreign_axes(g, r, here[0], here[1], here[2]) == 0) want(here[0], here[1], here[2]);
        });
    }

    s.points.clear();
    for (int z = 0; z <= size[2]; ++z) {
        for (int y = 0; y <= size[1]; ++y) {
            for (int x = 0; x <= size[0]; ++x) {
                if (marks[local_node(x, y, z)] == kWanted) {
                    s.points.push_back(g.node(r.lo[0] + x, r.lo[1] + y, r.lo[2] + z));
                }
            }
        }
    }
    evaluate(field, run, s);
    float* values = sb.values_of(i);
    std::size_t next = 0;
    for (int z = 0; z <= size[2]; ++z) {
        for (int y = 0; y <= size[1]; ++y) {
            for (int x = 0; x <= size[0]; ++x) {
                std::uint8_t& mark = marks[local_node(x, y, z)];
                if (mark != kWanted) continue;
                const bool border = g.border_node(r.lo[0] + x, r.lo[1] + y, r.lo[2] + z);
                values[local_node(x, y, z)] = detail::usable_sample(s.values[next++], border);
                mark = kKnown;
            }
        }
    }
}

// Phase 4, first step: copies into block i the values of its upper-face nodes that other
// blocks own. Writes only block i's upper faces, which no other block reads.
void fetch_foreign_nodes(const BlockGrid& g, SparseBlocks& sb, std::size_t i) {
    const CellRange& r = sb.blocks[i].second.cells;
    float* values = sb.values_of(i);
    const std::array<std::size_t, 8> above = neighbours(g, sb, i, +1);
    for_masked_nodes(size_of(r), sb.masks[i], {-1, -1, -1}, [&](int x, int y, int z) {
        const unsigned axes = foreign_axes(g, r, x, y, z);
        if (axes == 0) return;
        const std::size_t owner = above[axes];
        if (owner == SparseBlocks::kNone) return;  // evaluated here in phase 3
        const std::size_t there =
            local_node(x - int(axes & 1u) * kBlockCells, y - int(axes >> 1 & 1u) * kBlockCells,
                       z - int(axes >> 2 & 1u) * kBlockCells);
        assert(sb.marks_of(owner)[there] == kKnown);
        values[local_node(x, y, z)] = sb.values_of(owner)[there];
    });
}

// Blocks of 8^3 cells not proven empty, in block order, found row by row of coarse ranges.
std::vector<std::pair<std::uint64_t, Candidate>> candidate_blocks(
    const BlockGrid& g, const BatchField& field, MeshingRun& run,
    tbb::enumerable_thread_specific<SparseScratch>& scratches) {
    const int coarse_y = (g.cells[1] + kCoarseCells - 1) / kCoarseCells;
    const int coarse_z = (g.cells[2] + kCoarseCells - 1) / kCoarseCells;
    std::vector<std::vector<std::pair<std::uint64_t, Candidate>>> rows(std::size_t(coarse_y) *
                                                                       coarse_z);
    run.begin_phase(0.0f, 0.1f, rows.size());
    run.for_each(rows.size(), [&](std::size_t row) {
        SparseScratch& s = scratches.local();
        // The whole row as a parent with no value: every coarse range in it is evaluated.
        Candidate whole;
        whole.cells.lo = {0, int(row % coarse_y) * kCoarseCells,
                          int(row / coarse_y) * kCoarseCells};
        whole.cells.hi = {g.cells[0], std::min(whole.cells.lo[1] + kCoarseCells, g.cells[1]),
                          std::min(whole.cells.lo[2] + kCoarseCells, g.cells[2])};
        whole.value = std::nanf("");
        s.parents.assign(1, whole);
        refine(g, field, run, s.parents, kCoarseCells, s.block, s.children);
        std::swap(s.parents, s.children);
        refine(g, field, run, s.parents, kBlockCells, s.block, s.children);
        for (const Candidate& c : s.children) {
            const std::array<int, 3> b{c.cells.lo[0] / kBlockCells, c.cells.lo[1] / kBlockCells,
                                       c.cells.lo[2] / kBlockCells};
            rows[row].emplace_back(g.block_id(b), c);
        }
        run.advance();
    });
    std::vector<std::pair<std::uint64_t, Candidate>> blocks;
    for (const auto& row : rows) blocks.insert(blocks.end(), row.begin(), row.end());
    // Block ids are unique, so the order is total and the same on every run.
    tbb::parallel_sort(blocks.begin(), blocks.end(),
                       [](const auto& a, const auto& b) { return a.first < b.first; });
    return blocks;
}

}  // namespace

Mesh sparse_marching_cubes(const BatchField& field, const Box& box, const MeshSettings& settings) {
    const BlockGrid g(make_grid(box, settings));
    MeshingRun run(settings, false);
    run.throw_if_cancelled();
    std::size_t meshed = 0;
    Mesh mesh = run.execute([&] {
        tbb::enumerable_thread_specific<SparseScratch> scratches;
        SparseBlocks sb;
        sb.blocks = candidate_blocks(g, field, run, scratches);
        const std::size_t count = sb.blocks.size();
        sb.masks.assign(count, 0);
        sb.values.resize(count * kBlockNodeCount);
        sb.marks.resize(count * kBlockNodeCount);

        // Every phase runs over the same runs of consecutive blocks; each run is one chunk
        // of the output.
        const std::size_t chunk_count = (count + kBlocksPerChunk - 1) / kBlocksPerChunk;
        const auto for_each_block = [&](float start, float weight, auto&& per_block) {
            run.begin_phase(start, weight, chunk_count);
            run.for_each(chunk_count, [&](std::size_t c) {
                const std::size_t end = std::min((c + 1) * kBlocksPerChunk, count);
                for (std::size_t i = c * kBlocksPerChunk; i < end; ++i) per_block(c, i);
                run.advance();
            });
        };
        for_each_block(0.1f, 0.2f, [&](std::size_t, std::size_t i) {
            find_surviving_cells(g, field, run, sb, i, scratches.local());
        });
        for_each_block(0.3f, 0.6f, [&](std::size_t, std::size_t i) {
            sample_owned_nodes(g, field, run, sb, i, scratches.local().block);
        });
        std::vector<ChunkMesh> chunks(chunk_count);
        for_each_block(0.9f, 0.07f, [&](std::size_t c, std::size_t i) {
            ChunkMesh& chunk = chunks[c];
            if (i == c * kBlocksPerChunk) chunk.first_block = sb.blocks[i].first;
            chunk.end_block = sb.blocks[i].first + 1;
            if (sb.masks[i] == 0) return;
            fetch_foreign_nodes(g, sb, i);
            detail::mesh_block(g, g.block_coords(sb.blocks[i].first), sb.values_of(i), kBlockNodes,
                               std::ptrdiff_t(kBlockNodes) * kBlockNodes, sb.masks[i],
                               scratches.local().block, chunk);
        });
        meshed = std::size_t(std::count_if(sb.masks.begin(), sb.masks.end(),
                                           [](std::uint64_t m) { return m != 0; }));
        // The node values are spent; free them before the output is put together.
        sb = SparseBlocks{};
        run.begin_phase(0.97f, 0.03f, 1);
        return detail::assemble(chunks, run);
    });
    if (settings.stats) {
        settings.stats->evaluations = run.evaluations();
        settings.stats->blocks_total = g.block_count();
        settings.stats->blocks_meshed = meshed;
    }
    run.finish();
    return mesh;
}

}  // namespace sylva
