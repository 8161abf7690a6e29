#include "layout/generate.h"

#include <algorithm>
#include <cmath>

#include "core/random.h"

namespace sylva::layout {

const char* measure_name(SizeMeasure m) {
    return m == SizeMeasure::Polygons ? "polygons" : "corners";
}

namespace {

using Side = GrowthTable::Side;
using Entry = GrowthTable::Entry;

// A graph being grown: its star ids, its faces, and which face each dart walks.
struct State {
    AngleGraph g;
    std::vector<int> stars;
    Analysis a;
    std::vector<std::vector<int>> face_of;
    int size = 0;
};

void index_faces(State& s) {
    s.face_of.resize(s.g.vertices.size());
    for (std::size_t v = 0; v < s.g.vertices.size(); ++v)
        s.face_of[v].assign(s.g.vertices[v].size(), -1);
    for (std::size_t w = 0; w < s.a.walks.size(); ++w)
        for (const auto& [v, i] : s.a.walks[w].darts) s.face_of[v][i] = static_cast<int>(w);
}

// (E - V) of a side glued into a graph: its pieces' full edges, one edge per port, less one
// per floating piece (whose two ports are one edge), less its vertices.
int side_euler(const Side& s) {
    int e = static_cast<int>(s.ports->size()), v = 0;
    for (const Piece* p : s.pieces) {
        if (p->floating) {
            --e;
            continue;
        }
        e += p->graph.edges();
        v += static_cast<int>(p->graph.vertices.size());
    }
    return e - v;
}

int side_vertices(const Side& s) {
    int v = 0;
    for (const Piece* p : s.pieces)
        v += p->floating ? 0 : static_cast<int>(p->graph.vertices.size());
    return v;
}

bool contains(const std::vector<int>& v, int x) {
    return std::find(v.begin(), v.end(), x) != v.end();
}

// Places the side X of move `m` in the graph with entry `e` at vertex v (or the edge leaving
// v by dart i), finds the other pieces of X on the faces next to what is placed (the pieces
// of a composed boundary R1 v R2 ... meet around shared faces), and glues the other side in.
// False when X does not fit there or the result is not a complete planar graph.
bool attempt(const GrowthTable& table, const State& st, const Entry& e, int v, int i, Random& rng,
             State& out) {
    const GrowthTable::Move& m = table.move_list()[e.move];
    const Side& x = m.from;
    const std::size_t np = x.pieces.size();
    const AngleGraph& g = st.g;
    const Directions& dirs = table.grammar().dirs;
    SideMatch match;
    match.maps.assign(np, {});
    match.edges.assign(np, {-1, -1});
    std::vector<char> done(np, 0);
    std::vector<int> used;                        // vertices of matched vertex pieces
    std::vector<std::pair<int, int>> used_edges;  // matched floating edges (lower, upper)
    auto take_vertices = [&](int p, const std::vector<int>& map) {
        for (int u : map) {
            if (contains(used, u)) return false;
            for (const auto& [a, b] : used_edges)
                if (a == u || b == u) return false;
        }
        used.insert(used.end(), map.begin(), map.end());
        match.maps[p] = map;
        done[p] = 1;
        return true;
    };
    auto take_edge = [&](int p, int a, int ai) {
        const int b = g.vertices[a][ai].to;
        if (b < 0 || contains(used, a) || contains(used, b)) return false;
        const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
        if (std::find(used_edges.begin(), used_edges.end(), key) != used_edges.end()) return false;
        used_edges.push_back(key);
        match.edges[p] = {a, ai};
        done[p] = 1;
        return true;
    };
    std::vector<int> map;
    if (e.vertex < 0) {
        if (!take_edge(e.piece, v, i)) return false;
    } else if (!map_piece(x.pieces[e.piece]->graph, x.stars[e.piece], e.vertex, g, st.stars, v,
                          map) ||
               !take_vertices(e.piece, map)) {
        return false;
    }
    std::vector<int> faces;
    std::vector<std::pair<int, int>> candidates, best;
    for (std::size_t left = np - 1; left > 0; --left) {
        // The next piece is looked for on the faces around what is placed: first the inner
        // faces only (the outside face runs past everything on the boundary, so a piece met
        // there is mostly in the wrong place), then the outside too.
        int chosen = -1;
        for (int pass = 0; pass < 2 && chosen < 0; ++pass) {
            faces.clear();
            auto add_face = [&](int f) {
                if (pass == 1 || f != st.a.outer) faces.push_back(f);
            };
            for (std::size_t p = 0; p < np; ++p) {
                if (!done[p]) continue;
                if (x.pieces[p]->floating) {
                    const auto [a, ai] = match.edges[p];
                    const int b = g.vertices[a][ai].to;
                    add_face(st.face_of[a][ai]);
                    add_face(st.face_of[b][g.find(b, dirs.opposite[g.vertices[a][ai].dir])]);
                } else {
                    for (int u : match.maps[p])
                        for (int f : st.face_of[u]) add_face(f);
                }
            }
            std::sort(faces.begin(), faces.end());
            faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
            // The unplaced piece with the fewest places on those faces.
            best.clear();
            for (std::size_t q = 0; q < np; ++q) {
                if (done[q]) continue;
                candidates.clear();
                const Piece& piece = *x.pieces[q];
                for (int f : faces)
                    for (const auto& [a, ai] : st.a.walks[f].darts) {
                        if (piece.floating) {
                            if (g.vertices[a][ai].dir == piece.edge.dir &&
                                dart_label(g, a, ai) == piece.edge)
                                candidates.emplace_back(a, ai);
                            const int b = g.vertices[a][ai].to;
                            const int bj = g.find(b, dirs.opposite[g.vertices[a][ai].dir]);
                            if (g.vertices[b][bj].dir == piece.edge.dir &&
                                dart_label(g, b, bj) == piece.edge)
                                candidates.emplace_back(b, bj);
                        } else {
                            for (std::size_t pv = 0; pv < x.stars[q].size(); ++pv)
                                if (x.stars[q][pv] == st.stars[a])
                                    candidates.emplace_back(static_cast<int>(pv), a);
                        }
                    }
                if (candidates.empty()) continue;
                std::sort(candidates.begin(), candidates.end());
                candidates.erase(std::unique(candidates.begin(), candidates.end()),
                                 candidates.end());
                if (chosen < 0 || candidates.size() < best.size()) {
                    chosen = static_cast<int>(q);
                    best.swap(candidates);
                }
            }
        }
        if (chosen < 0) return false;
        bool placed = false;
        for (int k = 0; k < 8 && !best.empty() && !placed; ++k) {
            const std::size_t r = rng.next() % best.size();
            const auto [c0, c1] = best[r];
            best[r] = best.back();
            best.pop_back();
            if (x.pieces[chosen]->floating)
                placed = take_edge(chosen, c0, c1);
            else
                placed =
                    map_piece(x.pieces[chosen]->graph, x.stars[chosen], c0, g, st.stars, c1, map) &&
                    take_vertices(chosen, map);
        }
        if (!placed) return false;
    }
    const SideView xs{x.pieces, x.ports};
    const SideView ys{m.to.pieces, m.to.ports};
    std::vector<int> stars;
    Analysis a;
    std::optional<AngleGraph> h =
        replace_side(g, st.stars, dirs, xs, match, ys, m.to.stars, stars, &a);
    if (!h) return false;
    out.g = std::move(*h);
    out.stars = std::move(stars);
    out.a = std::move(a);
    out.size = table.size_of(out.g, out.a);
    index_faces(out);
    return true;
}

// How often each move was tried and worked in one growth, for drawing likely moves first.
struct MoveStats {
    std::vector<float> tries, wins;
    explicit MoveStats(std::size_t moves) : tries(moves, 0.0f), wins(moves, 0.0f) {}
    double weight(int m) const { return (wins[m] + 1.0) / (tries[m] + 1.0); }
    bool note(int m, bool worked) {
        tries[m] += 1.0f;
        wins[m] += worked ? 1.0f : 0.0f;
        return worked;
    }
};

struct StepLimits {
    int upper = 0;         // a growing move may reach this size at most
    int max_vertices = 0;  // 0: none
    bool vertex_limited = false;
};

bool acceptable(const GrowthTable& table, const State& st, const Entry& e, int kind,
                const StepLimits& limits) {
    return kind != GrowthTable::kGrow || st.size + table.move_list()[e.move].delta <= limits.upper;
}

bool accept(State& st, State& next, StepLimits& limits) {
    if (limits.max_vertices > 0 && static_cast<int>(next.g.vertices.size()) > limits.max_vertices) {
        limits.vertex_limited = true;
        return false;
    }
    st = std::move(next);
    return true;
}

// One move of `kind` at a random place; `tries` places are sampled.
bool sampled_step(const GrowthTable& table, State& st, int kind, int tries, double outside_share,
                  Random& rng, StepLimits& limits, MoveStats& stats) {
    State next;
    std::vector<const Entry*> choices;
    const auto& outside = st.a.walks[st.a.outer].darts;
    for (int t = 0; t < tries; ++t) {
        // Mostly on the outside: growth spreads outwards rather than packing holes, whose
        // drawings need ever shorter edges.
        const int v = rng.uniform() < outside_share
                          ? outside[rng.next() % outside.size()].first
                          : static_cast<int>(rng.next() % st.g.vertices.size());
        const int i = static_cast<int>(rng.next() % st.g.vertices[v].size());
        const auto& at_vertex = table.at_star(kind, st.stars[v]);
        const auto& at_edge = table.at_label(kind, dart_label(st.g, v, i));
        // A move that may start here and fits the size limit, drawn by how often it worked
        // so far (most rules' sides are rare, so trying them all alike wastes the tries).
        choices.clear();
        double total = 0;
        for (const auto* list : {&at_vertex, &at_edge})
            for (const Entry& e : *list)
                if (acceptable(table, st, e, kind, limits)) {
                    choices.push_back(&e);
                    total += stats.weight(e.move);
                }
        if (choices.empty()) continue;
        double pick = rng.uniform() * total;
        const Entry* chosen = choices.back();
        for (const Entry* c : choices)
            if ((pick -= stats.weight(c->move)) < 0) {
                chosen = c;
                break;
            }
        const Entry& e = *chosen;
        if (stats.note(e.move, attempt(table, st, e, v, i, rng, next)) && accept(st, next, limits))
            return true;
    }
    return false;
}

// One move of `kind` anywhere it fits: every place, in random order, the moves that worked
// most often first.
bool searched_step(const GrowthTable& table, State& st, int kind, Random& rng, StepLimits& limits,
                   MoveStats& stats) {
    State next;
    std::vector<int> order(st.g.vertices.size());
    for (std::size_t v = 0; v < order.size(); ++v) order[v] = static_cast<int>(v);
    for (std::size_t k = order.size(); k > 1; --k) std::swap(order[k - 1], order[rng.next() % k]);
    std::vector<std::pair<const Entry*, int>> here;  // entry, dart (-1: at the vertex)
    for (int v : order) {
        here.clear();
        for (const Entry& e : table.at_star(kind, st.stars[v]))
            if (acceptable(table, st, e, kind, limits)) here.emplace_back(&e, 0);
        for (int i = 0; i < static_cast<int>(st.g.vertices[v].size()); ++i)
            for (const Entry& e : table.at_label(kind, dart_label(st.g, v, i)))
                if (acceptable(table, st, e, kind, limits)) here.emplace_back(&e, i);
        std::stable_sort(here.begin(), here.end(), [&](const auto& a, const auto& b) {
            return stats.weight(a.first->move) > stats.weight(b.first->move);
        });
        for (const auto& [e, i] : here)
            if (stats.note(e->move, attempt(table, st, *e, v, i, rng, next)) &&
                accept(st, next, limits))
                return true;
    }
    return false;
}

State starter_state(const GrowthTable& table, int s) {
    State st;
    st.g = table.grammar().starters[s];
    st.stars = table.starter_stars(s);
    st.a = analyze(st.g, table.grammar().dirs);
    st.size = table.size_of(st.g, st.a);
    index_faces(st);
    return st;
}

}  // namespace

GrowthTable::GrowthTable(Grammar grammar) : grammar_(std::move(grammar)) {
    for (const AngleGraph& p : grammar_.primitives) stars_.add(p, 0);
    left_pieces_.reserve(grammar_.rules.size());
    for (const Rule& r : grammar_.rules) left_pieces_.push_back({r.left, false, {}});
    auto side = [&](std::vector<const Piece*> pieces, const std::vector<Port>& ports) {
        Side s;
        s.pieces = std::move(pieces);
        s.ports = &ports;
        for (const Piece* p : s.pieces)
            s.stars.push_back(p->floating ? std::vector<int>{} : stars_.ids(p->graph));
        return s;
    };
    struct Raw {
        Move move;
        int faces = 0, vertices = 0;
    };
    std::vector<Raw> raw;
    bool faces_change = false, vertices_change = false;
    for (std::size_t r = 0; r < grammar_.rules.size(); ++r) {
        const Rule& rule = grammar_.rules[r];
        std::vector<const Piece*> right;
        for (const Piece& p : rule.right) right.push_back(&p);
        Side left = side({&left_pieces_[r]}, rule.left_ports);
        Side right_side = side(right, rule.right_ports);
        bool known = true;
        for (const Side* s : {&left, &right_side})
            for (const auto& ids : s->stars) known = known && !contains(ids, -1);
        if (!known) continue;  // a side with a star the example lacks never matches
        const int faces = side_euler(right_side) - side_euler(left);
        const int vertices = side_vertices(right_side) - side_vertices(left);
        faces_change = faces_change || faces != 0;
        vertices_change = vertices_change || vertices != 0;
        raw.push_back({{static_cast<int>(r), true, left, right_side, 0}, faces, vertices});
        raw.push_back({{static_cast<int>(r), false, right_side, left, 0}, -faces, -vertices});
    }
    measure_ = !faces_change && vertices_change ? SizeMeasure::Corners : SizeMeasure::Polygons;
    example_size_ =
        measure_ == SizeMeasure::Polygons ? grammar_.example_polygons : grammar_.example_vertices;
    by_star_.assign(3, std::vector<std::vector<Entry>>(stars_.size()));
    by_label_.assign(3, {});
    for (Raw& r : raw) {
        r.move.delta = measure_ == SizeMeasure::Polygons ? r.faces : r.vertices;
        const int kind = r.move.delta > 0 ? kGrow : (r.move.delta == 0 ? kKeep : kShrink);
        const int m = static_cast<int>(moves_.size());
        const Side& from = r.move.from;
        for (std::size_t p = 0; p < from.pieces.size(); ++p) {
            if (from.pieces[p]->floating) {
                by_label_[kind][from.pieces[p]->edge].push_back({m, static_cast<int>(p), -1});
                continue;
            }
            for (std::size_t v = 0; v < from.stars[p].size(); ++v)
                by_star_[kind][from.stars[p][v]].push_back(
                    {m, static_cast<int>(p), static_cast<int>(v)});
        }
        can_grow_ = can_grow_ || kind == kGrow;
        moves_.push_back(std::move(r.move));
    }
    // Starters: their sizes, and how many growing moves fit each.
    Random rng(0x5eed5eedULL);
    for (std::size_t s = 0; s < grammar_.starters.size(); ++s) {
        starter_stars_.push_back(stars_.ids(grammar_.starters[s]));
        State st;
        st.g = grammar_.starters[s];
        st.stars = starter_stars_.back();
        st.a = analyze(st.g, grammar_.dirs);
        st.size = size_of(st.g, st.a);
        index_faces(st);
        starter_sizes_.push_back(st.size);
        std::vector<char> fits(moves_.size(), 0);
        State next;
        if (!contains(st.stars, -1))
            for (int v = 0; v < static_cast<int>(st.g.vertices.size()); ++v) {
                for (const Entry& e : at_star(kGrow, st.stars[v]))
                    if (!fits[e.move] && attempt(*this, st, e, v, 0, rng, next)) fits[e.move] = 1;
                for (int i = 0; i < static_cast<int>(st.g.vertices[v].size()); ++i)
                    for (const Entry& e : at_label(kGrow, dart_label(st.g, v, i)))
                        if (!fits[e.move] && attempt(*this, st, e, v, i, rng, next))
                            fits[e.move] = 1;
            }
        starter_weights_.push_back(static_cast<double>(std::count(fits.begin(), fits.end(), 1)));
    }
}

int GrowthTable::size_of(const AngleGraph& g, const Analysis& a) const {
    return measure_ == SizeMeasure::Polygons ? a.polygons() : static_cast<int>(g.vertices.size());
}

int GrowthTable::moves(int kind) const {
    int n = 0;
    for (const Move& m : moves_)
        n += kind == kGrow ? m.delta > 0 : (kind == kKeep ? m.delta == 0 : m.delta < 0);
    return n;
}

const std::vector<GrowthTable::Entry>& GrowthTable::at_star(int kind, int star) const {
    static const std::vector<Entry> kNone;
    if (star < 0 || star >= static_cast<int>(by_star_[kind].size())) return kNone;
    return by_star_[kind][star];
}

const std::vector<GrowthTable::Entry>& GrowthTable::at_label(int kind, const Label& label) const {
    static const std::vector<Entry> kNone;
    const auto it = by_label_[kind].find(label);
    return it == by_label_[kind].end() ? kNone : it->second;
}

AngleGraph grow_graph(const GrowthTable& table, std::uint64_t seed, const GrowSettings& settings,
                      GrowReport* report) {
    GrowReport local;
    GrowReport& rep = report ? *report : local;
    rep = {};
    const Grammar& grammar = table.grammar();
    Random rng(seed);
    const int target = settings.target > 0 ? settings.target : table.example_size();
    // The starter: among those no larger than the target (else the smallest), weighted by
    // the growing moves that fit it; uniform when none has any.
    const int ns = static_cast<int>(grammar.starters.size());
    int smallest = 0;
    for (int s = 1; s < ns; ++s)
        if (table.starter_size(s) < table.starter_size(smallest)) smallest = s;
    std::vector<double> weight(ns, 0.0);
    double total = 0;
    for (int s = 0; s < ns; ++s)
        if (table.starter_size(s) <= target || s == smallest)
            total += weight[s] = table.starter_weight(s);
    if (total <= 0)
        for (int s = 0; s < ns; ++s)
            if (table.starter_size(s) <= target || s == smallest) total += weight[s] = 1.0;
    double pick = rng.uniform() * total;
    int chosen = smallest;
    for (int s = 0; s < ns; ++s) {
        if (weight[s] <= 0) continue;
        chosen = s;
        if ((pick -= weight[s]) < 0) break;
    }
    State st = starter_state(table, chosen);
    rep.starter = chosen;
    rep.size = st.size;
    if (!table.can_grow() || contains(st.stars, -1)) return st.g;

    MoveStats stats(table.move_list().size());
    StepLimits limits;
    limits.upper = target + std::max(1, static_cast<int>(settings.overshoot * target));
    limits.max_vertices = settings.max_vertices;
    const int max_steps = settings.max_steps > 0 ? settings.max_steps : 4 * target + 64;
    const bool can_keep = table.moves(GrowthTable::kKeep) > 0;
    int grown = 0, reshape = -1;
    while (rep.steps < max_steps) {
        if (st.size < target) {
            ++rep.steps;
            if (can_keep && rng.uniform() < settings.keep_share &&
                sampled_step(table, st, GrowthTable::kKeep, settings.tries / 4 + 1,
                             settings.outside_share, rng, limits, stats)) {
                ++rep.applied;
                continue;
            }
            if (sampled_step(table, st, GrowthTable::kGrow, settings.tries, settings.outside_share,
                             rng, limits, stats) ||
                searched_step(table, st, GrowthTable::kGrow, rng, limits, stats)) {
                ++rep.applied;
                ++grown;
                continue;
            }
            rep.stuck = true;
            break;
        }
        if (reshape < 0) reshape = static_cast<int>(std::lround(settings.keep_share * grown));
        if (reshape == 0 || !can_keep) break;
        --reshape;
        ++rep.steps;
        if (sampled_step(table, st, GrowthTable::kKeep, settings.tries, settings.outside_share, rng,
                         limits, stats))
            ++rep.applied;
    }
    rep.step_limited = rep.steps >= max_steps && st.size < target;
    rep.vertex_limited = limits.vertex_limited;
    rep.size = st.size;
    return st.g;
}

}  // namespace sylva::layout
