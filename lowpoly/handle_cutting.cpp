#include "lowpoly/handle_cutting.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <queue>
#include <unordered_map>
#include <vector>

#include "core/disjoint_sets.h"

namespace sylva {
namespace {

using Triangle = std::array<std::uint32_t, 3>;
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

std::uint64_t key(std::uint32_t a, std::uint32_t b) {
    return (std::uint64_t{a} << 32) | b;
}

// Edges, faces per edge and vertex neighbours of a closed, oriented triangle mesh, in flat
// arrays (no hashing: the opposite of a -> b is found among the few edges leaving b).
struct Connectivity {
    struct Edge {
        std::uint32_t a, b;                      // a < b
        std::uint32_t face_ab = 0, face_ba = 0;  // the faces holding a->b and b->a
        float length = 0;
    };
    std::vector<Edge> edges;
    // CSR: vertex v's neighbours neighbour[first[v] .. first[v + 1]), with the face that
    // holds v -> neighbour and the edge between them.
    std::vector<std::uint32_t> first, neighbour, face, edge_of;

    explicit Connectivity(const Mesh& mesh) {
        const std::size_t n = mesh.positions.size();
        first.assign(n + 1, 0);
        for (const Triangle& t : mesh.triangles)
            for (std::uint32_t v : t) ++first[v + 1];
        for (std::size_t v = 0; v < n; ++v) first[v + 1] += first[v];
        neighbour.resize(first[n]);
        face.resize(first[n]);
        edge_of.assign(first[n], kNone);
        std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
        for (std::uint32_t f = 0; f < mesh.triangles.size(); ++f)
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t a = mesh.triangles[f][k], b = mesh.triangles[f][(k + 1) % 3];
                neighbour[fill[a]] = b;
                face[fill[a]++] = f;
            }
        edges.reserve(first[n] / 2);
        for (std::uint32_t a = 0; a < n; ++a)
            for (std::uint32_t i = first[a]; i < first[a + 1]; ++i) {
                const std::uint32_t b = neighbour[i];
                if (b < a) continue;
                const std::uint32_t j = slot(b, a);
                if (j == kNone) continue;  // not closed; the cut checks refuse such loops
                edge_of[i] = edge_of[j] = static_cast<std::uint32_t>(edges.size());
                edges.push_back(
                    {a, b, face[i], face[j], glm::length(mesh.positions[a] - mesh.positions[b])});
            }
    }

    // The CSR slot of from -> to, or kNone.
    std::uint32_t slot(std::uint32_t from, std::uint32_t to) const {
        for (std::uint32_t i = first[from]; i < first[from + 1]; ++i)
            if (neighbour[i] == to) return i;
        return kNone;
    }
    // The face that holds from -> to, or kNone.
    std::uint32_t face_of(std::uint32_t from, std::uint32_t to) const {
        const std::uint32_t i = slot(from, to);
        return i == kNone ? kNone : face[i];
    }
};

struct Loop {
    float length = std::numeric_limits<float>::infinity();
    std::vector<std::uint32_t> vertices;  // a simple cycle, consecutive ones joined by edges
};

// Roots about `wanted` of them, spread over the surface: the first vertex (by index) in
// each cell of a grid whose cells hold about area / wanted of it. Deterministic.
std::vector<std::uint32_t> spread_roots(const Mesh& mesh, const Connectivity& c,
                                        std::size_t wanted) {
    std::vector<std::uint32_t> roots;
    if (wanted <= 1) {
        for (std::uint32_t v = 0; v + 1 < c.first.size(); ++v)
            if (c.first[v] != c.first[v + 1]) return {v};
        return {};
    }
    double area = 0.0;
    for (const Triangle& t : mesh.triangles)
        area += 0.5 * glm::length(glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]],
                                             mesh.positions[t[2]] - mesh.positions[t[0]]));
    // A cell of side s holds about 1.5 s^2 of a curved surface.
    const double side = std::sqrt(1.5 * area / static_cast<double>(wanted));
    if (!(side > 0.0)) return spread_roots(mesh, c, 1);
    std::unordered_map<std::uint64_t, std::uint32_t> first_in_cell;
    for (std::uint32_t v = 0; v + 1 < c.first.size(); ++v) {
        if (c.first[v] == c.first[v + 1]) continue;
        const glm::dvec3 q = glm::floor(glm::dvec3(mesh.positions[v]) / side);
        const auto coordinate = [](double x) {
            return static_cast<std::uint64_t>(static_cast<std::int64_t>(x) & 0x1fffff);
        };
        const std::uint64_t cell =
            (coordinate(q.x) << 42) | (coordinate(q.y) << 21) | coordinate(q.z);
        if (first_in_cell.try_emplace(cell, v).second) roots.push_back(v);
    }
    return roots;  // in vertex order, as found
}

// Short non-separating loops through many roots at once. Erickson and Whittlesey's greedy
// system of loops takes a shortest-path tree from one root; here the tree is a forest of
// shortest paths from every root (each vertex hangs from its nearest root, a cell per
// root), joined into one spanning tree by edges between cells. Of the other edges, a
// maximum spanning tree of the dual graph by loop length (edges between cells first:
// their loops would wander through other cells); each edge left over closes a loop that
// crosses the dual tree once, so it does not separate the surface. Every such loop inside a
// cell is a candidate (up from both ends of its edge to where their paths to the root meet),
// measured through the root as the dual tree weighs it, longest first: cut_handles() takes
// the shortest ones that keep apart. (Every candidate, not only each cell's shortest, lets a
// round cut more handles, so fewer rounds are needed; weighed through the root rather than
// by the loop alone, the cuts chosen leave a smaller mean error.)
std::vector<Loop> loops_through(const Mesh& mesh, const Connectivity& c,
                                std::vector<std::uint32_t> roots) {
    const std::size_t n = mesh.positions.size();
    std::vector<float> dist(n, std::numeric_limits<float>::infinity());
    std::vector<std::uint32_t> parent(n, kNone), parent_edge(n, kNone), cell(n, kNone);
    using Item = std::pair<float, std::uint32_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
    auto grow = [&] {
        while (!queue.empty()) {
            auto [d, v] = queue.top();
            queue.pop();
            if (d > dist[v]) continue;
            for (std::uint32_t i = c.first[v]; i < c.first[v + 1]; ++i) {
                const std::uint32_t w = c.neighbour[i], e = c.edge_of[i];
                if (e == kNone) continue;
                const float nd = d + c.edges[e].length;
                if (nd < dist[w]) {
                    dist[w] = nd;
                    parent[w] = v;
                    parent_edge[w] = e;
                    cell[w] = cell[v];
                    queue.push({nd, w});
                }
            }
        }
    };
    auto plant = [&](std::uint32_t r) {
        dist[r] = 0.0f;
        parent[r] = r;
        cell[r] = r;
        queue.push({0.0f, r});
    };
    for (std::uint32_t r : roots) plant(r);
    grow();
    // A piece without a root gets one.
    for (std::uint32_t v = 0; v < n; ++v)
        if (cell[v] == kNone && c.first[v] != c.first[v + 1]) {
            roots.push_back(v);
            plant(v);
            grow();
        }

    std::vector<std::uint8_t> tree(c.edges.size(), 0);
    for (std::uint32_t v = 0; v < n; ++v)
        if (parent_edge[v] != kNone) tree[parent_edge[v]] = 1;
    // Join the cells: a spanning tree of the cell graph from edges between cells.
    DisjointSets cells(n);
    std::vector<std::uint32_t> between;                   // the other edges between cells
    std::vector<std::pair<float, std::uint32_t>> inside;  // (loop length, edge) within a cell
    for (std::uint32_t e = 0; e < c.edges.size(); ++e) {
        if (tree[e]) continue;
        const auto& edge = c.edges[e];
        if (cell[edge.a] == kNone || cell[edge.b] == kNone) continue;
        if (cell[edge.a] != cell[edge.b]) {
            if (cells.unite(cell[edge.a], cell[edge.b]))
                tree[e] = 1;
            else
                between.push_back(e);
        } else {
            inside.push_back({dist[edge.a] + edge.length + dist[edge.b], e});
        }
    }
    std::sort(inside.begin(), inside.end(), [](const auto& x, const auto& y) {
        return x.first != y.first ? x.first > y.first : x.second < y.second;
    });
    DisjointSets faces(mesh.triangles.size());
    for (std::uint32_t e : between) faces.unite(c.edges[e].face_ab, c.edges[e].face_ba);
    std::vector<std::pair<float, std::uint32_t>> closing;  // (loop length, edge)
    for (const auto& [length, e] : inside)
        if (!faces.unite(c.edges[e].face_ab, c.edges[e].face_ba)) closing.push_back({length, e});
    // Each loop: up from a to the lowest common ancestor, then down to b.
    std::vector<Loop> loops;
    std::vector<std::uint8_t> on_a_path(n, 0);
    for (const auto& [length, e] : closing) {
        const std::uint32_t r = cell[c.edges[e].a];
        const std::uint32_t a = c.edges[e].a, b = c.edges[e].b;
        std::vector<std::uint32_t> from_a;
        for (std::uint32_t v = a;; v = parent[v]) {
            on_a_path[v] = 1;
            if (v == r) break;
        }
        std::vector<std::uint32_t> from_b;
        std::uint32_t lca = b;
        while (!on_a_path[lca]) {
            from_b.push_back(lca);
            lca = parent[lca];
        }
        for (std::uint32_t v = a;; v = parent[v]) {
            on_a_path[v] = 0;
            if (v == r) break;
        }
        for (std::uint32_t v = a; v != lca; v = parent[v]) from_a.push_back(v);
        Loop loop;
        loop.length = length;
        loop.vertices.push_back(lca);
        loop.vertices.insert(loop.vertices.end(), from_a.rbegin(), from_a.rend());
        loop.vertices.insert(loop.vertices.end(), from_b.begin(), from_b.end());
        loops.push_back(std::move(loop));
    }
    return loops;
}

// Where a loop's caps meet: the mean of its vertices (as stored, in floats).
glm::vec3 centroid(const Mesh& mesh, const std::vector<std::uint32_t>& loop) {
    glm::vec3 sum(0.0f);
    for (std::uint32_t v : loop) sum += mesh.positions[v];
    return sum / static_cast<float>(loop.size());
}

// A planned cut: at each loop vertex, the faces left of the loop (swept counter-clockwise
// from the outgoing edge to the incoming one) move to a twin vertex.
struct Cut {
    const Loop* loop = nullptr;
    std::vector<std::pair<std::uint32_t, int>> moved;  // (face, corner) -> twin of that corner
    std::vector<int> moved_vertex;                     // loop index per moved corner
    std::uint32_t left_face = kNone, right_face = kNone;
};

// Plans the cut along `loop`; false when the loop is not a clean cycle of the surface or a
// cap triangle would be a sliver (check_topology's zero-area threshold).
bool plan_cut(const Mesh& mesh, const Connectivity& c, const Loop& loop, double min_twice_area,
              Cut& cut) {
    const std::vector<std::uint32_t>& l = loop.vertices;
    const std::size_t k = l.size();
    if (k < 3) return false;
    cut.loop = &loop;
    cut.moved.clear();
    cut.moved_vertex.clear();
    for (std::size_t i = 0; i < k; ++i) {
        const std::uint32_t v = l[i], next = l[(i + 1) % k], prev = l[(i + k - 1) % k];
        std::uint32_t a = next;
        for (int guard = 0;; ++guard) {
            const std::uint32_t f = c.face_of(v, a);
            if (f == kNone || guard > 64) return false;
            const Triangle& t = mesh.triangles[f];
            const int corner = t[0] == v ? 0 : t[1] == v ? 1 : 2;
            cut.moved.emplace_back(f, corner);
            cut.moved_vertex.push_back(static_cast<int>(i));
            const std::uint32_t w = t[(corner + 2) % 3];  // t = (v, a, w) in order
            if (w == prev) break;
            a = w;
        }
    }
    cut.left_face = c.face_of(l[0], l[1]);
    cut.right_face = c.face_of(l[1], l[0]);
    if (cut.left_face == kNone || cut.right_face == kNone) return false;
    // The caps (the triangle itself, or a fan around the centroid) must not be slivers.
    auto fat = [&](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& p) {
        return glm::length(glm::cross(a - p, b - p)) > min_twice_area;
    };
    if (k == 3)
        return fat(glm::dvec3(mesh.positions[l[0]]), glm::dvec3(mesh.positions[l[1]]),
                   glm::dvec3(mesh.positions[l[2]]));
    const glm::dvec3 centre(centroid(mesh, l));
    for (std::size_t i = 0; i < k; ++i)
        if (!fat(glm::dvec3(mesh.positions[l[i]]), glm::dvec3(mesh.positions[l[(i + 1) % k]]),
                 centre))
            return false;
    return true;
}

// Makes a planned cut: twins, faces moved to them, caps on both sides. The original side
// holds the edges next -> v, so its cap runs v -> next; the twin side the other way round.
void make_cut(Mesh& mesh, const Cut& cut) {
    const std::vector<std::uint32_t>& l = cut.loop->vertices;
    const std::size_t k = l.size();
    const glm::vec3 centre_point = centroid(mesh, l);
    std::vector<std::uint32_t> twin(k);
    for (std::size_t i = 0; i < k; ++i) {
        twin[i] = static_cast<std::uint32_t>(mesh.positions.size());
        mesh.positions.push_back(mesh.positions[l[i]]);
    }
    for (std::size_t m = 0; m < cut.moved.size(); ++m)
        mesh.triangles[cut.moved[m].first][cut.moved[m].second] =
            twin[static_cast<std::size_t>(cut.moved_vertex[m])];
    if (k == 3) {
        mesh.triangles.push_back({l[0], l[1], l[2]});
        mesh.triangles.push_back({twin[2], twin[1], twin[0]});
        return;
    }
    const auto centre = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.push_back(centre_point);
    const auto centre_twin = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.push_back(centre_point);
    for (std::size_t i = 0; i < k; ++i) {
        const std::size_t j = (i + 1) % k;
        mesh.triangles.push_back({centre, l[i], l[j]});
        mesh.triangles.push_back({centre_twin, twin[j], twin[i]});
    }
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

// The vertices a cut adds or changes: the loop's and everything appended since `before`.
void add_changed(const Mesh& mesh, const Cut& cut, std::size_t first_new,
                 std::vector<std::uint32_t>& changed) {
    changed.insert(changed.end(), cut.loop->vertices.begin(), cut.loop->vertices.end());
    for (auto v = static_cast<std::uint32_t>(first_new); v < mesh.positions.size(); ++v)
        changed.push_back(v);
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
    std::size_t cuts = 0;
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (const glm::vec3& p : mesh.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const double diagonal2 =
        mesh.positions.empty() ? 0.0 : glm::dot(glm::dvec3(hi - lo), glm::dvec3(hi - lo));
    const double min_twice_area = 2e-12 * diagonal2;  // check_topology's threshold
    std::size_t g = genus(mesh);
    // Roots per round: a few per handle, so that most handles have a cell with a loop
    // around them; fewer (down to one, the plain greedy system) when a round finds none.
    std::size_t divisor = 1;
    while (cuts < max_cuts && g > 0) {
        throw_if_cancelled(cancel);
        const Connectivity c(mesh);
        const std::size_t wanted_roots = std::max<std::size_t>(1, (4 * g + 4) / divisor);
        std::vector<Loop> loops = loops_through(mesh, c, spread_roots(mesh, c, wanted_roots));
        throw_if_cancelled(cancel);
        std::stable_sort(loops.begin(), loops.end(),
                         [](const Loop& x, const Loop& y) { return x.length < y.length; });
        // Shortest loops first, each apart from the ones before it by a ring of vertices
        // (the connectivity above describes the mesh before this round's cuts).
        const std::size_t n = mesh.positions.size();
        std::vector<std::uint8_t> touched(n, 0);
        std::vector<Cut> planned;
        for (const Loop& loop : loops) {
            if (planned.size() == max_cuts - cuts) break;
            if (std::any_of(loop.vertices.begin(), loop.vertices.end(),
                            [&](std::uint32_t v) { return touched[v]; }))
                continue;
            Cut cut;
            if (!plan_cut(mesh, c, loop, min_twice_area, cut)) continue;
            for (std::uint32_t v : loop.vertices) {
                touched[v] = 1;
                for (std::uint32_t i = c.first[v]; i < c.first[v + 1]; ++i)
                    touched[c.neighbour[i]] = 1;
            }
            planned.push_back(std::move(cut));
        }
        // Each loop alone does not separate the surface, but several together can (two
        // loops around the same tube). The loops cut the surface into regions; a loop left
        // uncut joins the two it runs between. Keep uncut a spanning forest of the regions,
        // longest loops first, and cut the rest: the surface stays in one piece, and every
        // cut removes a handle.
        std::vector<std::uint8_t> on_loop(c.edges.size(), 0);
        for (const Cut& cut : planned) {
            const std::vector<std::uint32_t>& l = cut.loop->vertices;
            for (std::size_t i = 0; i < l.size(); ++i)
                on_loop[c.edge_of[c.slot(l[i], l[(i + 1) % l.size()])]] = 1;
        }
        DisjointSets regions(mesh.triangles.size());
        for (std::uint32_t e = 0; e < c.edges.size(); ++e)
            if (!on_loop[e]) regions.unite(c.edges[e].face_ab, c.edges[e].face_ba);
        std::vector<const Cut*> chosen;
        for (auto it = planned.rbegin(); it != planned.rend(); ++it)
            if (!regions.unite(it->left_face, it->right_face)) chosen.push_back(&*it);
        std::reverse(chosen.begin(), chosen.end());  // shortest first again

        const Mesh before = mesh;
        std::vector<std::uint32_t> changed;
        for (const Cut* cut : chosen) {
            const std::size_t first_new = mesh.positions.size();
            make_cut(mesh, *cut);
            add_changed(mesh, *cut, first_new, changed);
        }
        std::size_t made = chosen.size();
        if (made > 0 &&
            (genus(mesh) + made != g || !closed_manifold_around(mesh, changed, min_twice_area))) {
            // Never seen: one at a time, each checked on its own.
            mesh = before;
            made = 0;
            for (const Cut* cut : chosen) {
                throw_if_cancelled(cancel);
                const Mesh one_before = mesh;
                const std::size_t first_new = mesh.positions.size();
                make_cut(mesh, *cut);
                changed.clear();
                add_changed(mesh, *cut, first_new, changed);
                if (genus(mesh) + made + 1 != g ||
                    !closed_manifold_around(mesh, changed, min_twice_area)) {
                    mesh = one_before;
                    continue;
                }
                ++made;
            }
        }
        g -= made;
        cuts += made;
        if (made == 0) {
            if (wanted_roots == 1) break;
            divisor *= 4;
        }
    }
    return cuts;
}

}  // namespace sylva
