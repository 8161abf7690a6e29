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
    std::size_t degenerate_triangles = 0;   // repeated vertex index or zero area
    std::size_t non_manifold_vertices = 0;  // triangles around a vertex form more than one fan

    // Closed 2-manifold with consistent orientation and no degenerate triangle.
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
