// The OpenVDB path: the field is sampled into a sparse narrow-band level set on the same
// grid as marching_cubes() and meshed by openvdb::tools::volumeToMesh, whose quads are
// split into triangles. Adaptivity > 0 merges flat regions into larger polygons. Its own
// settings are MeshSettings::vdb.
#pragma once

#include "marching/mesher.h"

namespace sylva {

// Same preconditions, cancel/progress/stats behaviour and orientation as
// sparse_marching_cubes(): the field must be 1-Lipschitz; triangles counter-clockwise seen
// from outside. The result is a closed, consistently oriented 2-manifold (possibly empty).
//
// Grid: make_grid(box, settings); voxel (i, j, k) is grid node (i, j, k). Blocks of 8^3
// nodes (one OpenVDB leaf) are skipped when |f(centre)| exceeds their half-diagonal plus the
// band (6.1 + band_voxels cells); near the surface, 4^3 sub-blocks are tested the same way
// (2.6 + band_voxels cells) before their nodes are sampled, one batch per block. A field
// that is exact only below some margin and constant above it (sdf/cone_field.h) meshes
// correctly when the margin exceeds the band; sub-blocks are skipped when it exceeds 5.6
// cells, whole blocks when it exceeds 9.1 cells (default band). On a cone cloud a margin of
// 6-7 cells is fastest (7 also lets sparse_marching_cubes() skip 8-cell blocks): each far
// block then costs 9 evaluations, but every evaluation near the cones sees fewer cones.
//
// As in marching_cubes(), the outermost layer of nodes and non-finite samples count as
// outside, so clipped surfaces are capped within the last cell. Samples closer to zero than
// 1% of a cell are pushed to +-1% of a cell on their own side (zero is outside), so the
// cells around a node do not meet in triangles of no area; the surface moves by at most
// that much.
//
// Vertices: one per surface cell (volumeToMesh places it at the mean of the cell's edge
// crossings), not one per crossed edge, so they differ from marching_cubes()'s but lie
// within a cell of the surface, inside the grid; at adaptivity 0 the triangle counts are
// within about 5% of each other. volumeToMesh merges cells only within a leaf, so on
// smooth shapes adaptivity stops reducing the count at about one quad per leaf (from ~0.1
// up); merged polygons are chords and shrink convex parts by a few percent.
//
// Threads: settings.threads also bounds OpenVDB's own work (0: the caller's arena).
// Progress, cancel and stats follow MeshSettings, run as for the other meshers
// (marching/meshing_run.h). Cancel is polled between sampling tasks (at most 64 blocks) and
// between phases; volumeToMesh itself cannot be interrupted (about 0.1-0.2 s at resolution
// 400 on two cores). Progress: up to 0.6 while sampling, 0.95 after volumeToMesh, then 1.
// Stats: evaluations counts every sample (block and sub-block centres included),
// blocks_total the 8^3-node blocks of the grid, blocks_meshed those whose nodes were
// (partly) sampled. The same inputs give the same mesh, vertex order included, whatever the
// thread count. Exceptions the field throws reach the caller.
//
// Throws InputError as marching_cubes() does, and when settings.vdb.adaptivity is outside
// [0, 1] or settings.vdb.band_voxels below 1; Cancelled when cancelled.
//
// Loading: OpenVDB lives in a module of its own (libsylva_vdb.so, marching/vdb_module.cpp),
// loaded on the first call: linked into every program, its relocations would cost each
// process more at start than a whole game export of a small tree takes. The module is
// looked for in $SYLVA_VDB_MODULE, next to the running program, then where the build put
// it; throws IoError naming the places tried when none loads.
Mesh vdb_mesh(const BatchField& field, const Box& box, const MeshSettings& settings);

// The module's entry point (extern "C" sylva_vdb_mesh_entry) returns this.
using VdbMeshFunction = Mesh (*)(const BatchField&, const Box&, const MeshSettings&);

}  // namespace sylva
