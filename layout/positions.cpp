#include "layout/positions.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/errors.h"
#include "core/random.h"
#include "layout/geometry.h"

namespace sylva::layout {

std::vector<std::vector<double>> null_space(std::vector<double> a, int rows, int cols) {
    auto at = [&](int r, int c) -> double& { return a[static_cast<std::size_t>(r) * cols + c]; };
    std::vector<int> pivot_col;
    int row = 0;
    for (int c = 0; c < cols && row < rows; ++c) {
        int best = row;
        for (int r = row + 1; r < rows; ++r)
            if (std::abs(at(r, c)) > std::abs(at(best, c))) best = r;
        if (std::abs(at(best, c)) < 1e-9) continue;
        for (int k = 0; k < cols; ++k) std::swap(at(row, k), at(best, k));
        const double inv = 1.0 / at(row, c);
        for (int k = 0; k < cols; ++k) at(row, k) *= inv;
        for (int r = 0; r < rows; ++r) {
            if (r == row || at(r, c) == 0.0) continue;
            const double f = at(r, c);
            for (int k = 0; k < cols; ++k) at(r, k) -= f * at(row, k);
        }
        pivot_col.push_back(c);
        ++row;
    }
    std::vector<char> is_pivot(cols, 0);
    for (int c : pivot_col) is_pivot[c] = 1;
    std::vector<std::vector<double>> basis;
    for (int free = 0; free < cols; ++free) {
        if (is_pivot[free]) continue;
        std::vector<double> v(cols, 0.0);
        v[free] = 1.0;
        for (std::size_t r = 0; r < pivot_col.size(); ++r)
            v[pivot_col[r]] = -at(static_cast<int>(r), free);
        basis.push_back(std::move(v));
    }
    return basis;
}

namespace {

// Modified Gram-Schmidt, in place; drops dependent vectors.
void orthonormalize(std::vector<std::vector<double>>& basis) {
    std::vector<std::vector<double>> out;
    for (auto v : basis) {
        for (const auto& q : out) {
            double d = 0;
            for (std::size_t i = 0; i < v.size(); ++i) d += v[i] * q[i];
            for (std::size_t i = 0; i < v.size(); ++i) v[i] -= d * q[i];
        }
        double n = 0;
        for (double x : v) n += x * x;
        n = std::sqrt(n);
        if (n < 1e-9) continue;
        for (double& x : v) x /= n;
        out.push_back(std::move(v));
    }
    basis = std::move(out);
}

std::vector<double> project(const std::vector<std::vector<double>>& q,
                            const std::vector<double>& t) {
    std::vector<double> s(t.size(), 0.0);
    for (const auto& b : q) {
        double d = 0;
        for (std::size_t i = 0; i < t.size(); ++i) d += b[i] * t[i];
        for (std::size_t i = 0; i < t.size(); ++i) s[i] += d * b[i];
    }
    return s;
}

}  // namespace

std::optional<PolygonMesh> realize(const AngleGraph& g, const Directions& dirs, std::uint64_t seed,
                                   int attempts) {
    const Analysis a = analyze(g, dirs);
    if (!a.planar || !a.complete) return std::nullopt;
    const int nv = static_cast<int>(g.vertices.size());
    // Edges: one per dart pair, named by the dart leaving the smaller vertex.
    std::map<std::pair<int, int>, int> edge_of;  // (vertex, dart) -> edge
    std::vector<int> edge_dir;
    std::vector<double> edge_mean;  // the example's mean length of edges with this label
    for (int v = 0; v < nv; ++v)
        for (int i = 0; i < static_cast<int>(g.vertices[v].size()); ++i) {
            const Dart& d = g.vertices[v][i];
            if (d.to < v) continue;
            const int e = static_cast<int>(edge_dir.size());
            edge_dir.push_back(d.dir);
            const Label l = dart_label(g, v, i);
            const std::size_t code =
                (static_cast<std::size_t>(l.dir) * dirs.colors() + l.left) * dirs.colors() +
                l.right;
            const double by_label = code < dirs.label_length.size() ? dirs.label_length[code] : 0.0;
            edge_mean.push_back(by_label > 0 ? by_label : dirs.mean_length[d.dir]);
            edge_of[{v, i}] = e;
            edge_of[{d.to, g.find(d.to, dirs.opposite[d.dir])}] = e;
        }
    const int ne = static_cast<int>(edge_dir.size());
    auto unit = [&](int dir) {
        const double r = dirs.degrees[dir] * M_PI / 180.0;
        glm::dvec2 u(std::cos(r), std::sin(r));
        // Axis directions exactly: cos(90 degrees) in doubles is 6e-17, not 0.
        for (int k = 0; k < 2; ++k)
            if (std::abs(u[k]) < 1e-12) u[k] = 0.0;
        return u;
    };
    // Closed faces: the steps sum to zero. (Sign: a dart's step is +s along its own direction,
    // and an edge's direction is that of its named dart, so the reverse dart contributes -s.)
    std::vector<double> rows;
    int nrows = 0;
    for (const Walk& w : a.walks) {
        if (w.turning > 0) continue;
        std::vector<double> rx(ne, 0.0), ry(ne, 0.0);
        for (const auto& [v, i] : w.darts) {
            const int e = edge_of.at({v, i});
            const double sign = g.vertices[v][i].dir == edge_dir[e] ? 1.0 : -1.0;
            const glm::dvec2 u = unit(edge_dir[e]);
            rx[e] += sign * u.x;
            ry[e] += sign * u.y;
        }
        rows.insert(rows.end(), rx.begin(), rx.end());
        rows.insert(rows.end(), ry.begin(), ry.end());
        nrows += 2;
    }
    std::vector<std::vector<double>> basis = null_space(rows, nrows, ne);
    orthonormalize(basis);
    if (basis.empty()) return std::nullopt;
    Random rng(seed);
    for (int attempt = 0; attempt < attempts; ++attempt) {
        std::vector<double> lo(ne), t(ne);
        for (int e = 0; e < ne; ++e) {
            const double mean = edge_mean[e];
            lo[e] = 0.3 * mean;
            t[e] = mean * (0.5 + rng.uniform());
        }
        std::vector<double> s = project(basis, t);
        bool ok = false;
        for (int iter = 0; iter < 60 && !ok; ++iter) {
            ok = true;
            for (int e = 0; e < ne; ++e)
                if (s[e] < lo[e] * 0.999) ok = false;
            if (ok) break;
            for (int e = 0; e < ne; ++e) t[e] = std::max(s[e], lo[e] * 1.2);
            s = project(basis, t);
        }
        if (!ok) continue;
        // Positions along a spanning tree from vertex 0.
        std::vector<glm::dvec2> pos(nv);
        std::vector<char> placed(nv, 0);
        std::vector<int> stack{0};
        placed[0] = 1;
        while (!stack.empty()) {
            const int v = stack.back();
            stack.pop_back();
            for (int i = 0; i < static_cast<int>(g.vertices[v].size()); ++i) {
                const Dart& d = g.vertices[v][i];
                if (placed[d.to]) continue;
                placed[d.to] = 1;
                pos[d.to] = pos[v] + s[edge_of.at({v, i})] * unit(d.dir);
                stack.push_back(d.to);
            }
        }
        // Polygons: the closed faces with a colour, counter-clockwise.
        PolygonMesh mesh;
        mesh.vertices = pos;
        for (const Walk& w : a.walks) {
            if (w.turning > 0 || w.color <= 0) continue;
            Polygon p;
            p.color = dirs.palette[w.color];
            for (auto it = w.darts.rbegin(); it != w.darts.rend(); ++it)
                p.vertices.push_back(g.vertices[it->first][it->second].to);
            mesh.polygons.push_back(std::move(p));
        }
        // Every edge of the drawing must keep clear of every other.
        double extent = 1e-12;
        for (const glm::dvec2& p : pos) extent = std::max({extent, std::abs(p.x), std::abs(p.y)});
        const double eps = extent * 1e-7;
        bool planar = true;
        std::vector<std::pair<int, int>> segs;
        for (const auto& [key, e] : edge_of)
            if (g.vertices[key.first][key.second].dir == edge_dir[e])
                segs.emplace_back(key.first, g.vertices[key.first][key.second].to);
        for (std::size_t i = 0; i < segs.size() && planar; ++i)
            for (std::size_t j = i + 1; j < segs.size() && planar; ++j) {
                const auto [p, q] = segs[i];
                const auto [r, u] = segs[j];
                if (p == r || p == u || q == r || q == u) continue;
                if (segments_touch(pos[p], pos[q], pos[r], pos[u], eps)) planar = false;
            }
        if (!planar) continue;
        try {
            validate_mesh(mesh, "generated");
        } catch (const InputError&) {
            continue;
        }
        return mesh;
    }
    return std::nullopt;
}

std::vector<PolygonMesh> generate_layouts(const Grammar& grammar, int count, std::uint64_t seed,
                                          const GenerateSettings& settings) {
    std::vector<PolygonMesh> out;
    Random seeds(seed);
    for (int i = 0; i < count; ++i) {
        const std::uint64_t base = seeds.next();
        std::optional<PolygonMesh> mesh;
        // A graph that cannot be drawn is grown again from another seed, then with fewer steps.
        // Last: a bare starter rule, sampled longer.
        for (int retry = 0; retry <= 16 && !mesh; ++retry) {
            GenerateSettings s = settings;
            s.steps = settings.steps * (16 - retry) / 16;
            const AngleGraph g = derive_graph(grammar, base + 0x9e37u * retry, s);
            mesh = realize(g, grammar.dirs, base ^ 0x5bd1e995u, retry == 16 ? 200 : 12);
        }
        if (!mesh)
            throw InputError("no drawable layout found from this grammar (variation " +
                             std::to_string(i) + ")");
        out.push_back(std::move(*mesh));
    }
    return out;
}

}  // namespace sylva::layout
