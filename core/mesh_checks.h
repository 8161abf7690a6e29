// Measures and topology checks on triangle meshes: is it closed, manifold, consistently
// oriented; its area and enclosed volume. Used by tests, the CLI summary and benchmarks.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/mesh.h"

namespace sylva {

struct MeshTopology {
    std::size_t boundary_edges = 0;         // undirected edges used by exactly one triangle
    std::size_t non_manifold_edges = 0;     // undirected edges used by three or more triangles
    std::size_t misoriented_edges = 0;      // edges used twice in the same direction
    std::size_t degenerate_triangles = 0;   // a repeated or missing vertex index
    std::size_t non_manifold_vertices = 0;  // triangles around a vertex form more than one fan
    // Three distinct vertices with (almost) no area between them: twice the area at most
    // 2e-12 of the bounding box's squared diagonal (float positions resolve about 1e-6 of
    // the size).
    // Such a sliver is still part of a closed surface (marching cubes makes them on very
    // fine grids and far from the origin, where floats are coarse), so it does not open
    // the mesh; a reduction counts them apart (lowpoly/decimate.h makes none).
    std::size_t zero_area_triangles = 0;

    // Closed 2-manifold with consistent orientation: every edge between exactly two
    // triangles in opposite directions, one fan around every vertex, no triangle with a
    // repeated or missing index. Zero-area triangles do not count against it.
    bool is_closed_manifold() const {
        return boundary_edges == 0 && non_manifold_edges == 0 && misoriented_edges == 0 &&
               degenerate_triangles == 0 && non_manifold_vertices == 0;
    }
};

MeshTopology check_topology(const Mesh& mesh);

// "boundary 0, non-manifold edges 0, ..." for messages and test failures.
std::string to_string(const MeshTopology& topology);

double surface_area(const Mesh& mesh);

// Signed volume by the divergence theorem; positive for a closed outward-oriented mesh.
double enclosed_volume(const Mesh& mesh);

// The signed volume of each connected component (triangles joined through shared
// vertices), in the order of each component's first triangle. A closed mesh that is
// outward everywhere has every entry positive; an inside-out piece shows as a negative
// one even when a bigger piece hides it in the total.
std::vector<double> component_volumes(const Mesh& mesh);

}  // namespace sylva
