// Marching cubes: turns any signed distance field into a closed triangle mesh.
//
// The field is negative inside. The surface is watertight by construction: each cube face
// decides its own contour from its four samples alone (asymptotic decider, evaluated in a
// canonical corner order), so the two cubes sharing a face always agree; vertices are
// welded by global edge id; a sample counts as inside only when strictly negative.
#pragma once

#include "marching/mesh.h"

#include <atomic>
#include <cstddef>
#include <functional>
#include <span>

namespace sylva {

// A field evaluated one point at a time (convenient for tests and simple shapes).
using ScalarField = std::function<float(const glm::vec3&)>;

// A field evaluated in batches: values[i] = f(points[i]); both spans have the same size.
// Called concurrently from several threads: it must be thread-safe.
using BatchField = std::function<void(std::span<const glm::vec3> points, std::span<float> values)>;

// Thrown by the meshers when MarchingCubesSettings::cancel became true.
struct MeshingCancelled {};

enum class Mesher {
    Dense,   // every grid node evaluated, in parallel slabs
    Sparse,  // blocks that provably hold no surface are skipped (needs a distance bound)
    Vdb,     // OpenVDB narrow-band level set + tools::volumeToMesh (marching/vdb_mesher.h)
};

// Counters a benchmark or a status bar can show.
struct MeshingStats {
    std::size_t evaluations = 0;     // field samples taken
    std::size_t blocks_total = 0;    // Sparse: blocks in the grid
    std::size_t blocks_meshed = 0;   // Sparse: blocks whose nodes were all evaluated
};

struct MarchingCubesSettings {
    // Cells along the longest side of the box (seed 001: P_Tres / P_Cres, 10-200).
    int resolution = 64;
    // Extra empty cells added on every side so the surface is never clipped by the box.
    int padding_cells = 2;
    // Worker threads; 0 = all cores (oneTBB's default arena).
    int threads = 0;
    // Called now and then with the finished fraction in [0, 1], from any thread.
    std::function<void(float)> progress;
    // Polled between blocks; when it becomes true the mesher throws MeshingCancelled.
    const std::atomic<bool>* cancel = nullptr;
    // Filled in when not null.
    MeshingStats* stats = nullptr;
};

// Meshes the zero level set of `field` inside `box` (grown by the padding).
//
// Grid: cubic cells of size h = longest box side / resolution over the box grown by
// padding_cells * h on every side; on the shorter axes the grid is widened, symmetrically,
// by less than one cell to a whole number of cells. The field is evaluated once per grid
// node, from the calling thread. A sample is inside only when it is finite and strictly
// negative (NaN and infinities count as outside).
//
// Clipping: the outermost layer of grid nodes always counts as outside, so the mesh is
// closed even where the field is still negative at the grid border; there the surface is
// capped flat, half a cell inside the grid border. With padding_cells >= 1 this cannot
// touch a surface that lies inside `box`.
//
// Output: a closed, consistently oriented 2-manifold (possibly empty), triangles
// counter-clockwise seen from outside, one vertex per crossed grid edge plus, rarely, one
// centre vertex for a cube whose contour loops through the same face twice. Every vertex
// lies inside the grid. The same inputs give the same mesh, vertex order included.
//
// Throws std::invalid_argument when resolution < 1, padding_cells < 0, or the box is empty
// (no positive side) or not finite.
Mesh marching_cubes(const ScalarField& field, const Box& box, const MarchingCubesSettings& settings);
Mesh marching_cubes(const BatchField& field, const Box& box, const MarchingCubesSettings& settings);

// The same grid, vertices and triangles as marching_cubes(), but a block of cells is only
// evaluated when the field value at its centre does not prove it empty: |f(centre)| greater
// than the block's half-diagonal means no sign change inside (the field must be
// 1-Lipschitz: a distance or a distance bound). Cost grows with the surface's area, not
// the box's volume. The mesh equals the dense one: same vertices, same triangles.
Mesh sparse_marching_cubes(const BatchField& field, const Box& box,
                           const MarchingCubesSettings& settings);

}  // namespace sylva
