// Marching cubes: turns any signed distance field into a closed triangle mesh.
//
// The field is negative inside. The surface is watertight by construction: each cube face
// decides its own contour from its four samples alone (asymptotic decider, evaluated in a
// canonical corner order), so the two cubes sharing a face always agree; vertices are
// welded by global edge id; a sample counts as inside only when strictly negative.
#pragma once

#include "marching/mesher.h"

namespace sylva {

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
// Progress, cancel and stats: see MeshSettings. Exceptions the field throws reach the caller.
//
// Throws InputError when resolution < 1, padding_cells < 0, or the box is empty (no
// positive side) or not finite; std::length_error past 2^32 - 1 vertices.
Mesh marching_cubes(const ScalarField& field, const Box& box, const MeshSettings& settings);
Mesh marching_cubes(const BatchField& field, const Box& box, const MeshSettings& settings);

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
Mesh sparse_marching_cubes(const BatchField& field, const Box& box, const MeshSettings& settings);

}  // namespace sylva
