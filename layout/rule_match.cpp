#include "layout/rule_match.h"

#include <algorithm>
#include <array>

namespace sylva::layout {

std::vector<int> StarTable::key(const AngleGraph& g, int v) {
    std::vector<int> k;
    k.reserve(2 * g.vertices[v].size());
    for (const Dart& d : g.vertices[v]) k.push_back(d.dir), k.push_back(d.left);
    return k;
}

int StarTable::add(const AngleGraph& g, int v) {
    return ids_.emplace(key(g, v), static_cast<int>(ids_.size())).first->second;
}

int StarTable::find(const AngleGraph& g, int v) const {
    const auto it = ids_.find(key(g, v));
    return it == ids_.end() ? -1 : it->second;
}

std::vector<int> StarTable::ids(const AngleGraph& g) const {
    std::vector<int> out(g.vertices.size());
    for (std::size_t v = 0; v < g.vertices.size(); ++v) out[v] = find(g, static_cast<int>(v));
    return out;
}

bool map_piece(const AngleGraph& piece, const std::vector<int>& piece_stars, int from,
               const AngleGraph& g, const std::vector<int>& g_stars, int anchor,
               std::vector<int>& map) {
    const std::size_t n = piece.vertices.size();
    map.assign(n, -1);
    if (piece_stars[from] < 0 || piece_stars[from] != g_stars[anchor]) return false;
    map[from] = anchor;
    // Pieces are small: a linear scan of the mapped vertices is the cheapest "used" test.
    // The work lists are reused per thread: this runs millions of times in a derivation.
    thread_local std::vector<int> stack, mapped;
    stack.assign(1, from);
    mapped.assign(1, anchor);
    while (!stack.empty()) {
        const int p = stack.back();
        stack.pop_back();
        const int gp = map[p];
        for (std::size_t i = 0; i < piece.vertices[p].size(); ++i) {
            const int q = piece.vertices[p][i].to;
            if (q < 0) continue;
            const int gq = g.vertices[gp][i].to;  // same star: same dart order
            if (gq < 0) return false;
            if (map[q] < 0) {
                if (piece_stars[q] != g_stars[gq]) return false;
                if (std::find(mapped.begin(), mapped.end(), gq) != mapped.end()) return false;
                map[q] = gq;
                mapped.push_back(gq);
                stack.push_back(q);
            } else if (map[q] != gq) {
                return false;
            }
        }
    }
    return true;
}

std::optional<AngleGraph> replace_side(const AngleGraph& g, const std::vector<int>& stars,
                                       const Directions& dirs, const SideView& x,
                                       const SideMatch& match, const SideView& y,
                                       const std::vector<std::vector<int>>& y_stars,
                                       std::vector<int>& out_stars, Analysis* analysis) {
    const int nv = static_cast<int>(g.vertices.size());
    std::vector<char> removed(nv, 0);
    for (const auto& m : match.maps)
        for (int v : m) removed[v] = 1;
    // Where each port of X attaches outside: a kept vertex and its dart into the hole.
    std::vector<std::pair<int, int>> attach;
    attach.reserve(x.ports->size());
    for (const Port& p : *x.ports) {
        int f = -1, fi = -1;
        if (x.pieces[p.piece]->floating) {
            const auto [v, i] = match.edges[p.piece];
            const int w = g.vertices[v][i].to;
            if (p.dart == 0)
                f = w, fi = g.find(w, dirs.opposite[g.vertices[v][i].dir]);
            else
                f = v, fi = i;
        } else {
            const int gv = match.maps[p.piece][p.vertex];
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
    out_stars.clear();
    for (int v = 0; v < nv; ++v)
        if (!removed[v]) {
            index[v] = static_cast<int>(h.vertices.size());
            h.vertices.push_back(g.vertices[v]);
            out_stars.push_back(stars[v]);
        }
    for (auto& ds : h.vertices)
        for (Dart& d : ds) d.to = d.to >= 0 && !removed[d.to] ? index[d.to] : -1;
    for (std::size_t p = 0; p < x.pieces.size(); ++p) {
        if (!x.pieces[p]->floating) continue;
        const auto [v, i] = match.edges[p];
        const int w = g.vertices[v][i].to;
        h.vertices[index[v]][i].to = -1;
        h.vertices[index[w]][g.find(w, dirs.opposite[g.vertices[v][i].dir])].to = -1;
    }
    for (auto& [f, fi] : attach) f = index[f];
    std::vector<int> offset;
    for (std::size_t p = 0; p < y.pieces.size(); ++p) {
        offset.push_back(static_cast<int>(h.vertices.size()));
        if (y.pieces[p]->floating) continue;
        const AngleGraph& piece = y.pieces[p]->graph;
        for (std::size_t v = 0; v < piece.vertices.size(); ++v) {
            auto ds = piece.vertices[v];
            for (Dart& d : ds)
                if (d.to >= 0) d.to += offset.back();
            h.vertices.push_back(std::move(ds));
            out_stars.push_back(y_stars[p][v]);
        }
    }
    auto glue = [&](int v, int i, int w, int j) {
        h.vertices[v][i].to = w;
        h.vertices[w][j].to = v;
    };
    std::vector<std::array<int, 2>> floating_ends(y.pieces.size(), {-1, -1});
    for (std::size_t k = 0; k < attach.size(); ++k) {
        const Port& p = (*y.ports)[k];
        const auto [f, fi] = attach[k];
        if (y.pieces[p.piece]->floating) {
            floating_ends[p.piece][p.dart] = static_cast<int>(k);
        } else {
            const int yv = offset[p.piece] + p.vertex;
            if (h.vertices[yv][p.dart].to >= 0 || h.vertices[f][fi].to >= 0) return std::nullopt;
            glue(yv, p.dart, f, fi);
        }
    }
    for (std::size_t p = 0; p < y.pieces.size(); ++p) {
        if (!y.pieces[p]->floating) continue;
        const auto [a, b] = floating_ends[p];
        if (a < 0 || b < 0) return std::nullopt;
        const auto [fa, fai] = attach[a];
        const auto [fb, fbi] = attach[b];
        if (fa == fb || h.vertices[fa][fai].to >= 0 || h.vertices[fb][fbi].to >= 0)
            return std::nullopt;
        glue(fa, fai, fb, fbi);
    }
    Analysis a = analyze(h, dirs);
    if (!a.planar || !a.complete) return std::nullopt;
    if (analysis) *analysis = std::move(a);
    return h;
}

}  // namespace sylva::layout
