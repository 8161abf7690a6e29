// Dense marching cubes: every grid node is evaluated, exactly once, one slab of blocks at a
// time, and every block is meshed. The cube logic lives in cube_table.cpp, the block meshing
// and stitching shared with the sparse mesher in block_mesher.cpp.
#include "marching/marching_cubes.h"

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "marching/block_mesher.h"
#include "marching/grid.h"
#include "marching/meshing_run.h"

namespace sylva {
namespace {

using detail::BlockGrid;
using detail::BlockScratch;
using detail::ChunkMesh;
using detail::kBlockCells;
using detail::MeshingRun;

// Rows of nodes per evaluation batch: batches of a few thousand points amortise the call
// and keep the points in cache.
constexpr std::size_t kBatchPoints = 4096;

Mesh mesh_dense(const BatchField& field, const Box& box, const MeshSettings& settings,
                bool serial) {
    const BlockGrid g(make_grid(box, settings));
    MeshingRun run(settings, serial);
    run.throw_if_cancelled();
    Mesh mesh = run.execute([&] {
        const int nx = g.grid.nodes[0], ny = g.grid.nodes[1];
        const std::size_t layer = std::size_t(nx) * std::size_t(ny);
        // The node layers of one slab of blocks; its top layer is the next slab's bottom,
        // carried over so that no node is evaluated twice.
        std::vector<float> slab((kBlockCells + 1) * layer);
        std::vector<ChunkMesh> chunks(std::size_t(g.blocks[1]) * std::size_t(g.blocks[2]));
        tbb::enumerable_thread_specific<BlockScratch> scratches;
        const std::size_t rows_per_batch = std::max<std::size_t>(1, kBatchPoints / nx);

        run.begin_phase(0.0f, 0.97f, std::size_t(g.blocks[2]) * 2);
        for (int bz = 0; bz < g.blocks[2]; ++bz) {
            const int z0 = bz * kBlockCells;
            const int layers = std::min(kBlockCells, g.cells[2] - z0) + 1;
            const int first = bz == 0 ? 0 : 1;
            if (bz > 0)
                std::memcpy(slab.data(), slab.data() + kBlockCells * layer, layer * sizeof(float));

            // Rows (layer, y) are contiguous in the slab, so a run of them is one batch.
            const std::size_t row_begin = std::size_t(first) * ny;
            const std::size_t rows = std::size_t(layers) * ny - row_begin;
            run.for_each((rows + rows_per_batch - 1) / rows_per_batch, [&](std::size_t batch) {
                BlockScratch& s = scratches.local();
                const std::size_t r0 = row_begin + batch * rows_per_batch;
                const std::size_t r1 = std::min(r0 + rows_per_batch, row_begin + rows);
                s.points.clear();
                for (std::size_t r = r0; r < r1; ++r) {
                    const int k = z0 + int(r / ny), j = int(r % ny);
                    for (int i = 0; i < nx; ++i) s.points.push_back(g.node(i, j, k));
                }
                float* values = slab.data() + r0 * nx;
                run.evaluate(field, s.points, std::span<float>(values, s.points.size()));
                for (std::size_t r = r0; r < r1; ++r) {
                    const int k = z0 + int(r / ny), j = int(r % ny);
                    float* row = values + (r - r0) * nx;
                    for (int i = 0; i < nx; ++i) {
                        row[i] = detail::usable_sample(row[i], g.border_node(i, j, k));
                    }
                }
            });
            run.advance();

            // One chunk per row of blocks: chunks then follow block order.
            run.for_each(std::size_t(g.blocks[1]), [&](std::size_t by) {
                BlockScratch& s = scratches.local();
                ChunkMesh& chunk = chunks[std::size_t(bz) * g.blocks[1] + by];
                chunk.first_block = g.block_id({0, int(by), bz});
                chunk.end_block = chunk.first_block + g.blocks[0];
                const std::size_t y0 = by * kBlockCells;
                for (int bx = 0; bx < g.blocks[0]; ++bx) {
                    const float* values = slab.data() + y0 * nx + std::size_t(bx) * kBlockCells;
                    detail::mesh_block(g, {bx, int(by), bz}, values, nx, std::ptrdiff_t(layer),
                                       detail::kAllCells, s, chunk);
                }
            });
            run.advance();
        }
        run.begin_phase(0.97f, 0.03f, 1);
        return detail::assemble(chunks, run);
    });
    if (settings.stats) {
        settings.stats->evaluations = run.evaluations();
        settings.stats->blocks_total = g.block_count();
        settings.stats->blocks_meshed = g.block_count();
    }
    run.finish();
    return mesh;
}

}  // namespace

Mesh marching_cubes(const BatchField& field, const Box& box, const MeshSettings& settings) {
    return mesh_dense(field, box, settings, false);
}

Mesh marching_cubes(const ScalarField& field, const Box& box, const MeshSettings& settings) {
    const BatchField batch = [&field](std::span<const glm::vec3> points, std::span<float> values) {
        for (std::size_t i = 0; i < points.size(); ++i) values[i] = field(points[i]);
    };
    return mesh_dense(batch, box, settings, true);
}

}  // namespace sylva
