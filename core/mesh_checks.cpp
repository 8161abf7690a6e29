#include "core/mesh_checks.h"

#include <algorithm>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <numeric>
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
    const std::size_t vertex_count = mesh.positions.size();
    std::vector<std::uint32_t> usable;
    usable.reserve(mesh.triangles.size());
    std::vector<std::uint32_t> link_start(vertex_count + 1, 0);
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
        const Triangle& tri = mesh.triangles[t];
        if (!indices_valid(mesh, tri) || repeats_index(tri)) {
            ++result.degenerate_triangles;
            continue;
        }
        if (glm::length(area_vector(mesh, tri)) <= min_twice_area) ++result.zero_area_triangles;
        usable.push_back(t);
        for (const std::uint32_t v : tri) ++link_start[v + 1];
    }

    // Each vertex's link: for every triangle (v, a, b) around it, the edge (a, b) opposite.
    // The triangle also uses the directed edges v -> a and b -> v, so the link holds every
    // use of every edge at v, and an undirected edge is counted once, at its lower end, with
    // no global sort of all edges.
    std::partial_sum(link_start.begin(), link_start.end(), link_start.begin());
    std::vector<std::pair<std::uint32_t, std::uint32_t>> links(link_start.back());
    {
        std::vector<std::uint32_t> fill(link_start.begin(), link_start.end() - 1);
        for (const std::uint32_t t : usable) {
            const Triangle& tri = mesh.triangles[t];
            links[fill[tri[0]]++] = {tri[1], tri[2]};
            links[fill[tri[1]]++] = {tri[2], tri[0]};
            links[fill[tri[2]]++] = {tri[0], tri[1]};
        }
    }

    // A vertex is manifold when its link is one connected path or cycle. Per vertex, its
    // neighbours numbered locally (slot[w] while v is visited), how often the edge to each is
    // used in each direction, and the link's components by union-find over the local numbers
    // (links are small: about six neighbours, so this stays in cache without any sort).
    struct Neighbour {
        std::uint32_t vertex;
        std::uint32_t parent;    // union-find over local numbers
        std::uint32_t outgoing;  // uses as v -> vertex
        std::uint32_t incoming;  // uses as vertex -> v
    };
    constexpr std::uint32_t kNone = ~0u;
    std::vector<std::uint32_t> slot(vertex_count, kNone);
    std::uint32_t largest_link = 0;
    for (std::size_t v = 0; v < vertex_count; ++v)
        largest_link = std::max(largest_link, link_start[v + 1] - link_start[v]);
    std::vector<Neighbour> around(2 * std::size_t(largest_link));
    std::uint32_t count = 0;
    const auto find = [&](std::uint32_t x) {
        while (around[x].parent != x) x = around[x].parent = around[around[x].parent].parent;
        return x;
    };
    const auto local = [&](std::uint32_t w) {
        std::uint32_t& s = slot[w];
        if (s == kNone) {
            s = count++;
            around[s] = {w, s, 0, 0};
        }
        return s;
    };
    for (std::uint32_t v = 0; v < vertex_count; ++v) {
        const std::uint32_t begin = link_start[v], end = link_start[v + 1];
        if (begin == end) continue;
        count = 0;
        std::uint32_t joins = 0;
        for (std::uint32_t k = begin; k < end; ++k) {
            const std::uint32_t a = local(links[k].first), b = local(links[k].second);
            ++around[a].outgoing;
            ++around[b].incoming;
            const std::uint32_t ra = find(a), rb = find(b);
            if (ra != rb) {
                around[ra].parent = rb;
                ++joins;
            }
        }
        // Each extra component of the link is another fan meeting the first at v only.
        if (count - joins > 1) ++result.non_manifold_vertices;
        for (std::uint32_t i = 0; i < count; ++i) {
            const Neighbour& n = around[i];
            slot[n.vertex] = kNone;
            if (n.vertex < v) continue;  // counted at its lower end
            const std::uint32_t uses = n.outgoing + n.incoming;
            if (uses == 1) {
                ++result.boundary_edges;
            } else if (uses >= 3) {
                ++result.non_manifold_edges;
            } else if (n.outgoing == 2 || n.incoming == 2) {
                ++result.misoriented_edges;
            }
        }
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
           std::to_string(t.non_manifold_vertices) + ", zero-area " +
           std::to_string(t.zero_area_triangles);
}

}  // namespace sylva
