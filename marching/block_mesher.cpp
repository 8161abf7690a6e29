#include "marching/block_mesher.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <stdexcept>

#include "marching/cube_table.h"

namespace sylva::detail {
namespace {

constexpr std::uint32_t kNoVertex = std::numeric_limits<std::uint32_t>::max();

constexpr std::size_t edge_slot(int i, int j, int k, int axis) {
    return (std::size_t(i) + kBlockNodes * (std::size_t(j) + kBlockNodes * std::size_t(k))) * 3 +
           std::size_t(axis);
}

// Meshes one block into a chunk. Holds what every cell of the block needs.
class BlockMesher {
  public:
    BlockMesher(const BlockGrid& g, const std::array<int, 3>& b, const float* values,
                std::ptrdiff_t sy, std::ptrdiff_t sz, BlockScratch& scratch, ChunkMesh& out)
        : g_(g),
          b_(b),
          range_(g.block_cells(b)),
          values_(values),
          sy_(sy),
          sz_(sz),
          scratch_(scratch),
          out_(out) {
        for (int a = 0; a < 3; ++a) size_[a] = range_.hi[a] - range_.lo[a];
    }

    ~BlockMesher() {
        for (const std::uint32_t slot : scratch_.touched) scratch_.edge_refs[slot] = kNoVertex;
        scratch_.touched.clear();
    }

    void run(std::uint64_t mask) {
        for (int k = 0; k < size_[2]; ++k) {
            for (int j = 0; j < size_[1]; ++j) {
                const std::uint64_t row_bits =
                    mask >> (kSubBlocksPerSide *
                             (j / kSubBlockCells + kSubBlocksPerSide * (k / kSubBlockCells)));
                const float* row = values_ + j * sy_ + k * sz_;
                for (int i = 0; i < size_[0]; ++i) {
                    if (!(row_bits >> (i / kSubBlockCells) & 1u)) continue;
                    const float* p = row + i;
                    const std::array<float, 8> v{
                        p[0],   p[1],       p[sy_],       p[sy_ + 1],
                        p[sz_], p[sz_ + 1], p[sz_ + sy_], p[sz_ + sy_ + 1]};
                    const unsigned config = corner_config(v);
                    if (config == 0 || config == 255) continue;
                    emit(cube_case(config, v), i, j, k);
                }
            }
        }
    }

  private:
    float value(int i, int j, int k) const { return values_[i + j * sy_ + k * sz_]; }

    const glm::vec3& position(std::uint32_t ref) const {
        return ref & ChunkMesh::kForeign ? out_.foreign_positions[ref & ~ChunkMesh::kForeign]
                                         : out_.positions[ref];
    }

    std::uint32_t add_owned(const glm::vec3& p) {
        // Refs keep the top bit for foreign vertices; a chunk is a few blocks, far below.
        assert(out_.positions.size() < ChunkMesh::kForeign);
        out_.positions.push_back(p);
        return std::uint32_t(out_.positions.size() - 1);
    }

    // The vertex on edge `axis` from local node (i, j, k), created on first use. Its position
    // is computed as every block that meets the edge computes it, from the same samples.
    std::uint32_t edge_vertex(int i, int j, int k, int axis) {
        const std::size_t slot = edge_slot(i, j, k, axis);
        std::uint32_t& ref = scratch_.edge_refs[slot];
        if (ref != kNoVertex) return ref;
        scratch_.touched.push_back(std::uint32_t(slot));

        const std::array<int, 3> local{i, j, k};
        std::array<int, 3> step{0, 0, 0};
        step[axis] = 1;
        const float v0 = value(i, j, k);
        const float v1 = value(i + step[0], j + step[1], k + step[2]);
        const std::array<int, 3> node{range_.lo[0] + i, range_.lo[1] + j, range_.lo[2] + k};
        glm::dvec3 p = g_.grid.node(node[0], node[1], node[2]);
        p[axis] += crossing_fraction(v0, v1) * g_.grid.h;
        const std::uint64_t key =
            (std::uint64_t(node[0]) +
             std::uint64_t(g_.grid.nodes[0]) *
                 (std::uint64_t(node[1]) + std::uint64_t(g_.grid.nodes[1]) * node[2])) *
                3 +
            std::uint64_t(axis);

        // On the block's upper face (other than the grid's) the edge belongs to the block
        // beyond; on its lower face to this block, and the block below will ask for it.
        std::array<int, 3> owner = b_;
        bool on_lower_face = false;
        for (int a = 0; a < 3; ++a) {
            if (a == axis) continue;
            if (local[a] == size_[a] && range_.hi[a] < g_.cells[a]) ++owner[a];
            if (local[a] == 0 && range_.lo[a] > 0) on_lower_face = true;
        }
        if (owner != b_) {
            ref = ChunkMesh::kForeign | std::uint32_t(out_.foreign_keys.size());
            out_.foreign_keys.push_back(key);
            out_.foreign_owners.push_back(g_.block_id(owner));
            out_.foreign_positions.emplace_back(p);
        } else {
            ref = add_owned(glm::vec3(p));
            if (on_lower_face) out_.shared.emplace_back(key, ref);
        }
        return ref;
    }

    void add_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        out_.triangles.push_back({a, b, c});
    }

    void emit(const CubeCase& cube, int i, int j, int k) {
        int offset = 0;
        for (int l = 0; l < cube.loop_count; ++l) {
            const int n = cube.loop_size[l];
            std::array<std::uint32_t, 12> ids;
            for (int m = 0; m < n; ++m) {
                const int e = cube.edges[offset + m];
                const std::array<int, 3> o = edge_origin(e);
                ids[m] = edge_vertex(i + o[0], j + o[1], k + o[2], edge_axis(e));
            }
            offset += n;
            if (cube.center_mask >> l & 1u) {
                glm::dvec3 sum(0.0);
                for (int m = 0; m < n; ++m) sum += glm::dvec3(position(ids[m]));
                const std::uint32_t center = add_owned(glm::vec3(sum / double(n)));
                for (int m = 0; m < n; ++m) add_triangle(center, ids[m], ids[(m + 1) % n]);
            } else if (n == 4) {
                // Either diagonal is safe here; the shorter one gives better-shaped triangles.
                const float d02 = glm::distance(position(ids[0]), position(ids[2]));
                const float d13 = glm::distance(position(ids[1]), position(ids[3]));
                if (d02 <= d13) {
                    add_triangle(ids[0], ids[1], ids[2]);
                    add_triangle(ids[0], ids[2], ids[3]);
                } else {
                    add_triangle(ids[1], ids[2], ids[3]);
                    add_triangle(ids[1], ids[3], ids[0]);
                }
            } else {
                for (int m = 1; m + 1 < n; ++m) add_triangle(ids[0], ids[m], ids[m + 1]);
            }
        }
    }

    const BlockGrid& g_;
    const std::array<int, 3> b_;
    const CellRange range_;
    std::array<int, 3> size_{};
    const float* values_;
    const std::ptrdiff_t sy_;
    const std::ptrdiff_t sz_;
    BlockScratch& scratch_;
    ChunkMesh& out_;
};

// The chunk holding `block`, or null: chunks are sorted and disjoint.
const ChunkMesh* chunk_of(const std::vector<ChunkMesh>& chunks, std::uint64_t block) {
    auto it =
        std::upper_bound(chunks.begin(), chunks.end(), block,
                         [](std::uint64_t b, const ChunkMesh& c) { return b < c.first_block; });
    if (it == chunks.begin()) return nullptr;
    --it;
    return block < it->end_block ? &*it : nullptr;
}

}  // namespace

BlockGrid::BlockGrid(const Grid& g) : grid(g) {
    double magnitude = 0.0;
    for (int a = 0; a < 3; ++a) {
        cells[a] = g.nodes[a] - 1;
        blocks[a] = (cells[a] + kBlockCells - 1) / kBlockCells;
        magnitude =
            std::max({magnitude, std::abs(g.origin[a]), std::abs(g.origin[a] + cells[a] * g.h)});
    }
    // Sample points are rounded to float, and a float field's value carries rounding of the
    // order of a few ulps of the coordinates; 1e-5 of their magnitude (about 100 ulps)
    // covers both with room to spare, and is far below a cell at any usable resolution.
    rounding_slack = 1e-5 * magnitude;
}

CellRange BlockGrid::block_cells(const std::array<int, 3>& b) const {
    CellRange r;
    for (int a = 0; a < 3; ++a) {
        r.lo[a] = b[a] * kBlockCells;
        r.hi[a] = std::min(r.lo[a] + kBlockCells, cells[a]);
    }
    return r;
}

bool BlockGrid::touches_border(const CellRange& r) const {
    for (int a = 0; a < 3; ++a) {
        if (r.lo[a] == 0 || r.hi[a] == cells[a]) return true;
    }
    return false;
}

glm::vec3 BlockGrid::centre(const CellRange& r) const {
    const glm::dvec3 middle(0.5 * (r.lo[0] + r.hi[0]), 0.5 * (r.lo[1] + r.hi[1]),
                            0.5 * (r.lo[2] + r.hi[2]));
    return glm::vec3(grid.origin + middle * grid.h);
}

bool BlockGrid::proven_empty(const CellRange& r, float value, double offset) const {
    const glm::dvec3 extent(r.hi[0] - r.lo[0], r.hi[1] - r.lo[1], r.hi[2] - r.lo[2]);
    const double reach = 0.5 * glm::length(extent) * grid.h + offset;
    // The relative part guards the bound against the field's own rounding near the surface.
    const double bound = reach * (1.0 + 1e-3) + rounding_slack;
    // NaN compares false both ways: it proves nothing.
    if (double(value) > bound) return true;
    return double(value) < -bound && !touches_border(r);
}

float usable_sample(float value, bool border) {
    const bool usable = std::isfinite(value) && !(border && inside(value));
    return usable ? value : std::numeric_limits<float>::quiet_NaN();
}

BlockScratch::BlockScratch()
    : edge_refs(std::size_t(3) * kBlockNodes * kBlockNodes * kBlockNodes, kNoVertex) {}

void mesh_block(const BlockGrid& g, const std::array<int, 3>& b, const float* values,
                std::ptrdiff_t sy, std::ptrdiff_t sz, std::uint64_t mask, BlockScratch& scratch,
                ChunkMesh& out) {
    BlockMesher(g, b, values, sy, sz, scratch, out).run(mask);
}

Mesh assemble(std::vector<ChunkMesh>& chunks, MeshingRun& run) {
    run.for_each(chunks.size(), [&](std::size_t c) {
        std::sort(chunks[c].shared.begin(), chunks[c].shared.end());
    });

    // Resolve refs to other chunks' vertices as (chunk, index) pairs; offsets come later.
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> resolved(chunks.size());
    run.for_each(chunks.size(), [&](std::size_t c) {
        ChunkMesh& chunk = chunks[c];
        auto& out = resolved[c];
        out.reserve(chunk.foreign_keys.size());
        for (std::size_t f = 0; f < chunk.foreign_keys.size(); ++f) {
            const std::uint64_t key = chunk.foreign_keys[f];
            if (const ChunkMesh* owner = chunk_of(chunks, chunk.foreign_owners[f])) {
                const auto it = std::lower_bound(owner->shared.begin(), owner->shared.end(),
                                                 std::pair<std::uint64_t, std::uint32_t>(key, 0));
                if (it != owner->shared.end() && it->first == key) {
                    out.emplace_back(std::uint32_t(owner - chunks.data()), it->second);
                    continue;
                }
            }
            // Only a field that breaks its distance bound gets here (the owner block was
            // skipped as empty): keep the vertex, at the cost of a crack, rather than fail.
            // Appending to this chunk's positions is safe: other chunks read only `shared`.
            chunk.positions.push_back(chunk.foreign_positions[f]);
            out.emplace_back(std::uint32_t(c), std::uint32_t(chunk.positions.size() - 1));
        }
    });

    // Read by every chunk's writer while chunks are freed, so kept apart from them.
    std::vector<std::size_t> vertex_offsets(chunks.size()), triangle_offsets(chunks.size());
    std::size_t vertices = 0, triangles = 0;
    for (std::size_t c = 0; c < chunks.size(); ++c) {
        vertex_offsets[c] = vertices;
        triangle_offsets[c] = triangles;
        vertices += chunks[c].positions.size();
        triangles += chunks[c].triangles.size();
    }
    if (vertices >= std::numeric_limits<std::uint32_t>::max()) {
        throw std::length_error("marching_cubes: more than 2^32 - 1 vertices");
    }

    Mesh mesh;
    mesh.positions.resize(vertices);
    mesh.triangles.resize(triangles);
    run.for_each(chunks.size(), [&](std::size_t c) {
        ChunkMesh& chunk = chunks[c];
        std::copy(chunk.positions.begin(), chunk.positions.end(),
                  mesh.positions.begin() + std::ptrdiff_t(vertex_offsets[c]));
        std::vector<std::uint32_t> foreign(resolved[c].size());
        for (std::size_t f = 0; f < foreign.size(); ++f) {
            const auto [owner, index] = resolved[c][f];
            foreign[f] = std::uint32_t(vertex_offsets[owner] + index);
        }
        const std::uint32_t base = std::uint32_t(vertex_offsets[c]);
        auto* out = mesh.triangles.data() + triangle_offsets[c];
        for (const auto& t : chunk.triangles) {
            for (int m = 0; m < 3; ++m) {
                const std::uint32_t ref = t[m];
                (*out)[m] =
                    ref & ChunkMesh::kForeign ? foreign[ref & ~ChunkMesh::kForeign] : base + ref;
            }
            ++out;
        }
        // The chunk is spent; free it now rather than hold two copies of the mesh.
        chunk = ChunkMesh{};
    });
    return mesh;
}

}  // namespace sylva::detail
