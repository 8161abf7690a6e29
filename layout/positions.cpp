#include "layout/positions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>

#include "core/errors.h"
#include "core/random.h"
#include "layout/rectangularize.h"

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
            for (int k = c; k < cols; ++k) at(r, k) -= f * at(row, k);
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

std::string color_name(const Directions& dirs, int color) {
    if (color == 0) return "outside";
    const std::uint32_t rgb = dirs.palette[color];
    const std::string cls = planting_class(rgb);
    for (const auto& [name, value] : {std::pair<const char*, std::uint32_t>{"forest", 0x2e7d32},
                                      {"orchard", 0x9ccc65},
                                      {"meadow", 0xe6ee9c},
                                      {"path", 0xa1887f}})
        if (rgb == value && cls == name) return name;
    return color_hex(rgb);
}

std::string edge_class(const Label& label, const Directions& dirs) {
    std::string a = color_name(dirs, label.left), b = color_name(dirs, label.right);
    if (b < a) std::swap(a, b);
    return a + "/" + b;
}

std::vector<std::string> edge_classes(const Directions& dirs) {
    std::set<std::string> out;
    for (const auto& [label, length] : dirs.label_length) {
        out.insert(edge_class(label, dirs));
        for (int c : {label.left, label.right})
            if (c > 0) out.insert(color_name(dirs, c));
    }
    return {out.begin(), out.end()};
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

// An orthonormal basis of a null space in blocks of columns (an orthogonal graph's two axes
// are independent systems): projecting costs what the blocks hold, not vectors x columns.
struct Basis {
    struct Block {
        std::vector<int> cols;
        std::vector<std::vector<double>> q;  // orthonormal, over `cols`
    };
    std::vector<Block> blocks;
    bool empty() const {
        for (const Block& b : blocks)
            if (!b.q.empty()) return false;
        return true;
    }
};

void project(const Basis& basis, const std::vector<double>& t, std::vector<double>& s) {
    s.assign(t.size(), 0.0);
    for (const Basis::Block& block : basis.blocks) {
        const std::size_t n = block.cols.size();
        for (const auto& b : block.q) {
            double d = 0;
            for (std::size_t i = 0; i < n; ++i) d += b[i] * t[block.cols[i]];
            for (std::size_t i = 0; i < n; ++i) s[block.cols[i]] += d * b[i];
        }
    }
}

// The range of an edge with `label`, in the example's units.
LengthRange range_of(const Label& label, double mean, const Directions& dirs,
                     const LengthSettings& settings, bool relaxed) {
    LengthRange r{settings.min_factor * mean, settings.max_factor * mean};
    const auto& ranges = settings.ranges;
    if (const auto it = ranges.find(edge_class(label, dirs)); it != ranges.end()) {
        r = it->second;
    } else {
        bool named = false;
        LengthRange both{0, std::numeric_limits<double>::infinity()};
        for (int c : {label.left, label.right}) {
            if (c == 0) continue;
            const auto jt = ranges.find(color_name(dirs, c));
            if (jt == ranges.end()) continue;
            named = true;
            both.lo = std::max(both.lo, jt->second.lo);
            if (jt->second.hi > 0) both.hi = std::min(both.hi, jt->second.hi);
        }
        if (named) {
            r = {both.lo, std::isfinite(both.hi) ? both.hi : 0.0};
        } else if (const auto kt = ranges.find("*"); kt != ranges.end()) {
            r = kt->second;
        }
    }
    if (relaxed || r.hi <= 0) r.hi = std::numeric_limits<double>::infinity();
    return r;
}

}  // namespace

namespace {

// One way of drawing: the null space of the graph's own faces (`refine` false), or of its
// rectangular refinement, compacted first (`refine` true; orthogonal graphs only).
// `structural` (per edge, in units of its mean): lengths the structure asks for (from a
// compaction), raising the targets of edges it makes much longer, so that a long edge the
// structure forces (a path along thirty plots) does not squeeze everything next to it in
// the least-squares fit. `units` gets the drawing's edge lengths in those units.
std::optional<PolygonMesh> realize_with(const AngleGraph& g, const Directions& dirs,
                                        std::uint64_t seed, const LengthSettings& lengths,
                                        int attempts, int relax, bool refine,
                                        const std::vector<double>* structural = nullptr,
                                        std::vector<double>* units = nullptr) {
    const Analysis a = analyze(g, dirs);
    if (!a.planar || !a.complete) return std::nullopt;
    const int nv = static_cast<int>(g.vertices.size());
    // The input's edges: one per dart pair, named by the dart leaving the smaller vertex.
    std::vector<std::vector<int>> edge_of(nv);
    std::vector<int> edge_dir;
    std::vector<Label> edge_label;
    std::vector<double> mean;  // the example's mean length of edges with this label
    for (int v = 0; v < nv; ++v) edge_of[v].assign(g.vertices[v].size(), -1);
    for (int v = 0; v < nv; ++v)
        for (int i = 0; i < static_cast<int>(g.vertices[v].size()); ++i) {
            const Dart& d = g.vertices[v][i];
            if (d.to < v) continue;
            const int e = static_cast<int>(edge_dir.size());
            edge_dir.push_back(d.dir);
            edge_label.push_back(dart_label(g, v, i));
            mean.push_back(dirs.length_of(edge_label.back()));
            edge_of[v][i] = e;
            edge_of[d.to][g.find(d.to, dirs.opposite[d.dir])] = e;
        }
    const int ne = static_cast<int>(edge_dir.size());
    double min_mean = 1e300, max_mean = 0;
    for (double m : mean) min_mean = std::min(min_mean, m), max_mean = std::max(max_mean, m);
    // The graph whose faces close: orthogonal graphs refined into rectangles (any lengths
    // then draw them without crossings), others as they are.
    const bool ortho = orthogonal(dirs);
    const std::optional<Refinement> refined =
        ortho && refine ? rectangularize(g, dirs) : std::nullopt;
    if (refine && !refined) return std::nullopt;
    const AngleGraph& h = refined ? refined->graph : g;
    const int hv = static_cast<int>(h.vertices.size());
    // Its edges: parts of an input edge (group = that edge) or added ones (group -1).
    std::vector<std::vector<int>> part_of(hv);
    std::vector<int> part_dir, group;
    std::vector<double> scale;  // the unit a part's variable counts in
    const double added_scale = 10.0 * max_mean;
    for (int v = 0; v < hv; ++v) part_of[v].assign(h.vertices[v].size(), -1);
    for (int v = 0; v < hv; ++v)
        for (int i = 0; i < static_cast<int>(h.vertices[v].size()); ++i) {
            const Dart& d = h.vertices[v][i];
            if (d.to < v) continue;
            const int p = static_cast<int>(part_dir.size());
            part_dir.push_back(d.dir);
            int e = -1;
            if (refined) {
                const auto [ov, oi] = refined->origin[v][i];
                if (ov >= 0) e = edge_of[ov][oi];
            } else {
                e = edge_of[v][i];
            }
            group.push_back(e);
            scale.push_back(e >= 0 ? mean[e] : added_scale);
            part_of[v][i] = p;
            part_of[d.to][h.find(d.to, dirs.opposite[d.dir])] = p;
        }
    const int np = static_cast<int>(part_dir.size());
    std::vector<std::vector<int>> parts(ne);
    for (int p = 0; p < np; ++p)
        if (group[p] >= 0) parts[group[p]].push_back(p);
    auto unit = [&](int dir) {
        const double r = (dirs.degrees[dir] - (ortho ? dirs.degrees[0] : 0.0)) * M_PI / 180.0;
        glm::dvec2 u(std::cos(r), std::sin(r));
        // Axis directions exactly: cos(90 degrees) in doubles is 6e-17, not 0.
        for (int k = 0; k < 2; ++k)
            if (std::abs(u[k]) < 1e-12) u[k] = 0.0;
        return u;
    };
    // Closed faces: the steps sum to zero, each part counted in its unit (x = s / scale).
    // (Sign: a dart's step is +s along its own direction, and a part's direction is that of
    // its named dart, so the reverse dart contributes -s.) Orthogonal graphs measured along
    // the first direction and its normal split into two independent systems.
    const Analysis ha = refined ? analyze(h, dirs) : a;
    std::vector<double> rows_a, rows_b;
    int nrows = 0;
    for (const Walk& w : ha.walks) {
        if (w.turning > 0) continue;
        std::vector<double> ra(np, 0.0), rb(np, 0.0);
        for (const auto& [v, i] : w.darts) {
            const int p = part_of[v][i];
            const double sign = h.vertices[v][i].dir == part_dir[p] ? 1.0 : -1.0;
            const glm::dvec2 u = unit(part_dir[p]) * scale[p];
            ra[p] += sign * u.x;
            rb[p] += sign * u.y;
        }
        rows_a.insert(rows_a.end(), ra.begin(), ra.end());
        rows_b.insert(rows_b.end(), rb.begin(), rb.end());
        ++nrows;
    }
    // The null space, made when needed (refined graphs mostly do without, see below).
    Basis basis;
    bool have_basis = false;
    auto make_basis = [&] {
        if (have_basis) return;
        have_basis = true;
        if (ortho) {
            // Parts along the first direction's axis only meet rows_a, the others rows_b.
            for (int axis = 0; axis < 2; ++axis) {
                Basis::Block block;
                for (int p = 0; p < np; ++p)
                    if ((part_dir[p] % 2) == axis) block.cols.push_back(p);
                const std::vector<double>& rows = axis == 0 ? rows_a : rows_b;
                const std::size_t nc = block.cols.size();
                std::vector<double> sub(static_cast<std::size_t>(nrows) * nc);
                for (int r = 0; r < nrows; ++r)
                    for (std::size_t c = 0; c < nc; ++c)
                        sub[r * nc + c] = rows[static_cast<std::size_t>(r) * np + block.cols[c]];
                block.q = null_space(std::move(sub), nrows, static_cast<int>(nc));
                orthonormalize(block.q);
                basis.blocks.push_back(std::move(block));
            }
        } else {
            Basis::Block block;
            for (int p = 0; p < np; ++p) block.cols.push_back(p);
            std::vector<double> rows = rows_a;
            rows.insert(rows.end(), rows_b.begin(), rows_b.end());
            block.q = null_space(std::move(rows), 2 * nrows, np);
            orthonormalize(block.q);
            basis.blocks.push_back(std::move(block));
        }
    };
    if (!refined) {
        make_basis();
        if (basis.empty()) return std::nullopt;
    }
    // Ranges, in units: per input edge (on the sum of its parts), per part (positive).
    std::vector<double> lo(ne), hi(ne), part_lo(np);
    for (int e = 0; e < ne; ++e) {
        const LengthRange r = range_of(edge_label[e], mean[e], dirs, lengths, relax > 0);
        const double shrink = relax >= 3 ? 0.05 : (relax == 2 ? 1.0 / 3.0 : 1.0);
        lo[e] = std::max(r.lo * shrink, 1e-9 * mean[e]) / mean[e];
        hi[e] = r.hi / mean[e];
        if (!(lo[e] <= hi[e])) return std::nullopt;
    }
    for (int p = 0; p < np; ++p)
        part_lo[p] = group[p] >= 0 && parts[group[p]].size() == 1 ? lo[group[p]]
                                                                  : 0.02 * min_mean / scale[p];
    // The faces either side of each input edge, for the targets.
    std::vector<int> face_left(ne, -1), face_right(ne, -1);
    for (std::size_t w = 0; w < a.walks.size(); ++w)
        for (const auto& [v, i] : a.walks[w].darts) {
            const int e = edge_of[v][i];
            (g.vertices[v][i].dir == edge_dir[e] ? face_right : face_left)[e] = static_cast<int>(w);
        }
    Random rng(seed);
    auto log_uniform = [&](double spread) {
        return std::exp((2.0 * rng.uniform() - 1.0) * std::log(std::max(spread, 1.0)));
    };
    // Within the ranges, up to a thousandth (closure is exact: x stays in the null space).
    auto satisfied = [&](const std::vector<double>& x) {
        for (int p = 0; p < np; ++p)
            if (x[p] < part_lo[p] * (1 - 1e-3)) return false;
        for (int e = 0; e < ne; ++e) {
            double sum = 0;
            for (int p : parts[e]) sum += x[p];
            if (sum < lo[e] * (1 - 1e-3) || sum > hi[e] * (1 + 1e-3)) return false;
        }
        return true;
    };
    // The nearest point of the ranges: each part at least its least length, the parts of an
    // input edge shifted alike until their sum is in the edge's range.
    auto into_ranges = [&](const std::vector<double>& v, std::vector<double>& out) {
        out.resize(np);
        for (int p = 0; p < np; ++p) out[p] = std::max(v[p], part_lo[p]);
        for (int e = 0; e < ne; ++e) {
            const auto& ps = parts[e];
            auto sum_at = [&](double shift) {
                double sum = 0;
                for (int p : ps) sum += std::max(part_lo[p], v[p] + shift);
                return sum;
            };
            const double sum = sum_at(0.0);
            const double want = std::clamp(sum, lo[e], std::max(lo[e], hi[e]));
            if (want == sum) continue;
            // The sum grows with the shift: bisect for the shift that gives `want`.
            double below = -1.0, above = 1.0;
            while (sum_at(below) > want) below *= 2;
            while (sum_at(above) < want) above *= 2;
            for (int k = 0; k < 60; ++k) {
                const double mid = 0.5 * (below + above);
                (sum_at(mid) < want ? below : above) = mid;
            }
            for (int p : ps) out[p] = std::max(part_lo[p], v[p] + above);
        }
    };
    std::vector<double> target(np, 0.0), x;
    // Compaction (Tamassia 1987): in a graph of rectangles each coordinate is a longest path.
    // Per axis, the vertices joined by edges across it share a coordinate; every part along
    // it must span at least its target (a split input edge: its parts together), so
    // coordinates in topological order give a drawing where each edge is at least its
    // target and every face closes. False on a cycle (not a drawable refinement).
    auto compaction = [&](std::vector<double>& out) {
        out.assign(np, 0.0);
        std::vector<std::array<double, 2>> coord(hv);
        for (int axis = 0; axis < 2; ++axis) {
            std::vector<int> comp(hv);
            for (int v = 0; v < hv; ++v) comp[v] = v;
            auto root = [&](int v) {
                while (comp[v] != v) v = comp[v] = comp[comp[v]];
                return v;
            };
            for (int v = 0; v < hv; ++v)
                for (const Dart& d : h.vertices[v])
                    if (d.dir % 2 != axis) comp[root(v)] = root(d.to);
            std::vector<std::vector<std::pair<int, double>>> next(hv);
            std::vector<int> indegree(hv, 0);
            auto at_least = [&](int from, int to, double length) {
                next[root(from)].emplace_back(root(to), length);
                ++indegree[root(to)];
            };
            for (int v = 0; v < hv; ++v)
                for (int i = 0; i < static_cast<int>(h.vertices[v].size()); ++i) {
                    const Dart& d = h.vertices[v][i];
                    if (d.dir != axis) continue;  // each part once, along its positive heading
                    const int p = part_of[v][i];
                    const int e = group[p];
                    const double least = e >= 0 && parts[e].size() == 1 ? target[p] * scale[p]
                                                                        : part_lo[p] * scale[p];
                    at_least(v, d.to, least);
                }
            for (int v = 0; v < nv; ++v)
                for (int i = 0; i < static_cast<int>(g.vertices[v].size()); ++i) {
                    const Dart& d = g.vertices[v][i];
                    const int e = edge_of[v][i];
                    if (d.dir != axis || parts[e].size() < 2) continue;
                    double t = 0;
                    for (int p : parts[e]) t += target[p];
                    at_least(v, d.to, t * mean[e]);
                }
            std::vector<double> c(hv, 0.0);
            std::vector<int> ready;
            for (int v = 0; v < hv; ++v)
                if (root(v) == v && indegree[v] == 0) ready.push_back(v);
            int done = 0, nodes = 0;
            for (int v = 0; v < hv; ++v) nodes += root(v) == v;
            while (!ready.empty()) {
                const int v = ready.back();
                ready.pop_back();
                ++done;
                for (const auto& [w, length] : next[v]) {
                    c[w] = std::max(c[w], c[v] + length);
                    if (--indegree[w] == 0) ready.push_back(w);
                }
            }
            if (done != nodes) return false;
            for (int v = 0; v < hv; ++v) coord[v][axis] = c[root(v)];
        }
        for (int v = 0; v < hv; ++v)
            for (int i = 0; i < static_cast<int>(h.vertices[v].size()); ++i) {
                const Dart& d = h.vertices[v][i];
                const int axis = d.dir % 2;
                const double span = coord[d.to][axis] - coord[v][axis];
                out[part_of[v][i]] = (d.dir == axis ? span : -span) / scale[part_of[v][i]];
            }
        return true;
    };
    for (int attempt = 0; attempt < attempts; ++attempt) {
        std::vector<double> color_scale(dirs.colors());
        for (double& s : color_scale) s = log_uniform(lengths.class_spread);
        const std::size_t nw = a.walks.size();
        std::vector<double> face_scale(nw, 1.0), stretch(nw, 1.0);
        for (std::size_t w = 0; w < nw; ++w) {
            const Walk& walk = a.walks[w];
            if (walk.turning > 0 || walk.color <= 0) continue;
            face_scale[w] = color_scale[walk.color] * log_uniform(lengths.polygon_spread);
            stretch[w] = log_uniform(lengths.stretch);
        }
        std::fill(target.begin(), target.end(), 0.0);
        for (int e = 0; e < ne; ++e) {
            const double c2 = std::cos(2.0 * dirs.degrees[edge_dir[e]] * M_PI / 180.0);
            const int l = face_left[e], r = face_right[e];
            double t = std::sqrt(face_scale[l] * face_scale[r]) *
                       std::pow(stretch[l] * stretch[r], 0.5 * c2);
            t = std::clamp(t, lo[e], std::min(hi[e], 1e9));
            if (structural && (*structural)[e] > 1.5 * t)
                t = std::min((*structural)[e], std::min(hi[e], 1e9));
            for (int p : parts[e]) target[p] = t / static_cast<double>(parts[e].size());
        }
        // Refined orthogonal graphs: compaction to the targets first (fast, and any lengths
        // draw them); where that passes a range's upper end, the null space search below
        // for lengths within the ranges, unless even the least lengths pass it.
        bool done = false;
        if (refined) {
            if (!compaction(x)) return std::nullopt;
            done = relax >= 1 || satisfied(x);
            if (!done) {
                const std::vector<double> wanted = target;
                for (int p = 0; p < np; ++p) target[p] = part_lo[p];
                for (int e = 0; e < ne; ++e)
                    for (int p : parts[e]) target[p] = lo[e] / static_cast<double>(parts[e].size());
                std::vector<double> least;
                const bool fits = compaction(least) && satisfied(least);
                target = wanted;
                if (!fits) return std::nullopt;
                make_basis();
                if (basis.empty()) return std::nullopt;
            }
        }
        if (!done) {
            // The closest lengths to the target that close every face and keep the ranges:
            // alternating direction method of multipliers between the null space and the ranges
            // (a convex problem; it converges where plain alternating projections crawl).
            std::vector<double> z, dual(np, 0.0), mid(np);
            project(basis, target, x);
            into_ranges(x, z);
            bool ok = satisfied(x);
            double last_gap = std::numeric_limits<double>::infinity();
            for (int iter = 1; iter <= 1500 && !ok; ++iter) {
                for (int p = 0; p < np; ++p) mid[p] = 0.5 * (target[p] + z[p] - dual[p]);
                project(basis, mid, x);
                for (int p = 0; p < np; ++p) mid[p] = x[p] + dual[p];
                into_ranges(mid, z);
                double gap = 0;
                for (int p = 0; p < np; ++p) {
                    dual[p] += x[p] - z[p];
                    gap = std::max(gap, std::abs(x[p] - z[p]) / (std::abs(z[p]) + part_lo[p]));
                }
                ok = satisfied(x);
                // The ranges and the closed faces do not meet: stop once the gap stops shrinking.
                if (iter % 100 == 0) {
                    if (gap > 0.9 * last_gap) break;
                    last_gap = gap;
                }
            }
            // The ranges are the same for every attempt: if they cannot be met, none will.
            if (!ok) return std::nullopt;
        }
        (void)done;
        if (units) {
            units->assign(ne, 0.0);
            for (int e = 0; e < ne; ++e)
                for (int p : parts[e]) (*units)[e] += x[p] * scale[p] / mean[e];
        }
        // Positions along a spanning tree from vertex 0 of the refined graph; the input's
        // vertices keep their indices in it.
        std::vector<glm::dvec2> pos(hv);
        std::vector<char> placed(hv, 0);
        std::vector<int> stack{0};
        placed[0] = 1;
        while (!stack.empty()) {
            const int v = stack.back();
            stack.pop_back();
            for (int i = 0; i < static_cast<int>(h.vertices[v].size()); ++i) {
                const Dart& d = h.vertices[v][i];
                if (placed[d.to]) continue;
                placed[d.to] = 1;
                const int p = part_of[v][i];
                const double r = dirs.degrees[d.dir] * M_PI / 180.0;
                glm::dvec2 u(std::cos(r), std::sin(r));
                for (int k = 0; k < 2; ++k)
                    if (std::abs(u[k]) < 1e-12) u[k] = 0.0;
                pos[d.to] = pos[v] + x[p] * scale[p] * u;
                stack.push_back(d.to);
            }
        }
        // Polygons: the input's closed faces with a colour, counter-clockwise.
        PolygonMesh mesh;
        mesh.vertices.assign(pos.begin(), pos.begin() + nv);
        for (const Walk& w : a.walks) {
            if (w.turning > 0 || w.color <= 0) continue;
            Polygon p;
            p.color = dirs.palette[w.color];
            for (auto it = w.darts.rbegin(); it != w.darts.rend(); ++it)
                p.vertices.push_back(g.vertices[it->first][it->second].to);
            mesh.polygons.push_back(std::move(p));
        }
        // Planar: no crossing or touching edges, no overlaps (the readers' own check).
        try {
            validate_mesh(mesh, "generated");
        } catch (const InputError&) {
            continue;
        }
        return mesh;
    }
    return std::nullopt;
}

}  // namespace

std::optional<PolygonMesh> realize(const AngleGraph& g, const Directions& dirs, std::uint64_t seed,
                                   const LengthSettings& lengths, int attempts, int relax) {
    const bool ortho = orthogonal(dirs);
    // The thesis's way first: lengths nearest the sampled targets in the null space of the
    // faces, checked for crossings. Orthogonal graphs then fall back on their rectangular
    // refinement, which cannot cross (and past the ranges' ends draw only that way); with
    // holes (enclosed outside faces), whose sides the faces alone do not keep apart, they
    // start there.
    bool holes = false;
    if (ortho) {
        const Analysis a = analyze(g, dirs);
        for (std::size_t w = 0; w < a.walks.size(); ++w)
            holes = holes || (static_cast<int>(w) != a.outer && a.walks[w].color == 0);
    }
    if (!ortho) return realize_with(g, dirs, seed, lengths, attempts, relax, false);
    // The structure's own lengths: the compaction of the refinement, every edge at its target
    // or longer where the structure needs it.
    std::vector<double> structural;
    std::optional<PolygonMesh> compacted = realize_with(
        g, dirs, seed ^ 0x5eedULL, lengths, 1, std::max(relax, 1), true, nullptr, &structural);
    if (!holes && !structural.empty())
        if (auto mesh = realize_with(g, dirs, seed, lengths, std::min(attempts, 2), relax, false,
                                     &structural))
            return mesh;
    if (relax == 0) return realize_with(g, dirs, seed ^ 0x5eedULL, lengths, 1, 0, true);
    return compacted;
}

}  // namespace sylva::layout
