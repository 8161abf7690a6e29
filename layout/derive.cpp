#include "layout/derive.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include "layout/rule_match.h"

namespace sylva::layout {

namespace {

// Hashes of boundary runs, in unsigned 64-bit arithmetic (wrapping by definition): a run's
// labels and the wraps between them (not after its last item). Equal runs hash alike; a hit
// is always checked item by item, so a collision costs time, never a wrong rule.
std::uint64_t mix(std::uint64_t h, std::uint64_t x) {
    h += x * 0x9e3779b97f4a7c15ULL + 0x632be59bd9b4e019ULL;
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ULL;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebULL;
    return h ^ (h >> 31);
}

std::uint64_t label_hash(const Label& l) {
    return mix(mix(static_cast<std::uint32_t>(l.dir), static_cast<std::uint32_t>(l.left)),
               static_cast<std::uint32_t>(l.right));
}

std::uint64_t wrap_hash(int wraps) {
    return mix(0x77726170ULL, static_cast<std::uint32_t>(wraps));
}

std::uint64_t run_hash(const Boundary& b, std::size_t start, std::size_t length) {
    std::uint64_t h = 0;
    for (std::size_t k = 0; k < length; ++k) {
        const BoundaryItem& item = b[(start + k) % b.size()];
        h = mix(h, label_hash(item.label));
        if (k + 1 < length) h = mix(h, wrap_hash(item.wraps));
    }
    return h;
}

// A closed boundary's hash: the least over its rotations (with the wrap that closes it).
std::uint64_t closed_hash(const Boundary& b) {
    std::uint64_t best = ~std::uint64_t{0};
    for (std::size_t r = 0; r < b.size(); ++r)
        best = std::min(
            best, mix(run_hash(b, r, b.size()), wrap_hash(b[(r + b.size() - 1) % b.size()].wraps)));
    return best;
}

struct CodeHash {
    std::size_t operator()(const std::vector<int>& code) const {
        return static_cast<std::size_t>(code_hash(code));
    }
};

// A candidate right-hand piece and its boundary.
struct Candidate {
    Piece piece;
    Boundary boundary;
};

// One piece of a decomposition: candidate c, and for each of its boundary items the position
// in the decomposed boundary it fills.
struct Placed {
    int candidate = 0;
    std::vector<std::pair<int, int>> positions;  // (position in L's boundary, item of c)
};

// Finds earlier graphs whose boundaries compose a new graph's boundary (Schröder 2024,
// figure 3.7): a run of the boundary that is a whole opened candidate boundary, and the rest,
// closed with the turn that makes it 360 degrees, decomposed again (R1 v R2: the extra v is
// the joint). Longer runs are tried first. Sub-boundaries that failed are remembered for the
// rest of one decomposition.
class Decomposer {
  public:
    Decomposer(const Directions& dirs, int max_pieces, int max_steps)
        : dirs_(dirs), max_pieces_(max_pieces), max_steps_(max_steps) {}

    void add(Piece piece) {
        Candidate c{std::move(piece), {}};
        c.boundary = piece_boundary(c.piece, dirs_);
        const int index = static_cast<int>(candidates_.size());
        const std::size_t m = c.boundary.size();
        if (sizes_.size() <= m) sizes_.resize(m + 1, 0);
        sizes_[m] = 1;
        closed_[closed_hash(c.boundary)].push_back(index);
        // Every opening of the boundary: a rotation, all items, the wrap at the end dropped.
        for (std::size_t r = 0; r < m; ++r)
            open_[mix(run_hash(c.boundary, r, m), m)].emplace_back(index, static_cast<int>(r));
        candidates_.push_back(std::move(c));
    }

    const Candidate& candidate(int i) const { return candidates_[i]; }

    std::optional<std::vector<Placed>> decompose(const Boundary& b) {
        failed_.clear();
        steps_ = 0;
        std::vector<int> positions(b.size());
        for (std::size_t i = 0; i < positions.size(); ++i) positions[i] = static_cast<int>(i);
        return recurse(b, positions, 1);
    }

    int piece_limited = 0, cut = 0;

  private:
    // Whether b's run from `start` equals candidate c's boundary opened at `rotation`.
    bool same_run(const Boundary& b, std::size_t start, const Candidate& c, int rotation) const {
        const std::size_t n = b.size(), m = c.boundary.size();
        for (std::size_t k = 0; k < m; ++k) {
            const BoundaryItem& x = b[(start + k) % n];
            const BoundaryItem& y = c.boundary[(rotation + k) % m];
            if (x.label != y.label || (k + 1 < m && x.wraps != y.wraps)) return false;
        }
        return true;
    }

    std::optional<std::vector<Placed>> recurse(const Boundary& b, const std::vector<int>& positions,
                                               int depth) {
        const std::size_t n = b.size();
        std::uint64_t key = closed_hash(b);
        if (const auto exact = closed_.find(key); exact != closed_.end())
            for (int index : exact->second) {
                const Candidate& c = candidates_[index];
                const int r = boundary_match(b, c.boundary);
                if (r < 0) continue;
                Placed p{index, {}};
                for (std::size_t i = 0; i < n; ++i)
                    p.positions.emplace_back(positions[i], static_cast<int>((i + r) % n));
                return std::vector<Placed>{p};
            }
        if (max_pieces_ > 0 && depth >= max_pieces_) {
            ++piece_limited;
            return std::nullopt;
        }
        // What may follow depends on the depth only when max_pieces is set.
        if (max_pieces_ > 0) key = mix(key, static_cast<std::uint64_t>(depth));
        if (failed_.count(key)) return std::nullopt;
        // Every run that is a whole opened candidate: (length, start, candidate, rotation).
        struct Hit {
            std::size_t length, start;
            int candidate, rotation;
        };
        std::vector<Hit> hits;
        for (std::size_t s = 0; s < n; ++s) {
            std::uint64_t h = 0;
            for (std::size_t length = 1; length < n; ++length) {
                const BoundaryItem& item = b[(s + length - 1) % n];
                h = mix(h, label_hash(item.label));
                if (length < sizes_.size() && sizes_[length])
                    if (const auto it = open_.find(mix(h, length)); it != open_.end())
                        for (const auto& [index, rotation] : it->second)
                            if (same_run(b, s, candidates_[index], rotation))
                                hits.push_back({length, s, index, rotation});
                h = mix(h, wrap_hash(item.wraps));
            }
        }
        std::stable_sort(hits.begin(), hits.end(),
                         [](const Hit& x, const Hit& y) { return x.length > y.length; });
        std::size_t last_length = 0, last_start = n;
        for (const Hit& hit : hits) {
            // One candidate per place: the rest of the boundary is the same whichever fits.
            if (hit.length == last_length && hit.start == last_start) continue;
            last_length = hit.length, last_start = hit.start;
            if (++steps_ > max_steps_) {
                if (steps_ == max_steps_ + 1) ++cut;
                return std::nullopt;
            }
            Boundary rest;
            std::vector<int> rest_positions;
            double sum = 0;
            for (std::size_t k = hit.length; k < n; ++k) {
                rest.push_back(b[(hit.start + k) % n]);
                rest_positions.push_back(positions[(hit.start + k) % n]);
                if (k + 1 < n) sum += rest.back().turn;
            }
            rest.back().turn = 360.0 - sum;
            set_wraps(rest, dirs_);
            auto tail = recurse(rest, rest_positions, depth + 1);
            if (!tail) continue;
            Placed p{hit.candidate, {}};
            const std::size_t m = candidates_[hit.candidate].boundary.size();
            for (std::size_t k = 0; k < hit.length; ++k)
                p.positions.emplace_back(positions[(hit.start + k) % n],
                                         static_cast<int>((hit.rotation + k) % m));
            tail->insert(tail->begin(), p);
            return tail;
        }
        if (steps_ <= max_steps_) failed_.insert(key);
        return std::nullopt;
    }

    const Directions& dirs_;
    int max_pieces_;
    long max_steps_;
    long steps_ = 0;
    std::vector<Candidate> candidates_;
    std::vector<char> sizes_;  // sizes_[m]: some candidate has a boundary of m items
    std::unordered_map<std::uint64_t, std::vector<int>> closed_;
    std::unordered_map<std::uint64_t, std::vector<std::pair<int, int>>> open_;
    std::unordered_set<std::uint64_t> failed_;
};

Port port_of(const BoundaryItem& item, int piece, bool floating) {
    if (floating) return {piece, -1, item.dart};
    return {piece, item.vertex, item.dart};
}

void glue(AngleGraph& g, int v, int i, int w, int j) {
    g.vertices[v][i].to = w;
    g.vertices[w][j].to = v;
}

// Whether each run of a partial graph's open boundaries can still become part of a face.
// Between two consecutive half-edges a and b the boundary runs along one face of any
// completion, of the colour left of a. That face is a closed walk whose corners are sectors
// of that colour in the example's stars, turning by -360 in all (+360 for the outside), so
// the rest of it is a chain of such corners from b's direction back to a's, turning by what
// the run leaves. Per colour, a graph of headings (one edge per corner: in-heading ->
// out-heading, weighted by its turn) gives the least and most any such chain can turn;
// a run outside that range can never be closed, and the graph is a dead end (a spiral of
// corners, say). Exact for what it tests; colours with more than kMaxHeadings headings are
// not tested (the table would be too large to be worth it).
class DeadEnds {
  public:
    static constexpr int kMaxHeadings = 256;

    DeadEnds(const std::vector<AngleGraph>& primitives, const Directions& dirs) : dirs_(dirs) {
        const int nc = dirs.colors();
        colors_.resize(nc);
        for (const AngleGraph& p : primitives) {
            const auto& ds = p.vertices[0];
            const int n = static_cast<int>(ds.size());
            for (int i = 0; i < n; ++i) {
                const Dart& in = ds[i];
                const Dart& out = ds[(i + 1) % n];
                double gap = dirs.degrees[out.dir] - dirs.degrees[in.dir];
                if (gap <= 1e-6) gap += 360.0;
                colors_[in.left].corners.push_back({dirs.opposite[in.dir], out.dir, gap - 180.0});
            }
        }
        for (Color& c : colors_) build(c);
    }

    // False when some run of an open boundary of `a` can never be closed.
    bool completable(const Analysis& a) const {
        for (int w : a.open_walks) {
            const Boundary& b = a.walks[w].items;
            for (std::size_t i = 0; i < b.size(); ++i) {
                const BoundaryItem& x = b[i];
                const BoundaryItem& y = b[(i + 1) % b.size()];
                const Color& c = colors_[x.label.left];
                if (!c.tested) continue;
                const int h0 = dirs_.opposite[x.label.dir], h1 = y.label.dir;
                const double run = x.turn - 180.0;
                bool ok = false;
                for (double total : {-360.0, 360.0}) {
                    if (total > 0 && x.label.left != 0) continue;  // only the outside turns +360
                    const double rest = total - run;
                    if (h0 == h1 && std::abs(rest) < 1e-6) ok = true;  // a and b glue directly
                    const auto i0 = c.index.find(h1), i1 = c.index.find(h0);
                    if (i0 == c.index.end() || i1 == c.index.end()) continue;
                    const std::size_t k = static_cast<std::size_t>(i0->second) * c.n + i1->second;
                    if (rest >= c.least[k] - 1e-6 && rest <= c.most[k] + 1e-6) ok = true;
                }
                if (!ok) return false;
            }
        }
        return true;
    }

  private:
    struct Corner {
        int in, out;  // travel headings (direction indices)
        double turn;
    };
    struct Color {
        std::vector<Corner> corners;
        std::map<int, int> index;  // heading -> node
        int n = 0;
        std::vector<double> least, most;  // over chains of >= 1 corner, node x node
        bool tested = false;
    };

    static void build(Color& c) {
        for (const Corner& k : c.corners)
            for (int h : {k.in, k.out})
                if (!c.index.count(h)) c.index.emplace(h, static_cast<int>(c.index.size()));
        c.n = static_cast<int>(c.index.size());
        if (c.n == 0 || c.n > kMaxHeadings) return;
        const double inf = std::numeric_limits<double>::infinity();
        const std::size_t n = static_cast<std::size_t>(c.n);
        c.least.assign(n * n, inf);
        c.most.assign(n * n, -inf);
        for (const Corner& k : c.corners) {
            const std::size_t e = static_cast<std::size_t>(c.index[k.in]) * n + c.index[k.out];
            c.least[e] = std::min(c.least[e], k.turn);
            c.most[e] = std::max(c.most[e], k.turn);
        }
        // Floyd-Warshall both ways; a cycle that turns (negative for the least, positive for
        // the most) makes every chain through it unbounded.
        for (std::size_t k = 0; k < n; ++k)
            for (std::size_t i = 0; i < n; ++i)
                for (std::size_t j = 0; j < n; ++j) {
                    c.least[i * n + j] =
                        std::min(c.least[i * n + j], c.least[i * n + k] + c.least[k * n + j]);
                    c.most[i * n + j] =
                        std::max(c.most[i * n + j], c.most[i * n + k] + c.most[k * n + j]);
                }
        for (std::size_t k = 0; k < n; ++k) {
            const bool down = c.least[k * n + k]<-1e-6, up = c.most[k * n + k]> 1e-6;
            for (std::size_t i = 0; i < n; ++i)
                for (std::size_t j = 0; j < n; ++j) {
                    if (down && c.least[i * n + k] < inf && c.least[k * n + j] < inf)
                        c.least[i * n + j] = -inf;
                    if (up && c.most[i * n + k] > -inf && c.most[k * n + j] > -inf)
                        c.most[i * n + j] = inf;
                }
        }
        c.tested = true;
    }

    const Directions& dirs_;
    std::vector<Color> colors_;
};

// A hierarchy graph with the star id (primitive) of each vertex.
struct Node {
    AngleGraph graph;
    std::vector<int> stars;
};

}  // namespace

Grammar derive_grammar(const Example& example, const DeriveSettings& settings) {
    using clock = std::chrono::steady_clock;
    const auto start = clock::now();
    Grammar grammar;
    grammar.dirs = example.dirs;
    const Directions& dirs = grammar.dirs;
    grammar.example_vertices = static_cast<int>(example.graph.vertices.size());
    grammar.example_polygons = static_cast<int>(example.mesh.polygons.size());
    HierarchyReport& report = grammar.hierarchy;

    // Generation 1: the primitives (one vertex, every edge split), without duplicates; a
    // primitive's index is its star id.
    StarTable stars;
    for (std::size_t v = 0; v < example.graph.vertices.size(); ++v) {
        AngleGraph p;
        p.vertices.push_back(example.graph.vertices[v]);
        for (Dart& d : p.vertices[0]) d.to = -1;
        if (stars.find(p, 0) < 0) {
            stars.add(p, 0);
            grammar.primitives.push_back(std::move(p));
        }
    }
    Decomposer decomposer(dirs, settings.max_pieces, settings.max_decomposition_steps);
    // Generation 0: the distinct edges.
    std::set<Label> edge_labels;
    for (std::size_t v = 0; v < example.graph.vertices.size(); ++v)
        for (std::size_t i = 0; i < example.graph.vertices[v].size(); ++i) {
            const Label l = dart_label(example.graph, static_cast<int>(v), static_cast<int>(i));
            if (dirs.degrees[l.dir] < 180.0 && edge_labels.insert(l).second) {
                Piece e;
                e.floating = true;
                e.edge = l;
                decomposer.add(e);
            }
        }
    for (const AngleGraph& p : grammar.primitives) decomposer.add({p, false, {}});

    // Primitive half-edges by label, for branch gluing.
    std::map<Label, std::vector<std::pair<int, int>>> primitive_darts;
    for (std::size_t p = 0; p < grammar.primitives.size(); ++p)
        for (std::size_t i = 0; i < grammar.primitives[p].vertices[0].size(); ++i)
            primitive_darts[dart_label(grammar.primitives[p], 0, static_cast<int>(i))].emplace_back(
                static_cast<int>(p), static_cast<int>(i));

    // Rules by the stars of their left sides' vertices. A new graph contains a rule's left
    // side only through what the last gluing added (its parent contained none), so only
    // matches through the new vertex or the new edge's ends are tried.
    std::vector<std::vector<int>> rule_stars;
    std::vector<std::vector<std::pair<int, int>>> rules_at_star(grammar.primitives.size());
    std::vector<int> map;
    auto reducible = [&](const Node& c, std::initializer_list<int> anchors) {
        for (int v : anchors)
            for (const auto& [r, p] : rules_at_star[c.stars[v]])
                if (rule_stars[r].size() <= c.stars.size() &&
                    map_piece(grammar.rules[r].left, rule_stars[r], p, c.graph, c.stars, v, map))
                    return true;
        return false;
    };
    const DeadEnds dead_ends(grammar.primitives, dirs);
    std::unordered_set<std::vector<int>, CodeHash> seen;
    for (const AngleGraph& p : grammar.primitives) seen.insert(canonical_code(p));

    std::vector<Node> frontier;
    for (std::size_t p = 0; p < grammar.primitives.size(); ++p)
        frontier.push_back({grammar.primitives[p], {static_cast<int>(p)}});
    report.graphs = static_cast<int>(frontier.size());
    report.generations = 1;
    bool stopped = false;
    int since_clock = 0;
    auto out_of_time = [&]() {
        if (settings.max_seconds <= 0 || ++since_clock < 16) return false;
        since_clock = 0;
        return std::chrono::duration<double>(clock::now() - start).count() > settings.max_seconds;
    };
    std::size_t expanded = 0;
    std::vector<Node> next;
    // An example with more distinct stars than the budget has graphs: nothing grows.
    if (report.graphs >= settings.max_graphs) {
        report.stopped_by = "graphs";
        stopped = true;
    }
    while (!frontier.empty() && !stopped) {
        if (settings.max_generations > 0 && report.generations >= settings.max_generations) {
            report.stopped_by = "generations";
            break;
        }
        ++report.generations;
        next.clear();
        // Tests a new graph; `anchors` are the vertices the last gluing changed.
        auto consider = [&](Node&& child, std::initializer_list<int> anchors) {
            if (settings.max_vertices > 0 &&
                static_cast<int>(child.graph.vertices.size()) > settings.max_vertices) {
                ++report.vertex_limited;
                return;
            }
            if (!seen.insert(canonical_code(child.graph)).second) return;
            Analysis a = analyze(child.graph, dirs);
            if (!a.planar) return;
            if (!dead_ends.completable(a)) {
                ++report.dead_ends;
                return;
            }
            if (reducible(child, anchors)) return;
            ++report.graphs;
            if (report.graphs >= settings.max_graphs) {
                report.stopped_by = "graphs";
                stopped = true;
            } else if (out_of_time()) {
                report.stopped_by = "seconds";
                stopped = true;
            }
            if (a.complete) {
                grammar.starters.push_back(std::move(child.graph));
                return;
            }
            if (!a.single_boundary()) {
                ++report.multi_boundary;
                next.push_back(std::move(child));
                return;
            }
            if (auto parts = decomposer.decompose(a.boundary)) {
                Rule rule;
                rule.left = child.graph;
                rule.boundary = boundary_string(a.boundary, dirs);
                for (const BoundaryItem& item : a.boundary)
                    rule.left_ports.push_back(port_of(item, 0, false));
                rule.right_ports.resize(a.boundary.size());
                for (std::size_t k = 0; k < parts->size(); ++k) {
                    const Candidate& c = decomposer.candidate((*parts)[k].candidate);
                    rule.right.push_back(c.piece);
                    for (const auto& [position, item] : (*parts)[k].positions)
                        rule.right_ports[position] =
                            port_of(c.boundary[item], static_cast<int>(k), c.piece.floating);
                }
                const int r = static_cast<int>(grammar.rules.size());
                for (std::size_t v = 0; v < child.stars.size(); ++v)
                    rules_at_star[child.stars[v]].emplace_back(r, static_cast<int>(v));
                rule_stars.push_back(child.stars);
                grammar.rules.push_back(std::move(rule));
                return;
            }
            decomposer.add({child.graph, false, {}});
            next.push_back(std::move(child));
        };
        for (expanded = 0; expanded < frontier.size() && !stopped; ++expanded) {
            throw_if_cancelled(settings.cancel);
            const Node& node = frontier[expanded];
            const Analysis a = analyze(node.graph, dirs);
            for (int w : a.open_walks) {
                const Boundary& b = a.walks[w].items;
                const std::size_t n = b.size();
                // Loop gluing: a and a-bar next to each other, closing a face.
                for (std::size_t i = 0; i < n && n >= 2 && !stopped; ++i) {
                    const BoundaryItem& x = b[i];
                    const BoundaryItem& y = b[(i + 1) % n];
                    if (y.label != reversed(x.label, dirs) || std::abs(x.turn + 180.0) > 1e-6)
                        continue;
                    Node child = node;
                    glue(child.graph, x.vertex, x.dart, y.vertex, y.dart);
                    consider(std::move(child), {x.vertex, y.vertex});
                }
                // Branch gluing with every primitive that has the opposite half-edge.
                for (std::size_t i = 0; i < n && !stopped; ++i) {
                    const BoundaryItem& x = b[i];
                    const auto it = primitive_darts.find(reversed(x.label, dirs));
                    if (it == primitive_darts.end()) continue;
                    for (const auto& [p, j] : it->second) {
                        if (stopped) break;
                        Node child = node;
                        child.graph.vertices.push_back(grammar.primitives[p].vertices[0]);
                        child.stars.push_back(p);
                        const int nv = static_cast<int>(child.graph.vertices.size()) - 1;
                        glue(child.graph, x.vertex, x.dart, nv, j);
                        consider(std::move(child), {nv});
                    }
                }
            }
        }
        if (stopped) break;
        frontier.swap(next);
    }
    report.open_graphs = static_cast<int>(
        stopped ? next.size() + (frontier.size() - std::min(expanded, frontier.size()))
                : frontier.size());
    report.piece_limited = decomposer.piece_limited;
    report.decompositions_cut = decomposer.cut;
    // The example is a complete graph a closed hierarchy derives; when a limit ended growth
    // and no starter is the example, it becomes one, so every grammar derives at least the
    // example's structure. (The code is compared only when the sizes agree: an example's
    // code takes time in proportion to its square.)
    if (report.stopped_by != "closed" || grammar.starters.empty()) {
        bool have = false;
        std::vector<int> code;
        for (const AngleGraph& s : grammar.starters)
            if (s.vertices.size() == example.graph.vertices.size()) {
                if (code.empty()) code = canonical_code(example.graph);
                have = have || canonical_code(s) == code;
            }
        if (!have) {
            grammar.starters.push_back(example.graph);
            report.example_added = true;
        }
    }
    return grammar;
}

}  // namespace sylva::layout
