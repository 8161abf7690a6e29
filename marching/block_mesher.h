// Marching cubes one block of cells at a time, and the stitching of blocks into one mesh.
//
// The dense and the sparse mesher both cut the grid into the same blocks of kBlockCells^3
// cells and mesh them with mesh_block(); they differ only in how they obtain the node
// values. The output is put together in block order, and each crossed edge's vertex belongs
// to one block fixed by geometry alone, so the mesh is the same bytes whichever thread
// meshed which block, however blocks were grouped, and whichever mesher skipped which
// empty block.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <utility>
#include <vector>

#include "marching/grid.h"
#include "marching/meshing_run.h"

namespace sylva::detail {

constexpr int kBlockCells = 8;
constexpr int kBlockNodes = kBlockCells + 1;
// Sparse meshing proves empty space in cubes of this many cells, down to this size: the
// cells of a block are marked in a 4 x 4 x 4 bit mask of such cubes.
constexpr int kSubBlockCells = 2;
constexpr int kSubBlocksPerSide = kBlockCells / kSubBlockCells;
static_assert(kSubBlocksPerSide * kSubBlocksPerSide * kSubBlocksPerSide == 64);
constexpr std::uint64_t kAllCells = ~std::uint64_t(0);

// Cells [lo, hi) on each axis, so nodes [lo, hi].
struct CellRange {
    std::array<int, 3> lo{};
    std::array<int, 3> hi{};
};

// The grid with its cut into blocks (the last block on an axis may be smaller).
struct BlockGrid {
    Grid grid;
    std::array<int, 3> cells{};
    std::array<int, 3> blocks{};
    // What float rounding may add to a field value, whatever the point (see proven_empty).
    double rounding_slack = 0.0;

    explicit BlockGrid(const Grid& g);

    std::uint64_t block_count() const {
        return std::uint64_t(blocks[0]) * std::uint64_t(blocks[1]) * std::uint64_t(blocks[2]);
    }
    // Block ids run x fastest, then y, then z: the order of the output.
    std::uint64_t block_id(const std::array<int, 3>& b) const {
        return std::uint64_t(b[0]) +
               std::uint64_t(blocks[0]) * (std::uint64_t(b[1]) + std::uint64_t(blocks[1]) * b[2]);
    }
    std::array<int, 3> block_coords(std::uint64_t id) const {
        const std::uint64_t plane = std::uint64_t(blocks[0]) * std::uint64_t(blocks[1]);
        return {int(id % blocks[0]), int(id % plane / blocks[0]), int(id / plane)};
    }
    CellRange block_cells(const std::array<int, 3>& b) const;

    // Where node (i, j, k) is sampled. Every mesher computes it this way, in double and
    // rounded once, so a node shared by two blocks gets the same point and the same value.
    glm::vec3 node(int i, int j, int k) const { return glm::vec3(grid.node(i, j, k)); }

    bool border_node(int i, int j, int k) const {
        return i == 0 || j == 0 || k == 0 || i == cells[0] || j == cells[1] || k == cells[2];
    }
    // Whether the range holds a node of the outermost layer, which counts as outside.
    bool touches_border(const CellRange& r) const;

    glm::vec3 centre(const CellRange& r) const;
    // Whether no grid node of the closed range can differ in sign from the others, given
    // the field value `value` at a point at most `offset` from the range's centre: the field
    // is 1-Lipschitz, so every node lies within half the range's diagonal plus `offset` of
    // that point. A margin covers float rounding. A range that touches the border is never
    // proven empty by an inside value: its border nodes count as outside.
    bool proven_empty(const CellRange& r, float value, double offset = 0.0) const;
};

// The value a mesher stores for a node: NaN (outside, no usable value) when the field is
// not finite there, or when the node is on the border and the field is negative; the
// border layer is always outside so the mesh closes even where the field does not.
float usable_sample(float value, bool border);

// The output of a run of consecutive blocks, before stitching. Each crossed edge's vertex
// belongs to the block holding the edge's lower end when node coordinates round down to
// blocks (half-open blocks, the last one closed); blocks across its other faces refer to it.
struct ChunkMesh {
    static constexpr std::uint32_t kForeign = 0x80000000u;

    // The blocks [first_block, end_block) this chunk covers (some may have been skipped).
    std::uint64_t first_block = 0;
    std::uint64_t end_block = 0;
    // Vertices this chunk owns, in creation order: the final order.
    std::vector<glm::vec3> positions;
    // Vertex refs: an index into positions, or kForeign | an index into the foreign_ lists.
    std::vector<std::array<std::uint32_t, 3>> triangles;
    // Edges whose vertex belongs to another block: edge key, owner block, position.
    std::vector<std::uint64_t> foreign_keys;
    std::vector<std::uint64_t> foreign_owners;
    std::vector<glm::vec3> foreign_positions;
    // Owned vertices on a block's lower faces, which later blocks refer to: (edge key,
    // index into positions).
    std::vector<std::pair<std::uint64_t, std::uint32_t>> shared;
};

// Per-thread buffers, reused from block to block.
struct BlockScratch {
    BlockScratch();
    // Vertex ref per (local node, axis) edge slot of the block being meshed, or kNoVertex.
    std::vector<std::uint32_t> edge_refs;
    std::vector<std::uint32_t> touched;
    // A batch of points to evaluate and their values, for the meshers' own use.
    std::vector<glm::vec3> points;
    std::vector<float> values;
};

// Meshes the cells of block b that lie in a sub-block whose bit is set in `mask` (bit
// sx + 4 * (sy + 4 * sz) for the sub-block of local cells 2 sx .. 2 sx + 1, ...), appending
// to `out`. values[i + j * sy + k * sz] is the usable sample of the block's local node
// (i, j, k); only the nodes of the masked cells are read.
void mesh_block(const BlockGrid& g, const std::array<int, 3>& b, const float* values,
                std::ptrdiff_t sy, std::ptrdiff_t sz, std::uint64_t mask, BlockScratch& scratch,
                ChunkMesh& out);

// Stitches the chunks, which must be sorted by block and not overlap, into one mesh: the
// chunks' vertices and triangles one after another, refs to other blocks' vertices
// resolved. A vertex whose owner block produced none (only when the field broke the
// distance bound the sparse mesher relies on) is kept where it was referred to.
// Throws std::length_error past 2^32 - 1 vertices.
Mesh assemble(std::vector<ChunkMesh>& chunks, MeshingRun& run);

}  // namespace sylva::detail
