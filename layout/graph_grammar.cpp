#include "layout/graph_grammar.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <tuple>

#include "core/errors.h"
#include "core/random.h"

namespace sylva::layout {

namespace {

// A label's three fields, each its own element of a key: no packing that overflows (one int
// overflowed at 128 edge directions) or makes two labels equal (4096 colours). The order is
// the packed code's order for every label it could hold.
void push_label(std::vector<int>& key, const Label& l) {
    key.push_back(l.dir);
    key.push_back(l.left);
    key.push_back(l.right);
}

// The key of a run of boundary items: labels and the wraps between them (not after the last).
std::vector<int> run_key(const Boundary& b, std::size_t start, std::size_t length) {
    std::vector<int> key;
    key.reserve(4 * length);
    for (std::size_t k = 0; k < length; ++k) {
        const BoundaryItem& item = b[(start + k) % b.size()];
        push_label(key, item.label);
        if (k + 1 < length) key.push_back(item.wraps);
    }
    return key;
}

// A closed boundary's key: the smallest rotation of labels and wraps.
std::vector<int> closed_key(const Boundary& b) {
    std::vector<int> best;
    for (std::size_t r = 0; r < b.size(); ++r) {
        std::vector<int> key = run_key(b, r, b.size());
        key.push_back(b[(r + b.size() - 1) % b.size()].wraps);
        if (best.empty() || key < best) best = std::move(key);
    }
    return best;
}

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

class Decomposer {
  public:
    Decomposer(const Directions& dirs, int max_pieces) : dirs_(dirs), max_pieces_(max_pieces) {}

    void add(Piece piece) {
        Candidate c{std::move(piece), {}};
        c.boundary = piece_boundary(c.piece, dirs_);
        const int index = static_cast<int>(candidates_.size());
        closed_.emplace(closed_key(c.boundary), index);
        // Every opening of the boundary: a rotation, all items, the wrap at the end dropped.
        for (std::size_t r = 0; r < c.boundary.size(); ++r)
            open_[run_key(c.boundary, r, c.boundary.size())].emplace_back(index,
                                                                          static_cast<int>(r));
        candidates_.push_back(std::move(c));
    }

    const Candidate& candidate(int i) const { return candidates_[i]; }

    // Pieces whose boundaries compose `b` (positions[i] is b[i]'s place in the original).
    std::optional<std::vector<Placed>> decompose(const Boundary& b,
                                                 const std::vector<int>& positions,
                                                 int depth) const {
        const std::size_t n = b.size();
        const auto exact = closed_.find(closed_key(b));
        if (exact != closed_.end()) {
            const Candidate& c = candidates_[exact->second];
            const int r = boundary_match(b, c.boundary);
            if (r >= 0) {
                Placed p{exact->second, {}};
                for (std::size_t i = 0; i < n; ++i)
                    p.positions.emplace_back(positions[i], static_cast<int>((i + r) % n));
                return std::vector<Placed>{p};
            }
        }
        if (depth >= max_pieces_) return std::nullopt;
        // A run of b that is a whole opened candidate; the rest, closed with the turn that
        // makes it 360 degrees, must decompose too (R1 v R2: the extra v is the joint).
        for (std::size_t length = n - 1; length >= 1; --length)
            for (std::size_t s = 0; s < n; ++s) {
                const auto it = open_.find(run_key(b, s, length));
                if (it == open_.end()) continue;
                Boundary rest;
                std::vector<int> rest_positions;
                double sum = 0;
                for (std::size_t k = length; k < n; ++k) {
                    rest.push_back(b[(s + k) % n]);
                    rest_positions.push_back(positions[(s + k) % n]);
                    if (k + 1 < n) sum += rest.back().turn;
                }
                rest.back().turn = 360.0 - sum;
                set_wraps(rest, dirs_);
                auto tail = decompose(rest, rest_positions, depth + 1);
                if (!tail) continue;
                const auto [index, rotation] = it->second.front();
                Placed p{index, {}};
                const std::size_t m = candidates_[index].boundary.size();
                for (std::size_t k = 0; k < length; ++k)
                    p.positions.emplace_back(positions[(s + k) % n],
                                             static_cast<int>((rotation + k) % m));
                tail->insert(tail->begin(), p);
                return tail;
            }
        return std::nullopt;
    }

  private:
    const Directions& dirs_;
    int max_pieces_;
    std::vector<Candidate> candidates_;
    std::map<std::vector<int>, int> closed_;
    std::map<std::vector<int>, std::vector<std::pair<int, int>>> open_;
};

Port port_of(const BoundaryItem& item, int piece, bool floating) {
    if (floating) return {piece, -1, item.dart};
    return {piece, item.vertex, item.dart};
}

bool same_star(const AngleGraph& a, int va, const AngleGraph& b, int vb) {
    const auto& x = a.vertices[va];
    const auto& y = b.vertices[vb];
    if (x.size() != y.size()) return false;
    for (std::size_t i = 0; i < x.size(); ++i)
        if (x[i].dir != y[i].dir || x[i].left != y[i].left) return false;
    return true;
}

// Maps a connected piece into g with piece vertex 0 at `anchor`; false when it does not fit.
bool map_piece(const AngleGraph& piece, const AngleGraph& g, int anchor, std::vector<int>& map) {
    map.assign(piece.vertices.size(), -1);
    map[0] = anchor;
    std::vector<int> stack{0};
    std::set<int> used{anchor};
    while (!stack.empty()) {
        const int p = stack.back();
        stack.pop_back();
        if (!same_star(piece, p, g, map[p])) return false;
        for (std::size_t i = 0; i < piece.vertices[p].size(); ++i) {
            const int q = piece.vertices[p][i].to;
            if (q < 0) continue;
            const int gq = g.vertices[map[p]][i].to;  // same star: same dart order
            if (gq < 0) return false;
            if (map[q] < 0) {
                if (!used.insert(gq).second) return false;
                map[q] = gq;
                stack.push_back(q);
            } else if (map[q] != gq) {
                return false;
            }
        }
    }
    return true;
}

std::vector<int> star_key(const AngleGraph& g, int v) {
    std::vector<int> key;
    for (const Dart& d : g.vertices[v]) key.push_back(d.dir), key.push_back(d.left);
    return key;
}

void glue(AngleGraph& g, int v, int i, int w, int j) {
    g.vertices[v][i].to = w;
    g.vertices[w][j].to = v;
}

}  // namespace

Boundary piece_boundary(const Piece& piece, const Directions& dirs) {
    if (piece.floating) {
        Boundary b(2);
        b[0].label = piece.edge;  // the head end, pointing out along the edge
        b[0].dart = 0;
        b[1].label = reversed(piece.edge, dirs);
        b[1].dart = 1;
        b[0].turn = b[1].turn = 180.0;
        set_wraps(b, dirs);
        return b;
    }
    return analyze(piece.graph, dirs).boundary;
}

Grammar derive_grammar(const Example& example, const DeriveSettings& settings) {
    Grammar grammar;
    grammar.dirs = example.dirs;
    const Directions& dirs = grammar.dirs;
    grammar.example_vertices = static_cast<int>(example.graph.vertices.size());
    const int max_vertices =
        settings.max_vertices > 0 ? settings.max_vertices : grammar.example_vertices;

    // Generation 1: the primitives (one vertex, every edge split), without duplicates.
    std::set<std::vector<int>> seen;
    for (std::size_t v = 0; v < example.graph.vertices.size(); ++v) {
        AngleGraph p;
        p.vertices.push_back(example.graph.vertices[v]);
        for (Dart& d : p.vertices[0]) d.to = -1;
        if (seen.insert(canonical_code(p)).second) grammar.primitives.push_back(p);
    }
    Decomposer decomposer(dirs, settings.max_pieces);
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

    // Rules by the star of their left side's vertex 0: a new graph that contains a rule's left
    // side is reduced by that rule, so it (and all it would grow into) leaves the hierarchy.
    std::map<std::vector<int>, std::vector<int>> rules_by_star;
    auto reducible = [&](const AngleGraph& c) {
        std::vector<int> map;
        for (int v = 0; v < static_cast<int>(c.vertices.size()); ++v) {
            const auto it = rules_by_star.find(star_key(c, v));
            if (it == rules_by_star.end()) continue;
            for (int r : it->second)
                if (map_piece(grammar.rules[r].left, c, v, map)) return true;
        }
        return false;
    };
    std::vector<AngleGraph> frontier = grammar.primitives;
    grammar.hierarchy_graphs = static_cast<int>(frontier.size());
    grammar.generations = 1;
    bool stopped = false;
    for (int gen = 2; gen <= settings.max_generations && !frontier.empty() && !stopped; ++gen) {
        grammar.generations = gen;
        std::vector<AngleGraph> next;
        auto consider = [&](AngleGraph&& child) {
            if (static_cast<int>(child.vertices.size()) > max_vertices) return;
            if (!seen.insert(canonical_code(child)).second) return;
            const Analysis a = analyze(child, dirs);
            if (!a.planar || reducible(child)) return;
            ++grammar.hierarchy_graphs;
            if (a.complete) {
                grammar.starters.push_back(std::move(child));
                return;
            }
            std::vector<int> positions(a.boundary.size());
            for (std::size_t i = 0; i < positions.size(); ++i) positions[i] = static_cast<int>(i);
            if (auto parts = decomposer.decompose(a.boundary, positions, 1)) {
                Rule rule;
                rule.left = child;
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
                rules_by_star[star_key(rule.left, 0)].push_back(
                    static_cast<int>(grammar.rules.size()));
                grammar.rules.push_back(std::move(rule));
                return;
            }
            decomposer.add({child, false, {}});
            next.push_back(std::move(child));
            if (grammar.hierarchy_graphs >= settings.max_graphs) stopped = true;
        };
        for (const AngleGraph& g : frontier) {
            if (stopped) break;
            const Boundary b = analyze(g, dirs).boundary;
            const std::size_t n = b.size();
            // Loop gluing: a and a-bar next to each other, closing a face.
            for (std::size_t i = 0; i < n && n >= 2; ++i) {
                const BoundaryItem& x = b[i];
                const BoundaryItem& y = b[(i + 1) % n];
                if (y.label != reversed(x.label, dirs) || std::abs(x.turn + 180.0) > 1e-6) continue;
                AngleGraph child = g;
                glue(child, x.vertex, x.dart, y.vertex, y.dart);
                consider(std::move(child));
            }
            // Branch gluing with every primitive that has the opposite half-edge.
            for (const BoundaryItem& x : b) {
                const auto it = primitive_darts.find(reversed(x.label, dirs));
                if (it == primitive_darts.end()) continue;
                for (const auto& [p, i] : it->second) {
                    AngleGraph child = g;
                    child.vertices.push_back(grammar.primitives[p].vertices[0]);
                    glue(child, x.vertex, x.dart, static_cast<int>(child.vertices.size()) - 1, i);
                    consider(std::move(child));
                }
            }
        }
        frontier = std::move(next);
    }
    grammar.open_graphs = static_cast<int>(frontier.size());
    // The example itself is a complete graph the hierarchy reaches given room enough; when
    // the limits stopped growth before it, it is added as a starter so the grammar always
    // derives at least the example's structure.
    if (seen.insert(canonical_code(example.graph)).second)
        grammar.starters.push_back(example.graph);
    return grammar;
}

// ---- Applying rules ----

namespace {

struct Side {
    std::vector<const Piece*> pieces;
    const std::vector<Port>* ports = nullptr;
};

template <class T>
void shuffle(std::vector<T>& v, Random& rng) {
    for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[rng.next() % i]);
}

// Cuts the matched side X out of g and glues Y in; nullopt when the match does not lead to a
// planar complete graph.
std::optional<AngleGraph> replace(const AngleGraph& g, const Directions& dirs, const Side& x,
                                  const std::vector<std::vector<int>>& maps,
                                  const std::vector<std::pair<int, int>>& edges, const Side& y) {
    const int nv = static_cast<int>(g.vertices.size());
    std::vector<char> removed(nv, 0);
    for (const auto& m : maps)
        for (int v : m) removed[v] = 1;
    // Where each port of X attaches outside: a kept vertex and its dart into the hole.
    std::vector<std::pair<int, int>> attach;
    for (const Port& p : *x.ports) {
        int f = -1, fi = -1;
        if (x.pieces[p.piece]->floating) {
            const auto [v, i] = edges[p.piece];
            const int w = g.vertices[v][i].to;
            if (p.dart == 0)
                f = w, fi = g.find(w, dirs.opposite[g.vertices[v][i].dir]);
            else
                f = v, fi = i;
        } else {
            const int gv = maps[p.piece][p.vertex];
            const Dart& d = g.vertices[gv][p.dart];
            f = d.to;
            if (f < 0) return std::nullopt;
            fi = g.find(f, dirs.opposite[d.dir]);
        }
        if (f < 0 || removed[f]) return std::nullopt;
        attach.emplace_back(f, fi);
    }
    std::vector<int> index(nv, -1);
    AngleGraph h;
    for (int v = 0; v < nv; ++v)
        if (!removed[v])
            index[v] = static_cast<int>(h.vertices.size()), h.vertices.push_back(g.vertices[v]);
    for (auto& ds : h.vertices)
        for (Dart& d : ds) d.to = d.to >= 0 && !removed[d.to] ? index[d.to] : -1;
    for (const auto& [v, i] : edges) {
        if (v < 0) continue;  // a vertex piece
        const int w = g.vertices[v][i].to;
        h.vertices[index[v]][i].to = -1;
        h.vertices[index[w]][g.find(w, dirs.opposite[g.vertices[v][i].dir])].to = -1;
    }
    for (auto& [f, fi] : attach) f = index[f];
    std::vector<int> offset;
    for (const Piece* p : y.pieces) {
        offset.push_back(static_cast<int>(h.vertices.size()));
        if (p->floating) continue;
        for (auto ds : p->graph.vertices) {
            for (Dart& d : ds)
                if (d.to >= 0) d.to += offset.back();
            h.vertices.push_back(ds);
        }
    }
    std::vector<std::array<int, 2>> floating_ends(y.pieces.size(), {-1, -1});
    for (std::size_t k = 0; k < attach.size(); ++k) {
        const Port& p = (*y.ports)[k];
        const auto [f, fi] = attach[k];
        if (y.pieces[p.piece]->floating) {
            floating_ends[p.piece][p.dart] = static_cast<int>(k);
        } else {
            const int yv = offset[p.piece] + p.vertex;
            if (h.vertices[yv][p.dart].to >= 0 || h.vertices[f][fi].to >= 0) return std::nullopt;
            glue(h, yv, p.dart, f, fi);
        }
    }
    for (std::size_t p = 0; p < y.pieces.size(); ++p) {
        if (!y.pieces[p]->floating) continue;
        const auto [a, b] = floating_ends[p];
        if (a < 0 || b < 0) return std::nullopt;
        const auto [fa, fai] = attach[a];
        const auto [fb, fbi] = attach[b];
        if (h.vertices[fa][fai].to >= 0 || h.vertices[fb][fbi].to >= 0) return std::nullopt;
        glue(h, fa, fai, fb, fbi);
    }
    const Analysis a = analyze(h, dirs);
    if (!a.planar || !a.complete) return std::nullopt;
    return h;
}

std::optional<AngleGraph> apply_side(const AngleGraph& g, const Directions& dirs, const Side& x,
                                     const Side& y, Random& rng, int budget) {
    const int nv = static_cast<int>(g.vertices.size());
    // Candidates per piece.
    std::vector<std::vector<std::vector<int>>> vertex_options(x.pieces.size());
    std::vector<std::vector<std::pair<int, int>>> edge_options(x.pieces.size());
    for (std::size_t p = 0; p < x.pieces.size(); ++p) {
        const Piece& piece = *x.pieces[p];
        if (piece.floating) {
            for (int v = 0; v < nv; ++v)
                for (std::size_t i = 0; i < g.vertices[v].size(); ++i)
                    if (g.vertices[v][i].to >= 0 &&
                        dart_label(g, v, static_cast<int>(i)) == piece.edge)
                        edge_options[p].emplace_back(v, static_cast<int>(i));
            if (edge_options[p].empty()) return std::nullopt;
            shuffle(edge_options[p], rng);
        } else {
            std::vector<int> anchors(nv);
            for (int v = 0; v < nv; ++v) anchors[v] = v;
            shuffle(anchors, rng);
            std::vector<int> map;
            for (int v : anchors)
                if (map_piece(piece.graph, g, v, map)) vertex_options[p].push_back(map);
            if (vertex_options[p].empty()) return std::nullopt;
        }
    }
    // Try combinations (pieces disjoint) until one gives a planar graph.
    const std::size_t np = x.pieces.size();
    std::vector<std::size_t> choice(np, 0);
    std::vector<std::vector<int>> maps(np);
    std::vector<std::pair<int, int>> edges(np, {-1, -1});
    int tries = 0;
    std::function<std::optional<AngleGraph>(std::size_t, std::set<int>&,
                                            std::set<std::pair<int, int>>&)>
        pick = [&](std::size_t p, std::set<int>& used_vertices,
                   std::set<std::pair<int, int>>& used_edges) -> std::optional<AngleGraph> {
        if (tries >= budget) return std::nullopt;
        if (p == np) {
            ++tries;
            // Floating edges must not touch the removed vertices.
            for (std::size_t q = 0; q < np; ++q)
                if (x.pieces[q]->floating) {
                    const auto [v, i] = edges[q];
                    if (used_vertices.count(v) || used_vertices.count(g.vertices[v][i].to))
                        return std::nullopt;
                }
            return replace(g, dirs, x, maps, edges, y);
        }
        if (x.pieces[p]->floating) {
            for (const auto& e : edge_options[p]) {
                const int w = g.vertices[e.first][e.second].to;
                const std::pair<int, int> key{std::min(e.first, w), std::max(e.first, w)};
                if (used_edges.count(key)) continue;
                used_edges.insert(key);
                edges[p] = e;
                maps[p].clear();
                auto r = pick(p + 1, used_vertices, used_edges);
                used_edges.erase(key);
                if (r || tries >= budget) return r;
            }
            return std::nullopt;
        }
        for (const auto& m : vertex_options[p]) {
            bool clash = false;
            for (int v : m) clash = clash || used_vertices.count(v);
            if (clash) continue;
            for (int v : m) used_vertices.insert(v);
            maps[p] = m;
            auto r = pick(p + 1, used_vertices, used_edges);
            for (int v : m) used_vertices.erase(v);
            if (r || tries >= budget) return r;
        }
        return std::nullopt;
    };
    std::set<int> used_vertices;
    std::set<std::pair<int, int>> used_edges;
    return pick(0, used_vertices, used_edges);
}

}  // namespace

AngleGraph derive_graph(const Grammar& grammar, std::uint64_t seed,
                        const GenerateSettings& settings) {
    if (grammar.starters.empty()) throw InputError("the grammar has no starter rule");
    Random rng(seed);
    AngleGraph g = grammar.starters[rng.next() % grammar.starters.size()];
    const int max_vertices = settings.max_vertices > 0 ? settings.max_vertices
                                                       : std::max(24, 3 * grammar.example_vertices);
    if (grammar.rules.empty()) return g;
    for (int step = 0; step < settings.steps; ++step) {
        const Rule& rule = grammar.rules[rng.next() % grammar.rules.size()];
        const bool grow = rng.uniform() < settings.grow;
        Side left{{}, &rule.left_ports};
        Piece left_piece{rule.left, false, {}};
        left.pieces.push_back(&left_piece);
        Side right{{}, &rule.right_ports};
        for (const Piece& p : rule.right) right.pieces.push_back(&p);
        std::optional<AngleGraph> h = grow ? apply_side(g, grammar.dirs, right, left, rng, 24)
                                           : apply_side(g, grammar.dirs, left, right, rng, 24);
        if (h && static_cast<int>(h->vertices.size()) <= max_vertices) g = std::move(*h);
    }
    return g;
}

// ---- Grammar files ----

namespace {

nlohmann::ordered_json graph_json(const AngleGraph& g) {
    nlohmann::ordered_json vs = nlohmann::ordered_json::array();
    for (const auto& ds : g.vertices) {
        nlohmann::ordered_json v = nlohmann::ordered_json::array();
        for (const Dart& d : ds) v.push_back({d.dir, d.left, d.to});
        vs.push_back(std::move(v));
    }
    return vs;
}

nlohmann::ordered_json ports_json(const std::vector<Port>& ports) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const Port& p : ports) out.push_back({p.piece, p.vertex, p.dart});
    return out;
}

}  // namespace

std::string write_grammar_json(const Grammar& grammar) {
    nlohmann::ordered_json doc;
    doc["format"] = "sylva-layout-grammar";
    doc["version"] = 1;
    doc["directions"] = grammar.dirs.degrees;
    doc["opposite"] = grammar.dirs.opposite;
    doc["mean_length"] = grammar.dirs.mean_length;
    doc["label_length"] = grammar.dirs.label_length;
    nlohmann::ordered_json palette = nlohmann::ordered_json::array();
    for (std::uint32_t c : grammar.dirs.palette) palette.push_back(color_hex(c));
    doc["palette"] = palette;
    doc["example_vertices"] = grammar.example_vertices;
    doc["hierarchy"] = {{"graphs", grammar.hierarchy_graphs},
                        {"generations", grammar.generations},
                        {"open_graphs", grammar.open_graphs}};
    doc["primitives"] = nlohmann::ordered_json::array();
    for (const AngleGraph& p : grammar.primitives) doc["primitives"].push_back(graph_json(p));
    doc["starters"] = nlohmann::ordered_json::array();
    for (const AngleGraph& s : grammar.starters) doc["starters"].push_back(graph_json(s));
    doc["rules"] = nlohmann::ordered_json::array();
    for (const Rule& r : grammar.rules) {
        nlohmann::ordered_json rule;
        rule["boundary"] = r.boundary;
        rule["left"] = graph_json(r.left);
        rule["left_ports"] = ports_json(r.left_ports);
        rule["right"] = nlohmann::ordered_json::array();
        for (const Piece& p : r.right) {
            if (p.floating)
                rule["right"].push_back({{"edge", {p.edge.dir, p.edge.left, p.edge.right}}});
            else
                rule["right"].push_back({{"graph", graph_json(p.graph)}});
        }
        rule["right_ports"] = ports_json(r.right_ports);
        doc["rules"].push_back(std::move(rule));
    }
    return doc.dump() + "\n";
}

namespace {

const nlohmann::json& member(const nlohmann::json& j, const std::string& name) {
    static const nlohmann::json kNull;
    if (!j.is_object()) return kNull;
    const auto it = j.find(name);
    return it == j.end() ? kNull : *it;
}

struct GrammarReader {
    const std::string& source;
    int directions = 0;
    int colors = 0;

    [[noreturn]] void fail(const std::string& key, const std::string& what) const {
        throw InputError(key + ": " + what, {source});
    }
    int integer(const nlohmann::json& j, const std::string& key, int lo, int hi) const {
        if (!j.is_number_integer() || j.get<long long>() < lo || j.get<long long>() > hi)
            fail(key, "expected an integer in " + std::to_string(lo) + ".." + std::to_string(hi));
        return static_cast<int>(j.get<long long>());
    }
    const nlohmann::json& array(const nlohmann::json& j, const std::string& key) const {
        if (!j.is_array()) fail(key, "expected an array");
        return j;
    }
    AngleGraph graph(const nlohmann::json& j, const std::string& key) const {
        AngleGraph g;
        const auto& vs = array(j, key);
        if (vs.size() > 4096) fail(key, "more than 4096 vertices");
        for (std::size_t v = 0; v < vs.size(); ++v) {
            const std::string vk = key + "[" + std::to_string(v) + "]";
            auto& ds = g.vertices.emplace_back();
            for (std::size_t i = 0; i < array(vs[v], vk).size(); ++i) {
                const std::string dk = vk + "[" + std::to_string(i) + "]";
                const auto& d = vs[v][i];
                if (!d.is_array() || d.size() != 3)
                    fail(dk, "expected [direction, colour, vertex]");
                ds.push_back({integer(d[0], dk, 0, directions - 1),
                              integer(d[1], dk, 0, colors - 1),
                              integer(d[2], dk, -1, static_cast<int>(vs.size()) - 1)});
            }
        }
        return g;
    }
};

}  // namespace

Grammar read_grammar_json(const std::string& text, const std::string& source) {
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        throw InputError("not JSON: " + std::string(e.what()), {source});
    }
    GrammarReader in{source};
    if (!doc.is_object() || member(doc, "format") != "sylva-layout-grammar")
        in.fail("format", "expected \"sylva-layout-grammar\"");
    Grammar g;
    const auto& dirs = in.array(member(doc, "directions"), "directions");
    if (dirs.empty() || dirs.size() > 4096) in.fail("directions", "expected 1 to 4096 angles");
    for (const auto& d : dirs) {
        if (!d.is_number() || d.get<double>() < 0 || d.get<double>() >= 360)
            in.fail("directions", "expected angles in [0, 360)");
        g.dirs.degrees.push_back(d.get<double>());
    }
    in.directions = static_cast<int>(g.dirs.degrees.size());
    for (std::size_t i = 1; i < g.dirs.degrees.size(); ++i)
        if (g.dirs.degrees[i] <= g.dirs.degrees[i - 1])
            in.fail("directions", "expected ascending angles");
    const auto& opp = in.array(member(doc, "opposite"), "opposite");
    if (opp.size() != dirs.size()) in.fail("opposite", "expected one entry per direction");
    for (const auto& o : opp)
        g.dirs.opposite.push_back(in.integer(o, "opposite", 0, in.directions - 1));
    for (int d = 0; d < in.directions; ++d)
        if (g.dirs.opposite[g.dirs.opposite[d]] != d ||
            std::abs(
                std::fmod(g.dirs.degrees[g.dirs.opposite[d]] - g.dirs.degrees[d] + 720.0, 360.0) -
                180.0) > 1e-3)
            in.fail("opposite", "direction " + std::to_string(d) +
                                    " and its opposite are not 180 degrees apart");
    const auto& lengths = in.array(member(doc, "mean_length"), "mean_length");
    if (lengths.size() != dirs.size()) in.fail("mean_length", "expected one entry per direction");
    for (const auto& l : lengths) {
        if (!l.is_number() || !(l.get<double>() > 0) || l.get<double>() > 1e7)
            in.fail("mean_length", "expected lengths > 0");
        g.dirs.mean_length.push_back(l.get<double>());
    }
    const auto& palette = in.array(member(doc, "palette"), "palette");
    if (palette.empty() || palette.size() > 4096) in.fail("palette", "expected 1 to 4096 colours");
    for (const auto& c : palette) {
        const std::string s = c.is_string() ? c.get<std::string>() : "";
        if (s.size() != 7 || s[0] != '#' ||
            s.find_first_not_of("0123456789abcdefABCDEF", 1) != std::string::npos)
            in.fail("palette", "expected colours \"#rrggbb\"");
        g.dirs.palette.push_back(static_cast<std::uint32_t>(std::stoul(s.substr(1), nullptr, 16)));
    }
    in.colors = g.dirs.colors();
    const auto& label_lengths = in.array(member(doc, "label_length"), "label_length");
    if (label_lengths.size() != dirs.size() * palette.size() * palette.size())
        in.fail("label_length", "expected directions x colours x colours entries");
    for (const auto& l : label_lengths) {
        if (!l.is_number() || !(l.get<double>() >= 0) || l.get<double>() > 1e7)
            in.fail("label_length", "expected lengths >= 0");
        g.dirs.label_length.push_back(l.get<double>());
    }
    g.example_vertices =
        in.integer(member(doc, "example_vertices"), "example_vertices", 1, 1 << 20);
    auto checked = [&](const nlohmann::json& j, const std::string& key, bool complete) {
        AngleGraph graph = in.graph(j, key);
        const Analysis a = analyze(graph, g.dirs);
        if (!a.planar) in.fail(key, "not a planar angle graph (" + a.why + ")");
        if (a.complete != complete)
            in.fail(key, complete ? "expected a complete graph" : "expected half-edges");
        return graph;
    };
    const auto& hierarchy = member(doc, "hierarchy");
    g.hierarchy_graphs = in.integer(member(hierarchy, "graphs"), "hierarchy.graphs", 0, 1 << 30);
    g.generations =
        in.integer(member(hierarchy, "generations"), "hierarchy.generations", 0, 1 << 30);
    g.open_graphs =
        in.integer(member(hierarchy, "open_graphs"), "hierarchy.open_graphs", 0, 1 << 30);
    const auto& primitives = in.array(member(doc, "primitives"), "primitives");
    for (std::size_t i = 0; i < primitives.size(); ++i)
        g.primitives.push_back(
            checked(primitives[i], "primitives[" + std::to_string(i) + "]", false));
    const auto& starters = in.array(member(doc, "starters"), "starters");
    for (std::size_t i = 0; i < starters.size(); ++i)
        g.starters.push_back(checked(starters[i], "starters[" + std::to_string(i) + "]", true));
    const auto& rules = in.array(member(doc, "rules"), "rules");
    for (std::size_t r = 0; r < rules.size(); ++r) {
        const std::string key = "rules[" + std::to_string(r) + "]";
        const auto& j = rules[r];
        if (!j.is_object()) in.fail(key, "expected an object");
        Rule rule;
        rule.left = checked(member(j, "left"), key + ".left", false);
        if (member(j, "boundary").is_string())
            rule.boundary = member(j, "boundary").get<std::string>();
        const auto& right = in.array(member(j, "right"), key + ".right");
        if (right.empty() || right.size() > 16) in.fail(key + ".right", "expected 1 to 16 pieces");
        for (std::size_t p = 0; p < right.size(); ++p) {
            const std::string pk = key + ".right[" + std::to_string(p) + "]";
            Piece piece;
            if (right[p].is_object() && right[p].contains("edge")) {
                const auto& e = right[p]["edge"];
                if (!e.is_array() || e.size() != 3)
                    in.fail(pk + ".edge", "expected [direction, left, right]");
                piece.floating = true;
                piece.edge = {in.integer(e[0], pk, 0, in.directions - 1),
                              in.integer(e[1], pk, 0, in.colors - 1),
                              in.integer(e[2], pk, 0, in.colors - 1)};
            } else if (right[p].is_object() && right[p].contains("graph")) {
                piece.graph = checked(right[p]["graph"], pk + ".graph", false);
            } else {
                in.fail(pk, "expected {\"edge\": ...} or {\"graph\": ...}");
            }
            rule.right.push_back(std::move(piece));
        }
        // Ports: both sides list the same boundary places, with equal labels.
        auto ports = [&](const char* name, const std::vector<Piece>& pieces) {
            std::vector<Port> out;
            const auto& ps = in.array(member(j, name), key + "." + name);
            for (std::size_t i = 0; i < ps.size(); ++i) {
                const std::string k = key + "." + name + "[" + std::to_string(i) + "]";
                if (!ps[i].is_array() || ps[i].size() != 3)
                    in.fail(k, "expected [piece, vertex, dart]");
                Port p;
                p.piece = in.integer(ps[i][0], k, 0, static_cast<int>(pieces.size()) - 1);
                const Piece& piece = pieces[p.piece];
                if (piece.floating) {
                    p.vertex = in.integer(ps[i][1], k, -1, -1);
                    p.dart = in.integer(ps[i][2], k, 0, 1);
                } else {
                    p.vertex = in.integer(ps[i][1], k, 0,
                                          static_cast<int>(piece.graph.vertices.size()) - 1);
                    p.dart =
                        in.integer(ps[i][2], k, 0,
                                   static_cast<int>(piece.graph.vertices[p.vertex].size()) - 1);
                    if (piece.graph.vertices[p.vertex][p.dart].to >= 0)
                        in.fail(k, "not a half-edge");
                }
                out.push_back(p);
            }
            return out;
        };
        const std::vector<Piece> left_pieces{{rule.left, false, {}}};
        rule.left_ports = ports("left_ports", left_pieces);
        rule.right_ports = ports("right_ports", rule.right);
        auto port_label = [&](const Piece& piece, const Port& p) {
            if (piece.floating) return p.dart == 0 ? piece.edge : reversed(piece.edge, g.dirs);
            return dart_label(piece.graph, p.vertex, p.dart);
        };
        std::size_t right_half_edges = 0;
        for (const Piece& p : rule.right) right_half_edges += p.floating ? 2 : p.graph.half_edges();
        if (rule.left_ports.size() != static_cast<std::size_t>(rule.left.half_edges()) ||
            rule.right_ports.size() != rule.left_ports.size() ||
            right_half_edges != rule.right_ports.size())
            in.fail(key, "the ports do not cover the boundary");
        std::set<std::tuple<int, int, int>> distinct;
        for (std::size_t i = 0; i < rule.left_ports.size(); ++i) {
            const Port& l = rule.left_ports[i];
            const Port& rp = rule.right_ports[i];
            if (port_label(left_pieces[0], l) != port_label(rule.right[rp.piece], rp))
                in.fail(key,
                        "port " + std::to_string(i) + " has different labels on the two sides");
            if (!distinct.insert({0, l.vertex, l.dart}).second ||
                !distinct.insert({1 + rp.piece, rp.vertex, rp.dart}).second)
                in.fail(key, "port " + std::to_string(i) + " repeats a half-edge");
        }
        g.rules.push_back(std::move(rule));
    }
    if (g.starters.empty()) in.fail("starters", "a grammar needs a starter rule");
    return g;
}

}  // namespace sylva::layout
