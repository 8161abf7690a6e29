// Test helper: the mesh is a closed, consistently oriented 2-manifold without degenerate or
// zero-area triangles, with every failing count reported.
#pragma once

#include <gtest/gtest.h>

#include "marching/mesh_checks.h"

namespace sylva {

inline void expect_closed_manifold(const Mesh& mesh) {
    const MeshTopology t = check_topology(mesh);
    EXPECT_TRUE(t.is_closed_manifold()) << to_string(t);
    EXPECT_EQ(t.zero_area_triangles, 0u) << to_string(t);
}

}  // namespace sylva
