#include "marching/mesh_checks.h"

#include <algorithm>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <numeric>
#include <tuple>
#include <utility>
#include <vector>

#include "core/disjoint_sets.h"

namespace sylva {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

glm::dvec3 corner(const Mesh& mesh, const Triangle& t, int k) {
    return glm::dvec3(mesh.positions[t[k]]);
}

bool indices_valid(const Mesh& mesh, const Triangle& t) {
    const std::size_t n = mesh.positions.size();
    return t[0] < n && t[1] < n && t[2] < n;
}

bool repeats_index(const Triangle& t) {
    return t[0] == t[1] || t[1] == t[2] || t[2] == t[0];
}

// Twice the triangle's vector area.
glm::dvec3 area_vector(const Mesh& mesh, const Triangle& t) {
    const glm::dvec3 a = corner(mesh, t, 0);
    return glm::cross(corner(mesh, t, 1) - a, corner(mesh, t, 2) - a);
}

struct Bounds {
    glm::dvec3 min{0.0};
    glm::dvec3 max{0.0};
};

Bounds bounds(const Mesh& mesh) {
    if (mesh.positions.empty()) return {};
    Bounds b{glm::dvec3(mesh.positions.front()), glm::dvec3(mesh.positions.front())};
    for (const auto& p : mesh.positions) {
        b.min = glm::min(b.min, glm::dvec3(p));
        b.max = glm::max(b.max, glm::dvec3(p));
    }
    return b;
}

}  // namespace

MeshTopology check_topology(const Mesh& mesh) {
    MeshTopology result;

    // Float positions cannot resolve areas much below (1e-6 * size)^2, so anything smaller
    // is zero area.
    const Bounds box = bounds(mesh);
    const glm::dvec3 diagonal = box.max - box.min;
    const double min_twice_area = 2e-12 * glm::dot(diagonal, diagonal);

    // Triangles with a bad or repeated index are degenerate and left out of the edge and
    // vertex checks, which would otherwise report the same defect again; flat triangles with
    // distinct indices still connect their neighbours and are kept.
    std::vector<std::uint32_t> usable;
    usable.reserve(mesh.triangles.size());
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
        const Triangle& tri = mesh.triangles[t];
        if (!indices_valid(mesh, tri) || repeats_index(tri)) {
            ++result.degenerate_triangles;
            continue;
        }
        if (glm::length(area_vector(mesh, tri)) <= min_twice_area) ++result.degenerate_triangles;
        usable.push_back(t);
    }

    // Undirected edges as (low, high, forward), sorted so that the uses of one edge are
    // adjacent.
    std::vector<std::tuple<std::uint32_t, std::uint32_t, bool>> edges;
    edges.reserve(3 * usable.size());
    for (const std::uint32_t t : usable) {
        const Triangle& tri = mesh.triangles[t];
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = tri[k], b = tri[(k + 1) % 3];
            edges.emplace_back(std::min(a, b), std::max(a, b), a < b);
        }
    }
    std::sort(edges.begin(), edges.end());
    for (std::size_t first = 0; first < edges.size();) {
        std::size_t last = first + 1;
        while (last < edges.size() && std::get<0>(edges[last]) == std::get<0>(edges[first]) &&
               std::get<1>(edges[last]) == std::get<1>(edges[first])) {
            ++last;
        }
        const std::size_t uses = last - first;
        if (uses == 1) {
            ++result.boundary_edges;
        } else if (uses >= 3) {
            ++result.non_manifold_edges;
        } else if (std::get<2>(edges[first]) == std::get<2>(edges[first + 1])) {
            ++result.misoriented_edges;
        }
        first = last;
    }

    // A vertex is manifold when the edges opposite it in its triangles (its link) form one
    // connected path or cycle; each extra connected component is another fan meeting the
    // first at this vertex only.
    std::vector<std::uint32_t> link_start(mesh.positions.size() + 1, 0);
    for (const std::uint32_t t : usable) {
        for (const std::uint32_t v : mesh.triangles[t]) ++link_start[v + 1];
    }
    std::partial_sum(link_start.begin(), link_start.end(), link_start.begin());
    std::vector<std::pair<std::uint32_t, std::uint32_t>> links(link_start.back());
    {
        std::vector<std::uint32_t> fill(link_start.begin(), link_start.end() - 1);
        for (const std::uint32_t t : usable) {
            const Triangle& tri = mesh.triangles[t];
            for (int k = 0; k < 3; ++k)
                links[fill[tri[k]]++] = {tri[(k + 1) % 3], tri[(k + 2) % 3]};
        }
    }
    std::vector<std::uint32_t> neighbours;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const auto begin = links.begin() + link_start[v];
        const auto end = links.begin() + link_start[v + 1];
        if (begin == end) continue;
        neighbours.clear();
        for (auto it = begin; it != end; ++it) {
            neighbours.push_back(it->first);
            neighbours.push_back(it->second);
        }
        std::sort(neighbours.begin(), neighbours.end());
        neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
        const auto local = [&](std::uint32_t n) {
            return int(std::lower_bound(neighbours.begin(), neighbours.end(), n) -
                       neighbours.begin());
        };
        DisjointSets sets(neighbours.size());
        std::size_t components = neighbours.size();
        for (auto it = begin; it != end; ++it) {
            if (sets.unite(std::uint32_t(local(it->first)), std::uint32_t(local(it->second))))
                --components;
        }
        if (components > 1) ++result.non_manifold_vertices;
    }
    return result;
}

double surface_area(const Mesh& mesh) {
    double twice_area = 0.0;
    for (const auto& tri : mesh.triangles) {
        if (indices_valid(mesh, tri)) twice_area += glm::length(area_vector(mesh, tri));
    }
    return 0.5 * twice_area;
}

std::vector<double> component_volumes(const Mesh& mesh) {
    // Union-find over vertices; a triangle joins its three.
    DisjointSets sets(mesh.positions.size());
    for (const auto& tri : mesh.triangles) {
        if (!indices_valid(mesh, tri)) continue;
        sets.unite(tri[1], tri[0]);
        sets.unite(tri[2], tri[0]);
    }
    const Bounds box = bounds(mesh);
    const glm::dvec3 reference = 0.5 * (box.min + box.max);
    std::vector<double> volumes;
    std::vector<std::int64_t> slot(mesh.positions.size(), -1);
    for (const auto& tri : mesh.triangles) {
        if (!indices_valid(mesh, tri)) continue;
        std::int64_t& k = slot[sets.find(tri[0])];
        if (k < 0) {
            k = static_cast<std::int64_t>(volumes.size());
            volumes.push_back(0.0);
        }
        const glm::dvec3 a = corner(mesh, tri, 0) - reference;
        const glm::dvec3 b = corner(mesh, tri, 1) - reference;
        const glm::dvec3 c = corner(mesh, tri, 2) - reference;
        volumes[static_cast<std::size_t>(k)] += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return volumes;
}

double enclosed_volume(const Mesh& mesh) {
    // Measured from the bounding-box centre rather than the origin: the same result for a
    // closed mesh, without the cancellation of large terms when the mesh is far from the
    // origin.
    const Bounds box = bounds(mesh);
    const glm::dvec3 reference = 0.5 * (box.min + box.max);
    double six_volume = 0.0;
    for (const auto& tri : mesh.triangles) {
        if (!indices_valid(mesh, tri)) continue;
        const glm::dvec3 a = corner(mesh, tri, 0) - reference;
        const glm::dvec3 b = corner(mesh, tri, 1) - reference;
        const glm::dvec3 c = corner(mesh, tri, 2) - reference;
        six_volume += glm::dot(a, glm::cross(b, c));
    }
    return six_volume / 6.0;
}

std::string to_string(const MeshTopology& t) {
    return "boundary " + std::to_string(t.boundary_edges) + ", non-manifold edges " +
           std::to_string(t.non_manifold_edges) + ", misoriented " +
           std::to_string(t.misoriented_edges) + ", degenerate " +
           std::to_string(t.degenerate_triangles) + ", non-manifold vertices " +
           std::to_string(t.non_manifold_vertices);
}

}  // namespace sylva
