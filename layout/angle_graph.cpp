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

double Directions::length_of(const Label& l) const {
    const auto it = label_length.find(l);
    if (it != label_length.end() && it->second > 0) return it->second;
    return l.dir >= 0 && l.dir < static_cast<int>(mean_length.size()) ? mean_length[l.dir] : 1.0;
}

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

int Analysis::polygons() const {
    int n = 0;
    for (const Walk& w : walks) n += w.items.empty() && w.turning < 0 && w.color > 0;
    return n;
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
    for (int w = 0; w < nw; ++w) {
        const Walk& walk = out.walks[w];
        const bool open = !walk.items.empty();
        if (open) out.open_walks.push_back(w);
        if (near(walk.turning, 360.0)) {
            if (out.outer >= 0) {
                out.why = "two walks turn by +360 degrees";
                return out;
            }
            if (!open && walk.color != 0) {
                out.why = "the outside face has a colour";
                return out;
            }
            out.outer = w;
            continue;
        }
        if (!near(walk.turning, -360.0)) {
            out.why = open ? "a boundary does not turn by 360 degrees"
                           : "a face does not turn by -360 degrees";
            return out;
        }
        if (!open && walk.color < 0) {
            out.why = "a face with two colours";
            return out;
        }
    }
    if (out.outer < 0) {
        out.why = "no outside face";
        return out;
    }
    if (nv - g.edges() + nw != 2) {
        out.why = "Euler's formula fails (the embedding is not planar)";
        return out;
    }
    out.complete = out.open_walks.empty();
    if (out.single_boundary()) out.boundary = out.walks[out.outer].items;
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
    if (ex.dirs.degrees.size() > static_cast<std::size_t>(kMaxDirections))
        throw InputError("more than " + std::to_string(kMaxDirections) + " edge directions");
    // The nearest direction, by binary search (an example may have as many directions as
    // edges).
    auto dir_of = [&](double deg) {
        if (deg >= 360.0 - 1e-4) deg -= 360.0;
        const auto& ds = ex.dirs.degrees;
        const auto it = std::lower_bound(ds.begin(), ds.end(), deg);
        std::size_t best =
            it == ds.end() ? ds.size() - 1 : static_cast<std::size_t>(it - ds.begin());
        if (best > 0 && std::abs(ds[best - 1] - deg) <= std::abs(ds[best] - deg)) --best;
        // Near 0 the nearest may sit just below 360.
        if (std::abs(ds.back() - 360.0 - deg) < std::abs(ds[best] - deg)) best = ds.size() - 1;
        return static_cast<int>(best);
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
    if (ex.dirs.colors() > kMaxColors)
        throw InputError("more than " + std::to_string(kMaxColors - 1) + " colours");
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
    std::map<Label, std::pair<double, int>> label_sum;
    for (const auto& [e, unused] : undirected) {
        const int a = e.first, b = e.second;
        const int d = dir_of(angle_of(a, b));
        ex.graph.vertices[vertex_index[a]].push_back({d, left(a, b), vertex_index[b]});
        ex.graph.vertices[vertex_index[b]].push_back(
            {ex.dirs.opposite[d], left(b, a), vertex_index[a]});
        const double len = glm::length(mesh.vertices[b] - mesh.vertices[a]);
        length_sum[d] += len, ++length_count[d];
        length_sum[ex.dirs.opposite[d]] += len, ++length_count[ex.dirs.opposite[d]];
        for (const Label& l : {Label{d, left(a, b), left(b, a)},
                               Label{ex.dirs.opposite[d], left(b, a), left(a, b)}}) {
            auto& [sum, count] = label_sum[l];
            sum += len;
            ++count;
        }
    }
    for (const auto& [l, s] : label_sum) ex.dirs.label_length[l] = s.first / s.second;
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

namespace {

// The code of g read breadth first from start vertex s (darts in counter-clockwise order fix
// the order in which neighbours are numbered).
void code_from(const AngleGraph& g, int s, std::vector<int>& order, std::vector<int>& index,
               std::vector<int>& code) {
    std::fill(index.begin(), index.end(), -1);
    code.clear();
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
}

// What code_from() writes first for start v, without the walk: its star and which darts
// are half-edges. Only starts with the smallest prefix can give the smallest code.
std::vector<int> start_prefix(const AngleGraph& g, int v) {
    std::vector<int> p{static_cast<int>(g.vertices[v].size())};
    for (const Dart& d : g.vertices[v]) {
        p.push_back(d.dir);
        p.push_back(d.left);
        p.push_back(d.to < 0 ? -1 : (d.to == v ? 0 : 1));
    }
    return p;
}

}  // namespace

std::vector<int> canonical_code(const AngleGraph& g) {
    const int nv = static_cast<int>(g.vertices.size());
    std::vector<int> best_prefix;
    std::vector<int> starts;
    for (int v = 0; v < nv; ++v) {
        std::vector<int> p = start_prefix(g, v);
        if (starts.empty() || p < best_prefix) {
            best_prefix = std::move(p);
            starts.assign(1, v);
        } else if (p == best_prefix) {
            starts.push_back(v);
        }
    }
    std::vector<int> best, code, order(nv), index(nv);
    for (int s : starts) {
        code_from(g, s, order, index, code);
        if (best.empty() || code < best) best = code;
    }
    return best;
}

std::uint64_t code_hash(const std::vector<int>& code) {
    std::uint64_t h = 0xcbf29ce484222325ULL ^ code.size();
    for (int x : code) {
        h ^= static_cast<std::uint32_t>(x);
        h *= 0x100000001b3ULL;
        h ^= h >> 29;
    }
    return h;
}

std::uint64_t label_number(const Label& l, const Directions& dirs) {
    const auto c = static_cast<std::uint64_t>(dirs.colors());
    return (static_cast<std::uint64_t>(l.dir) * c + static_cast<std::uint64_t>(l.left)) * c +
           static_cast<std::uint64_t>(l.right);
}

std::string boundary_string(const Boundary& b, const Directions& dirs) {
    if (b.empty()) return "^";
    std::string out;
    for (const BoundaryItem& item : b) {
        const bool positive = dirs.degrees[item.label.dir] < 180.0;
        const Label l = positive ? item.label : reversed(item.label, dirs);
        out += "e" + std::to_string(label_number(l, dirs)) + (positive ? "" : "'");
        double psi = dirs.degrees[item.label.dir] + 90.0;
        if (psi >= 180.0) psi -= 360.0;
        const double turns = std::floor((psi + item.turn + 180.0) / 360.0 + 1e-9);
        // A boundary turns by at most 180 degrees per half-edge in either sense, so |turns| is
        // small; the clamp only guards the conversion.
        const int n = static_cast<int>(std::clamp(turns, -1e6, 1e6));
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
