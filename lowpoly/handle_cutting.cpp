#include "lowpoly/handle_cutting.h"

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <numeric>
#include <queue>
#include <unordered_map>
#include <vector>

#include "core/disjoint_sets.h"
#include "marching/mesh_checks.h"

namespace sylva {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

std::uint64_t key(std::uint32_t a, std::uint32_t b) {
    return (std::uint64_t{a} << 32) | b;
}

// Edges, faces per edge and vertex neighbours of a closed, oriented triangle mesh.
struct Connectivity {
    struct Edge {
        std::uint32_t a, b;                      // a < b
        std::uint32_t face_ab = 0, face_ba = 0;  // the faces holding a->b and b->a
        float length = 0;
    };
    std::vector<Edge> edges;
    std::unordered_map<std::uint64_t, std::uint32_t> face_of;  // directed edge -> face
    std::vector<std::uint32_t> first, neighbour, edge_of;      // CSR: vertex -> (vertex, edge)

    explicit Connectivity(const Mesh& mesh) {
        face_of.reserve(3 * mesh.triangles.size());
        std::unordered_map<std::uint64_t, std::uint32_t> edge_index;
        edge_index.reserve(2 * mesh.triangles.size());
        for (std::uint32_t f = 0; f < mesh.triangles.size(); ++f)
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t a = mesh.triangles[f][k], b = mesh.triangles[f][(k + 1) % 3];
                face_of[key(a, b)] = f;
                auto [it, added] = edge_index.try_emplace(key(std::min(a, b), std::max(a, b)),
                                                          static_cast<std::uint32_t>(edges.size()));
                if (added)
                    edges.push_back({std::min(a, b), std::max(a, b), 0, 0,
                                     glm::length(mesh.positions[a] - mesh.positions[b])});
                Edge& e = edges[it->second];
                (a < b ? e.face_ab : e.face_ba) = f;
            }
        const std::size_t n = mesh.positions.size();
        std::vector<std::uint32_t> degree(n + 1, 0);
        for (const Edge& e : edges) ++degree[e.a], ++degree[e.b];
        first.assign(n + 1, 0);
        for (std::size_t v = 0; v < n; ++v) first[v + 1] = first[v] + degree[v];
        neighbour.resize(first[n]);
        edge_of.resize(first[n]);
        std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
        for (std::uint32_t i = 0; i < edges.size(); ++i) {
            const Edge& e = edges[i];
            neighbour[fill[e.a]] = e.b, edge_of[fill[e.a]++] = i;
            neighbour[fill[e.b]] = e.a, edge_of[fill[e.b]++] = i;
        }
    }
};

struct Loop {
    float length = std::numeric_limits<float>::infinity();
    std::vector<std::uint32_t> vertices;  // a simple cycle, consecutive ones joined by edges
};

// The shortest non-separating loop through `root` (Erickson and Whittlesey): shortest-path
// tree T from the root; of the other edges, a maximum spanning tree of the dual graph by
// loop length; the edges left over close the greedy system of loops, each non-separating
// (a dual cycle crosses it once), and the shortest of them is the answer.
Loop shortest_loop_through(const Mesh& mesh, const Connectivity& c, std::uint32_t root) {
    const std::size_t n = mesh.positions.size();
    std::vector<float> dist(n, std::numeric_limits<float>::infinity());
    std::vector<std::uint32_t> parent(n, root), parent_edge(n, UINT32_MAX);
    using Item = std::pair<float, std::uint32_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
    dist[root] = 0;
    queue.push({0.0f, root});
    while (!queue.empty()) {
        auto [d, v] = queue.top();
        queue.pop();
        if (d > dist[v]) continue;
        for (std::uint32_t i = c.first[v]; i < c.first[v + 1]; ++i) {
            const std::uint32_t w = c.neighbour[i], e = c.edge_of[i];
            const float nd = d + c.edges[e].length;
            if (nd < dist[w]) {
                dist[w] = nd;
                parent[w] = v;
                parent_edge[w] = e;
                queue.push({nd, w});
            }
        }
    }
    std::vector<bool> tree(c.edges.size(), false);
    for (std::size_t v = 0; v < n; ++v)
        if (parent_edge[v] != UINT32_MAX) tree[parent_edge[v]] = true;
    std::vector<std::pair<float, std::uint32_t>> others;  // (loop length, edge)
    for (std::uint32_t e = 0; e < c.edges.size(); ++e) {
        const auto& edge = c.edges[e];
        if (tree[e] || !std::isfinite(dist[edge.a]) || !std::isfinite(dist[edge.b])) continue;
        others.push_back({dist[edge.a] + edge.length + dist[edge.b], e});
    }
    std::sort(others.begin(), others.end(), [](const auto& x, const auto& y) {
        return x.first != y.first ? x.first > y.first : x.second < y.second;
    });
    DisjointSets faces(mesh.triangles.size());
    Loop best;
    std::uint32_t best_edge = UINT32_MAX;
    for (const auto& [length, e] : others)
        if (!faces.unite(c.edges[e].face_ab, c.edges[e].face_ba) && length < best.length) {
            best.length = length;
            best_edge = e;
        }
    if (best_edge == UINT32_MAX) return {};
    // The cycle: up from a to the lowest common ancestor, then down to b.
    const std::uint32_t a = c.edges[best_edge].a, b = c.edges[best_edge].b;
    std::vector<bool> on_a_path(n, false);
    for (std::uint32_t v = a;; v = parent[v]) {
        on_a_path[v] = true;
        if (v == root) break;
    }
    std::vector<std::uint32_t> from_b;
    std::uint32_t lca = b;
    while (!on_a_path[lca]) {
        from_b.push_back(lca);
        lca = parent[lca];
    }
    std::vector<std::uint32_t> from_a;
    for (std::uint32_t v = a; v != lca; v = parent[v]) from_a.push_back(v);
    best.vertices.push_back(lca);
    best.vertices.insert(best.vertices.end(), from_a.rbegin(), from_a.rend());
    best.vertices.insert(best.vertices.end(), from_b.begin(), from_b.end());
    return best;
}

// Cuts the mesh along the loop and closes both sides with a fan around its centroid.
// Returns false (mesh unchanged) when the loop is not a clean cycle of the surface.
bool cut_along(Mesh& mesh, const Connectivity& c, const std::vector<std::uint32_t>& loop) {
    const std::size_t k = loop.size();
    if (k < 3) return false;
    const std::vector<Triangle> original = mesh.triangles;
    const std::size_t first_new = mesh.positions.size();
    glm::vec3 centroid(0.0f);
    for (std::uint32_t v : loop) centroid += mesh.positions[v];
    centroid /= static_cast<float>(k);
    std::vector<std::uint32_t> twin(k);
    for (std::size_t i = 0; i < k; ++i) {
        twin[i] = static_cast<std::uint32_t>(mesh.positions.size());
        mesh.positions.push_back(mesh.positions[loop[i]]);
    }
    auto undo = [&] {
        mesh.triangles = original;
        mesh.positions.resize(first_new);
        return false;
    };
    // At each loop vertex, the faces left of the loop (swept counter-clockwise from the
    // outgoing edge to the incoming one) move to the twin vertex.
    for (std::size_t i = 0; i < k; ++i) {
        const std::uint32_t v = loop[i], next = loop[(i + 1) % k], prev = loop[(i + k - 1) % k];
        std::uint32_t a = next;
        for (int guard = 0;; ++guard) {
            auto found = c.face_of.find(key(v, a));
            if (found == c.face_of.end() || guard > 64) return undo();
            const std::uint32_t f = found->second;
            const Triangle& t = original[f];
            const int corner = t[0] == v ? 0 : t[1] == v ? 1 : 2;
            mesh.triangles[f][corner] = twin[i];
            const std::uint32_t w = t[(corner + 2) % 3];  // t = (v, a, w) in order
            if (w == prev) break;
            a = w;
        }
    }
    // Caps: the original side holds the edges next -> v, so its cap runs v -> next; the
    // twin side the other way round.
    if (k == 3) {
        mesh.triangles.push_back({loop[0], loop[1], loop[2]});
        mesh.triangles.push_back({twin[2], twin[1], twin[0]});
    } else {
        const auto centre = static_cast<std::uint32_t>(mesh.positions.size());
        mesh.positions.push_back(centroid);
        const auto centre_twin = static_cast<std::uint32_t>(mesh.positions.size());
        mesh.positions.push_back(centroid);
        for (std::size_t i = 0; i < k; ++i) {
            const std::size_t j = (i + 1) % k;
            mesh.triangles.push_back({centre, loop[i], loop[j]});
            mesh.triangles.push_back({centre_twin, twin[j], twin[i]});
        }
    }
    return true;
}

// check_topology() restricted to what a cut can change: the triangles around `changed`
// vertices. Every edge at such a vertex must have one face on each side, in opposite
// directions; every such vertex's faces must form one fan; no such face may be degenerate
// (the same threshold as check_topology: twice the area at most 2e-12 of the squared
// diagonal). A full check per cut costs a sort of every edge; this costs one scan.
bool closed_manifold_around(const Mesh& mesh, const std::vector<std::uint32_t>& changed,
                            double min_twice_area) {
    std::vector<bool> is_changed(mesh.positions.size(), false);
    for (std::uint32_t v : changed) is_changed[v] = true;
    std::unordered_map<std::uint64_t, int> balance;  // undirected edge -> +1 / -1 sum
    std::unordered_map<std::uint64_t, int> uses;     // undirected edge -> faces
    std::unordered_map<std::uint32_t, std::vector<std::pair<std::uint32_t, std::uint32_t>>>
        fans;  // vertex -> (a, b) of each face (v, a, b)
    for (const Triangle& t : mesh.triangles) {
        if (!is_changed[t[0]] && !is_changed[t[1]] && !is_changed[t[2]]) continue;
        const glm::dvec3 a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] ||
            !(glm::length(glm::cross(b - a, c - a)) > min_twice_area))
            return false;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t u = t[k], v = t[(k + 1) % 3];
            if (is_changed[u]) fans[u].emplace_back(v, t[(k + 2) % 3]);
            if (!is_changed[u] && !is_changed[v]) continue;
            const std::uint64_t e = u < v ? key(u, v) : key(v, u);
            balance[e] += u < v ? 1 : -1;
            ++uses[e];
        }
    }
    for (const auto& [e, n] : uses)
        if (n != 2 || balance[e] != 0) return false;
    for (auto& [v, fan] : fans) {
        // One cycle a -> b -> ... through all of v's faces.
        std::unordered_map<std::uint32_t, std::uint32_t> next;
        for (const auto& [a, b] : fan)
            if (!next.emplace(a, b).second) return false;
        std::uint32_t at = fan.front().first;
        for (std::size_t steps = 0; steps < fan.size(); ++steps) {
            auto found = next.find(at);
            if (found == next.end()) return false;
            at = found->second;
            if (at == fan.front().first && steps + 1 != fan.size()) return false;
        }
        if (at != fan.front().first) return false;
    }
    return true;
}

}  // namespace

std::size_t genus(const Mesh& mesh) {
    DisjointSets sets(mesh.positions.size());
    for (const Triangle& t : mesh.triangles) {
        sets.unite(t[0], t[1]);
        sets.unite(t[1], t[2]);
    }
    std::vector<long> vertices(mesh.positions.size(), 0), faces(mesh.positions.size(), 0);
    std::vector<bool> used(mesh.positions.size(), false);
    for (const Triangle& t : mesh.triangles) {
        ++faces[sets.find(t[0])];
        for (std::uint32_t v : t) used[v] = true;
    }
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v)
        if (used[v]) ++vertices[sets.find(v)];
    long total = 0;
    for (std::uint32_t r = 0; r < mesh.positions.size(); ++r)
        if (faces[r] > 0) total += (2 - (vertices[r] - faces[r] / 2)) / 2;  // chi = V - E + F
    return static_cast<std::size_t>(std::max(total, 0L));
}

std::size_t cut_handles(Mesh& mesh, std::size_t max_cuts, CancelFlag cancel) {
    constexpr std::size_t kRoots = 64;  // loops are sought through this many sample vertices
    std::size_t cuts = 0;
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (const glm::vec3& p : mesh.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const double diagonal2 =
        mesh.positions.empty() ? 0.0 : glm::dot(glm::dvec3(hi - lo), glm::dvec3(hi - lo));
    const double min_twice_area = 2e-12 * diagonal2;  // check_topology's threshold
    while (cuts < max_cuts) {
        throw_if_cancelled(cancel);
        std::size_t g = genus(mesh);
        if (g == 0) break;
        const Connectivity c(mesh);
        const std::size_t n = mesh.positions.size();
        const std::size_t step = std::max<std::size_t>(1, n / kRoots);
        // One slot per root, filled in parallel (the searches only read the mesh), then
        // sorted in slot order: the same loops in the same order on any thread count.
        std::vector<Loop> loops((n + step - 1) / step);
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, loops.size()), [&](const auto& range) {
            for (std::size_t i = range.begin(); i < range.end(); ++i) {
                // One search walks the whole mesh (tens of ms on a large one): poll each.
                if (is_cancelled(cancel)) return;
                loops[i] = shortest_loop_through(mesh, c, static_cast<std::uint32_t>(i * step));
            }
        });
        throw_if_cancelled(cancel);
        std::erase_if(loops, [](const Loop& l) { return l.vertices.empty(); });
        std::stable_sort(loops.begin(), loops.end(),
                         [](const Loop& x, const Loop& y) { return x.length < y.length; });
        // Several cuts per round, each away from the ones before it (the connectivity
        // above describes the mesh before this round's cuts).
        std::vector<bool> touched(n, false);
        std::size_t cut_this_round = 0;
        for (const Loop& loop : loops) {
            if (cuts == max_cuts) break;
            throw_if_cancelled(cancel);  // each cut copies and checks the whole mesh
            if (std::any_of(loop.vertices.begin(), loop.vertices.end(),
                            [&](std::uint32_t v) { return touched[v]; }))
                continue;
            const Mesh before = mesh;
            if (!cut_along(mesh, c, loop.vertices)) continue;
            std::vector<std::uint32_t> changed = loop.vertices;
            for (auto v = static_cast<std::uint32_t>(before.positions.size());
                 v < mesh.positions.size(); ++v)
                changed.push_back(v);  // twins and cap centres
            if (genus(mesh) + 1 != g || !closed_manifold_around(mesh, changed, min_twice_area)) {
                mesh = before;
                continue;
            }
            g -= 1;
            ++cuts;
            ++cut_this_round;
            for (std::uint32_t v : loop.vertices) {
                touched[v] = true;
                for (std::uint32_t i = c.first[v]; i < c.first[v + 1]; ++i)
                    touched[c.neighbour[i]] = true;
            }
        }
        if (cut_this_round == 0) break;
    }
    return cuts;
}

}  // namespace sylva
