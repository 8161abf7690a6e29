#include "layout/angle_graph.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <map>

#include "core/errors.h"

namespace sylva::layout {

namespace {

constexpr double kTurnTolerance = 1e-6;

bool near(double a, double b) {
    return std::abs(a - b) < kTurnTolerance;
}

double ccw_gap(const Directions& dirs, int from, int to) {
    double d = dirs.degrees[to] - dirs.degrees[from];
    if (d <= kTurnTolerance) d += 360.0;
    return d;
}

}  // namespace

int AngleGraph::half_edges() const {
    int n = 0;
    for (const auto& v : vertices)
        for (const Dart& d : v) n += d.to < 0;
    return n;
}

int AngleGraph::edges() const {
    int n = 0;
    for (const auto& v : vertices)
        for (const Dart& d : v) n += d.to >= 0;
    return n / 2;
}

Label dart_label(const AngleGraph& g, int v, int i) {
    return {g.vertices[v][i].dir, g.vertices[v][i].left, g.right(v, i)};
}

Label reversed(const Label& l, const Directions& dirs) {
    return {dirs.opposite[l.dir], l.right, l.left};
}

double base_turn(const Directions& dirs, int a, int b) {
    double d = dirs.degrees[b] - dirs.degrees[a];
    if (d < 0) d += 360.0;
    return d;
}

void set_wraps(Boundary& b, const Directions& dirs) {
    for (std::size_t i = 0; i < b.size(); ++i) {
        const BoundaryItem& next = b[(i + 1) % b.size()];
        b[i].wraps = static_cast<int>(
            std::lround((b[i].turn - base_turn(dirs, b[i].label.dir, next.label.dir)) / 360.0));
    }
}

int boundary_match(const Boundary& a, const Boundary& b) {
    const std::size_t n = a.size();
    if (n != b.size()) return -1;
    if (n == 0) return 0;
    for (std::size_t r = 0; r < n; ++r) {
        bool same = true;
        for (std::size_t i = 0; i < n && same; ++i) {
            const BoundaryItem& x = a[i];
            const BoundaryItem& y = b[(i + r) % n];
            same = x.label == y.label && x.wraps == y.wraps;
        }
        if (same) return static_cast<int>(r);
    }
    return -1;
}

Analysis analyze(const AngleGraph& g, const Directions& dirs) {
    Analysis out;
    const int nv = static_cast<int>(g.vertices.size());
    if (nv == 0) {
        out.why = "empty graph";
        return out;
    }
    // Darts must pair up: v -> w in direction d has w -> v in the opposite direction, with the
    // colours swapped.
    for (int v = 0; v < nv; ++v) {
        const auto& ds = g.vertices[v];
        if (ds.empty()) {
            out.why = "a vertex without edges";
            return out;
        }
        for (std::size_t i = 0; i < ds.size(); ++i) {
            if (i > 0 && ds[i].dir <= ds[i - 1].dir) {
                out.why = "darts not in counter-clockwise order";
                return out;
            }
            if (ds[i].to < 0) continue;
            const int w = ds[i].to;
            if (w >= nv) {
                out.why = "an edge to a missing vertex";
                return out;
            }
            const int j = g.find(w, dirs.opposite[ds[i].dir]);
            if (j < 0 || g.vertices[w][j].to != v ||
                reversed(dart_label(g, v, static_cast<int>(i)), dirs) != dart_label(g, w, j)) {
                out.why = "an edge whose two ends disagree";
                return out;
            }
        }
    }
    // Connected.
    std::vector<int> seen(nv, 0), stack{0};
    seen[0] = 1;
    int reached = 1;
    while (!stack.empty()) {
        const int v = stack.back();
        stack.pop_back();
        for (const Dart& d : g.vertices[v])
            if (d.to >= 0 && !seen[d.to]) seen[d.to] = 1, ++reached, stack.push_back(d.to);
    }
    if (reached != nv) {
        out.why = "not connected";
        return out;
    }
    // Face walks: leave along a dart with the face on the right; at the next vertex take the
    // next dart counter-clockwise from the one we came in on. A half-edge is walked out and
    // back round its open end (a +180 turn, whose middle is the half-edge's place on the
    // boundary).
    std::vector<std::vector<char>> used(nv);
    for (int v = 0; v < nv; ++v) used[v].assign(g.vertices[v].size(), 0);
    for (int v0 = 0; v0 < nv; ++v0)
        for (int i0 = 0; i0 < static_cast<int>(g.vertices[v0].size()); ++i0) {
            if (used[v0][i0]) continue;
            Walk walk;
            double cum = 0;
            std::vector<double> tips;
            int v = v0, i = i0;
            for (;;) {
                used[v][i] = 1;
                walk.darts.emplace_back(v, i);
                const Dart& d = g.vertices[v][i];
                int rv = v, ri = i;
                if (d.to < 0) {
                    BoundaryItem item;
                    item.vertex = v;
                    item.dart = i;
                    item.label = dart_label(g, v, i);
                    walk.items.push_back(item);
                    tips.push_back(cum + 90.0);
                    cum += 180.0;
                } else {
                    rv = d.to;
                    ri = g.find(rv, dirs.opposite[d.dir]);
                }
                const int c = g.vertices[rv][ri].left;
                walk.color = walk.color == -1 ? c : (walk.color == c ? c : -2);
                const int k = (ri + 1) % static_cast<int>(g.vertices[rv].size());
                cum += ccw_gap(dirs, g.vertices[rv][ri].dir, g.vertices[rv][k].dir) - 180.0;
                v = rv;
                i = k;
                if (v == v0 && i == i0) break;
                if (used[v][i]) {
                    out.why = "a face walk does not close";
                    return out;
                }
            }
            walk.turning = cum;
            for (std::size_t t = 0; t < tips.size(); ++t)
                walk.items[t].turn = (t + 1 < tips.size() ? tips[t + 1] : tips[0] + cum) - tips[t];
            set_wraps(walk.items, dirs);
            out.walks.push_back(std::move(walk));
        }
    const int nw = static_cast<int>(out.walks.size());
    int outer = -1;
    for (int w = 0; w < nw; ++w) {
        const Walk& walk = out.walks[w];
        if (!walk.items.empty()) {
            if (out.open_walk >= 0) {
                out.why = "half-edges on more than one boundary";
                return out;
            }
            out.open_walk = w;
            if (!near(walk.turning, 360.0)) {
                out.why = "the boundary does not turn by 360 degrees";
                return out;
            }
            continue;
        }
        if (walk.color < 0) {
            out.why = "a face with two colours";
            return out;
        }
        if (near(walk.turning, 360.0) && walk.color == 0 && outer < 0) {
            outer = w;
            continue;
        }
        if (!near(walk.turning, -360.0)) {
            out.why = "a face does not turn by -360 degrees";
            return out;
        }
    }
    if (out.open_walk < 0 && outer < 0) {
        out.why = "no outside face";
        return out;
    }
    if (out.open_walk >= 0 && outer >= 0) {
        out.why = "an outside face and half-edges";
        return out;
    }
    if (nv - g.edges() + nw != 2) {
        out.why = "Euler's formula fails (the embedding is not planar)";
        return out;
    }
    out.complete = out.open_walk < 0;
    if (!out.complete) out.boundary = out.walks[out.open_walk].items;
    out.planar = true;
    return out;
}

Example make_example(const PolygonMesh& mesh) {
    Example ex;
    ex.mesh = mesh;
    // Directions: every polygon edge in both orientations, clustered within 1e-4 degrees.
    auto angle_of = [&](int a, int b) {
        const glm::dvec2 d = mesh.vertices[b] - mesh.vertices[a];
        double deg = std::atan2(d.y, d.x) * 180.0 / M_PI;
        if (deg < 0) deg += 360.0;
        if (deg >= 360.0 - 1e-4) deg = 0.0;
        return deg;
    };
    std::vector<double> all;
    for (const Polygon& p : mesh.polygons)
        for (std::size_t i = 0; i < p.vertices.size(); ++i) {
            const int a = p.vertices[i], b = p.vertices[(i + 1) % p.vertices.size()];
            all.push_back(angle_of(a, b));
            all.push_back(angle_of(b, a));
        }
    std::sort(all.begin(), all.end());
    for (double a : all)
        if (ex.dirs.degrees.empty() || a - ex.dirs.degrees.back() > 1e-4)
            ex.dirs.degrees.push_back(a);
    auto dir_of = [&](double deg) {
        if (deg >= 360.0 - 1e-4) deg -= 360.0;
        int best = 0;
        for (std::size_t i = 0; i < ex.dirs.degrees.size(); ++i)
            if (std::abs(ex.dirs.degrees[i] - deg) < std::abs(ex.dirs.degrees[best] - deg))
                best = static_cast<int>(i);
        return best;
    };
    const int nd = static_cast<int>(ex.dirs.degrees.size());
    ex.dirs.opposite.resize(nd);
    for (int d = 0; d < nd; ++d)
        ex.dirs.opposite[d] = dir_of(std::fmod(ex.dirs.degrees[d] + 180.0, 360.0));
    // Colours: 0 the outside, then each polygon colour in order of appearance.
    ex.dirs.palette = {0};
    std::map<std::uint32_t, int> color_index;
    for (const Polygon& p : mesh.polygons)
        if (!color_index.count(p.color)) {
            color_index[p.color] = ex.dirs.colors();
            ex.dirs.palette.push_back(p.color);
        }
    // Darts: the polygon left of each directed edge.
    std::map<std::pair<int, int>, int> left_of;
    for (const Polygon& p : mesh.polygons)
        for (std::size_t i = 0; i < p.vertices.size(); ++i)
            left_of[{p.vertices[i], p.vertices[(i + 1) % p.vertices.size()]}] =
                color_index[p.color];
    std::map<int, int> vertex_index;
    for (const auto& [e, c] : left_of)
        for (int v : {e.first, e.second})
            if (!vertex_index.count(v)) vertex_index[v] = static_cast<int>(vertex_index.size());
    ex.graph.vertices.resize(vertex_index.size());
    std::vector<double> length_sum(nd, 0.0);
    std::vector<int> length_count(nd, 0);
    std::map<std::pair<int, int>, bool> undirected;
    for (const auto& [e, c] : left_of)
        undirected[{std::min(e.first, e.second), std::max(e.first, e.second)}] = true;
    auto left = [&](int a, int b) {
        const auto it = left_of.find({a, b});
        return it == left_of.end() ? 0 : it->second;
    };
    const int nc = ex.dirs.colors();
    std::vector<double> label_sum(static_cast<std::size_t>(nd) * nc * nc, 0.0);
    std::vector<int> label_count(label_sum.size(), 0);
    for (const auto& [e, unused] : undirected) {
        const int a = e.first, b = e.second;
        const int d = dir_of(angle_of(a, b));
        ex.graph.vertices[vertex_index[a]].push_back({d, left(a, b), vertex_index[b]});
        ex.graph.vertices[vertex_index[b]].push_back(
            {ex.dirs.opposite[d], left(b, a), vertex_index[a]});
        const double len = glm::length(mesh.vertices[b] - mesh.vertices[a]);
        length_sum[d] += len, ++length_count[d];
        length_sum[ex.dirs.opposite[d]] += len, ++length_count[ex.dirs.opposite[d]];
        const std::size_t forward =
            (static_cast<std::size_t>(d) * nc + left(a, b)) * nc + left(b, a);
        const std::size_t backward =
            (static_cast<std::size_t>(ex.dirs.opposite[d]) * nc + left(b, a)) * nc + left(a, b);
        label_sum[forward] += len, ++label_count[forward];
        label_sum[backward] += len, ++label_count[backward];
    }
    ex.dirs.label_length.resize(label_sum.size());
    for (std::size_t k = 0; k < label_sum.size(); ++k)
        ex.dirs.label_length[k] = label_count[k] ? label_sum[k] / label_count[k] : 0.0;
    for (auto& ds : ex.graph.vertices) {
        std::sort(ds.begin(), ds.end(), [](const Dart& x, const Dart& y) { return x.dir < y.dir; });
        for (std::size_t i = 1; i < ds.size(); ++i)
            if (ds[i].dir == ds[i - 1].dir)
                throw InputError(
                    "two edges leave one vertex in the same direction (overlapping edges)");
    }
    ex.dirs.mean_length.resize(nd);
    for (int d = 0; d < nd; ++d)
        ex.dirs.mean_length[d] = length_count[d] ? length_sum[d] / length_count[d] : 1.0;
    return ex;
}

std::vector<int> canonical_code(const AngleGraph& g) {
    std::vector<int> best;
    const int nv = static_cast<int>(g.vertices.size());
    std::vector<int> order(nv), index(nv);
    for (int s = 0; s < nv; ++s) {
        std::fill(index.begin(), index.end(), -1);
        std::vector<int> code;
        code.reserve(8 * nv);
        int head = 0, count = 0;
        order[count] = s;
        index[s] = count++;
        while (head < count) {
            const int v = order[head++];
            code.push_back(static_cast<int>(g.vertices[v].size()));
            for (const Dart& d : g.vertices[v]) {
                int target = -1;
                if (d.to >= 0) {
                    if (index[d.to] < 0) order[count] = d.to, index[d.to] = count++;
                    target = index[d.to];
                }
                code.push_back(d.dir);
                code.push_back(d.left);
                code.push_back(target);
            }
        }
        if (best.empty() || code < best) best = std::move(code);
    }
    return best;
}

std::string boundary_string(const Boundary& b, const Directions& dirs) {
    if (b.empty()) return "^";
    const int c = dirs.colors();
    std::string out;
    for (const BoundaryItem& item : b) {
        const bool positive = dirs.degrees[item.label.dir] < 180.0;
        const Label l = positive ? item.label : reversed(item.label, dirs);
        out += "e" + std::to_string((l.dir * c + l.left) * c + l.right) + (positive ? "" : "'");
        double psi = dirs.degrees[item.label.dir] + 90.0;
        if (psi >= 180.0) psi -= 360.0;
        const int n = static_cast<int>(std::floor((psi + item.turn + 180.0) / 360.0 + 1e-9));
        for (int k = 0; k < std::abs(n); ++k) out += n > 0 ? "^" : "v";
        out += " ";
    }
    out.pop_back();
    return out;
}

std::vector<Label> star(const AngleGraph& g, int v) {
    std::vector<Label> s;
    for (std::size_t i = 0; i < g.vertices[v].size(); ++i)
        s.push_back(dart_label(g, v, static_cast<int>(i)));
    return s;
}

}  // namespace sylva::layout
