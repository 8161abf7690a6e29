// Marching cubes: turns any signed distance field into a closed triangle mesh.
//
// The field is negative inside. The surface is watertight by construction: each cube face
// decides its own contour from its four samples alone (asymptotic decider, evaluated in a
// canonical corner order), so the two cubes sharing a face always agree; vertices are
// welded by global edge id; a sample counts as inside only when strictly negative.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <span>

#include "core/box.h"
#include "core/cancel.h"
#include "core/mesh.h"

namespace sylva {

// A field evaluated one point at a time (convenient for tests and simple shapes). Always
// called from the calling thread, so it need not be thread-safe.
using ScalarField = std::function<float(const glm::vec3&)>;

// A field evaluated in batches: values[i] = f(points[i]); both spans have the same size.
// Called concurrently from several threads: it must be thread-safe. It must also be a pure
// function of the point: the meshers may evaluate a point twice in different batches (a
// node the sparse mesher also used as a block centre, say) and rely on getting the same
// value, so that neighbouring blocks agree on a shared node.
using BatchField = std::function<void(std::span<const glm::vec3> points, std::span<float> values)>;

// Thrown by the meshers when MarchingCubesSettings::cancel became true.
enum class Mesher {
    Dense,   // every grid node evaluated, in parallel slabs
    Sparse,  // blocks that provably hold no surface are skipped (needs a distance bound)
    Vdb,     // OpenVDB narrow-band level set + tools::volumeToMesh (marching/vdb_mesher.h)
};

// Counters a benchmark or a status bar can show. Both meshers cut the grid into blocks of
// 8 x 8 x 8 cells (smaller at the far ends of the axes).
struct MeshingStats {
    std::size_t evaluations = 0;    // field samples taken, points in all batches
    std::size_t blocks_total = 0;   // blocks in the grid
    std::size_t blocks_meshed = 0;  // blocks whose cells were meshed (Dense: all of them)
};

struct MarchingCubesSettings {
    // Cells along the longest side of the box (seed 001: P_Tres / P_Cres, 10-200).
    int resolution = 64;
    // Extra empty cells added on every side so the surface is never clipped by the box.
    int padding_cells = 2;
    // Worker threads; 0 = all cores (oneTBB's default arena).
    int threads = 0;
    // Called now and then with the finished fraction in [0, 1], from any thread but never
    // concurrently; the fractions never decrease, and a run that completes ends with
    // exactly one call with 1. The callback may set *cancel.
    std::function<void(float)> progress;
    // Polled between small pieces of work (a batch of a few thousand nodes, or a few
    // blocks); once it is true the mesher lets the running pieces finish, drops its work
    // and throws Cancelled.
    CancelFlag cancel = nullptr;
    // Overwritten when not null (and the run completes).
    MeshingStats* stats = nullptr;
};

// Meshes the zero level set of `field` inside `box` (grown by the padding).
//
// Grid: cubic cells of size h = longest box side / resolution over the box grown by
// padding_cells * h on every side; on the shorter axes the grid is widened, symmetrically,
// by less than one cell to a whole number of cells (make_grid() in marching/grid.h). The
// field is evaluated exactly once per grid node. A sample is inside only when it is finite
// and strictly negative (NaN and infinities count as outside).
//
// Threads: the BatchField overload evaluates rows of nodes in batches and meshes blocks on
// settings.threads workers. The ScalarField overload runs everything on the calling thread
// (settings.threads is ignored), so a field that is not thread-safe is fine there; it
// gives the same mesh as the BatchField overload with the same field.
//
// Clipping: the outermost layer of grid nodes always counts as outside, so the mesh is
// closed even where the field is still negative at the grid border; there the surface is
// capped flat, half a cell inside the grid border. With padding_cells >= 1 this cannot
// touch a surface that lies inside `box`.
//
// Output: a closed, consistently oriented 2-manifold (possibly empty), triangles
// counter-clockwise seen from outside, one vertex per crossed grid edge plus, rarely, one
// centre vertex for a cube whose contour loops through the same face twice. Every vertex
// lies inside the grid. The same inputs give the same mesh, vertex order included, whatever
// the thread count: vertices follow the blocks in order (x fastest, then y, then z).
//
// Progress, cancel and stats: see MarchingCubesSettings. Exceptions the field throws reach
// the caller.
//
// Throws std::invalid_argument when resolution < 1, padding_cells < 0, or the box is empty
// (no positive side) or not finite; std::length_error past 2^32 - 1 vertices.
Mesh marching_cubes(const ScalarField& field, const Box& box,
                    const MarchingCubesSettings& settings);
Mesh marching_cubes(const BatchField& field, const Box& box, const MarchingCubesSettings& settings);

// The same grid, vertices and triangles as marching_cubes(), but a block of cells is only
// evaluated when the field value at its centre does not prove it empty: |f(centre)| greater
// than the block's half-diagonal means no sign change inside (the field must be
// 1-Lipschitz: a distance or a distance bound). Blocks are refined from 32 to 8, 4 and 2
// cells a side; only the nodes of the 2-cell cubes left are evaluated, each once as a rule
// (stats.evaluations counts the centres too). Cost grows with the surface's area, not the
// box's volume.
//
// Output: byte for byte the mesh marching_cubes(BatchField) gives (same vertices in the
// same order, same triangles), and the same whatever the thread count.
//
// A field clamped far from its surface, min(distance, m) (sdf/cone_field.h's margin), is
// still 1-Lipschitz, but only ranges whose half-diagonal is below m can be skipped: with
// m >= 7 cells empty 8-cell blocks are skipped (half-diagonal 4 sqrt(3) = 6.93 cells),
// with m >= 28 cells whole 32-cell ranges; with less, every block is visited (the mesh is
// the same, only slower).
//
// A field that breaks the bound gives a mesh with holes where it lied, never invalid
// indices. Throws like marching_cubes().
Mesh sparse_marching_cubes(const BatchField& field, const Box& box,
                           const MarchingCubesSettings& settings);

}  // namespace sylva
