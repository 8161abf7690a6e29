// The OpenVDB path: the field is sampled into a sparse narrow-band level set on the same
// grid as marching_cubes() and meshed by openvdb::tools::volumeToMesh, whose quads are
// split into triangles. Adaptivity > 0 merges flat regions into larger polygons.
#pragma once

#include "marching/marching_cubes.h"

namespace sylva {

struct VdbSettings {
    // openvdb::tools::volumeToMesh adaptivity, 0 (uniform) to 1 (most merging).
    double adaptivity = 0.0;
    // Half-width of the narrow band, in voxels.
    float band_voxels = 3.0f;
};

// Same preconditions, cancel/progress/stats behaviour and orientation as
// sparse_marching_cubes(): the field must be 1-Lipschitz; triangles counter-clockwise seen
// from outside.
Mesh vdb_mesh(const BatchField& field, const Box& box, const MarchingCubesSettings& settings,
              const VdbSettings& vdb = {});

}  // namespace sylva
