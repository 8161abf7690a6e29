#include "layout/rectangularize.h"

#include <algorithm>
#include <cmath>

namespace sylva::layout {

bool orthogonal(const Directions& dirs) {
    if (dirs.degrees.size() != 4) return false;
    for (double d : dirs.degrees) {
        const double r = std::fmod(d - dirs.degrees[0] + 720.0, 90.0);
        if (std::min(r, 90.0 - r) > 1e-6) return false;
    }
    return true;
}

namespace {

struct Work {
    AngleGraph g;
    std::vector<std::vector<std::pair<int, int>>> origin;
    const Directions& dirs;

    // Adds a dart at v keeping the counter-clockwise order.
    void add_dart(int v, Dart d, std::pair<int, int> from) {
        auto& ds = g.vertices[v];
        auto& os = origin[v];
        std::size_t at = 0;
        while (at < ds.size() && ds[at].dir < d.dir) ++at;
        ds.insert(ds.begin() + static_cast<long>(at), d);
        os.insert(os.begin() + static_cast<long>(at), from);
    }
    int add_vertex() {
        g.vertices.emplace_back();
        origin.emplace_back();
        return static_cast<int>(g.vertices.size()) - 1;
    }
    // The turn of a walk at the start of its dart k: -90 convex, 0 straight, +90 reflex (with
    // the face on the right, as analyze() walks).
    int turn(const Walk& w, std::size_t k) const {
        const auto [pv, pi] = w.darts[(k + w.darts.size() - 1) % w.darts.size()];
        const auto [v, i] = w.darts[k];
        double gap = dirs.degrees[g.vertices[v][i].dir] -
                     dirs.degrees[dirs.opposite[g.vertices[pv][pi].dir]];
        if (gap <= 1e-6) gap += 360.0;
        return static_cast<int>(std::lround(gap - 180.0));
    }
};

// Cuts one rectangle off a face with a reflex, convex, convex pattern; false when no face
// (or, with `outer` false, no inner face) has one.
bool refine_once(Work& w, bool outer) {
    const Analysis a = analyze(w.g, w.dirs);
    if (!a.planar || !a.complete) return false;
    for (std::size_t f = 0; f < a.walks.size(); ++f) {
        const Walk& walk = a.walks[f];
        if (!outer && walk.turning > 0) continue;
        const std::size_t m = walk.darts.size();
        std::vector<int> turns(m);
        for (std::size_t k = 0; k < m; ++k) turns[k] = w.turn(walk, k);
        for (std::size_t kr = 0; kr < m; ++kr) {
            if (turns[kr] != 90) continue;
            std::size_t k1 = kr, k2 = kr;
            auto next_turn = [&](std::size_t from) {
                for (std::size_t s = 1; s < m; ++s)
                    if (turns[(from + s) % m] != 0) return (from + s) % m;
                return from;
            };
            k1 = next_turn(kr);
            k2 = next_turn(k1);
            if (k1 == kr || k2 == kr || turns[k1] != -90 || turns[k2] != -90) continue;
            const auto [pv, pi] = walk.darts[(kr + m - 1) % m];
            const int d = w.g.vertices[pv][pi].dir;  // the heading arriving at r
            const int r = walk.darts[kr].first;
            const auto [u, iu] = walk.darts[k2];
            const int wv = w.g.vertices[u][iu].to;
            const int e = w.g.vertices[u][iu].dir;
            const int jw = w.g.find(wv, w.dirs.opposite[e]);
            const int face_color = w.g.vertices[wv][jw].left;  // the face is right of u -> w
            const Dart forward = w.g.vertices[u][iu];
            const std::pair<int, int> o_forward = w.origin[u][iu], o_back = w.origin[wv][jw];
            const int t = w.add_vertex();
            w.g.vertices[u][iu].to = t;
            w.g.vertices[wv][jw].to = t;
            w.add_dart(t, {e, forward.left, wv}, o_forward);
            w.add_dart(t, {w.dirs.opposite[e], face_color, u}, o_back);
            w.add_dart(t, {w.dirs.opposite[d], face_color, r}, {-1, -1});
            w.add_dart(r, {d, face_color, t}, {-1, -1});
            return true;
        }
    }
    return false;
}

// Encloses the graph in a rectangle, every reflex corner of the outside extended to it.
bool frame(Work& w) {
    const Analysis a = analyze(w.g, w.dirs);
    if (!a.planar || !a.complete || a.outer < 0) return false;
    const Walk& outer = a.walks[a.outer];
    // The four headings, counter-clockwise from the first direction: sides E, N, W, S.
    int heading[4];
    for (int s = 0; s < 4; ++s) heading[s] = s;  // dirs are sorted: base, +90, +180, +270
    auto side_of = [&](int dir) { return dir; };
    struct Extension {
        int r, dir, side;
    };
    std::vector<Extension> ext;
    const std::size_t m = outer.darts.size();
    for (std::size_t k = 0; k < m; ++k) {
        if (w.turn(outer, k) != 90) continue;
        const auto [pv, pi] = outer.darts[(k + m - 1) % m];
        const int d = w.g.vertices[pv][pi].dir;
        ext.push_back({outer.darts[k].first, d, side_of(d)});
    }
    if (ext.size() < 4) return false;
    // Start at a side change so that corners fall between sides.
    std::size_t start = 0;
    for (std::size_t k = 0; k < ext.size(); ++k)
        if (ext[k].side != ext[(k + ext.size() - 1) % ext.size()].side) {
            start = k;
            break;
        }
    struct FrameVertex {
        int vertex, side;  // side: the side it lies on; a corner: the side it ends
        int r = -1, dir = -1;
    };
    std::vector<FrameVertex> cycle;
    for (std::size_t n = 0; n < ext.size(); ++n) {
        const Extension& x = ext[(start + n) % ext.size()];
        if (!cycle.empty()) {
            const int prev = cycle.back().side;
            if (x.side != prev) {
                if (x.side != (prev + 1) % 4) return false;
                cycle.push_back({w.add_vertex(), prev + 4});  // corner after side prev
            }
        }
        cycle.push_back({w.add_vertex(), x.side, x.r, x.dir});
    }
    {
        const int prev = cycle.back().side, first = cycle.front().side;
        if (first != prev) {
            if (first != (prev + 1) % 4) return false;
            cycle.push_back({w.add_vertex(), prev + 4});
        }
    }
    const std::size_t n = cycle.size();
    for (std::size_t k = 0; k < n; ++k) {
        const FrameVertex& x = cycle[k];
        const FrameVertex& next = cycle[(k + 1) % n];
        // Along side s (counter-clockwise) the heading is s + 1; from the corner after side s
        // it is s + 2.
        const int along = x.side < 4 ? heading[(x.side + 1) % 4] : heading[(x.side - 4 + 2) % 4];
        w.add_dart(x.vertex, {along, 0, next.vertex}, {-1, -1});
        w.add_dart(next.vertex, {w.dirs.opposite[along], 0, x.vertex}, {-1, -1});
        if (x.r >= 0) {
            if (w.g.find(x.r, x.dir) >= 0) return false;  // one vertex extended twice alike
            w.add_dart(x.r, {x.dir, 0, x.vertex}, {-1, -1});
            w.add_dart(x.vertex, {w.dirs.opposite[x.dir], 0, x.r}, {-1, -1});
        }
    }
    return true;
}

}  // namespace

std::optional<Refinement> rectangularize(const AngleGraph& g, const Directions& dirs) {
    if (!orthogonal(dirs)) return std::nullopt;
    Work w{g, {}, dirs};
    w.origin.resize(g.vertices.size());
    for (std::size_t v = 0; v < g.vertices.size(); ++v)
        for (std::size_t i = 0; i < g.vertices[v].size(); ++i)
            w.origin[v].emplace_back(static_cast<int>(v), static_cast<int>(i));
    const std::size_t limit = 4 * (g.vertices.size() + 8);  // each cut removes a reflex corner
    std::size_t cuts = 0;
    while (refine_once(w, true))
        if (++cuts > limit) return std::nullopt;
    if (!frame(w)) return std::nullopt;
    while (refine_once(w, false))
        if (++cuts > 2 * limit) return std::nullopt;
    // Every face a rectangle: inner faces four convex corners and no reflex one.
    const Analysis a = analyze(w.g, dirs);
    if (!a.planar || !a.complete) return std::nullopt;
    for (const Walk& walk : a.walks) {
        if (walk.turning > 0) continue;
        int convex = 0;
        for (std::size_t k = 0; k < walk.darts.size(); ++k) {
            const int t = w.turn(walk, k);
            if (t == 90) return std::nullopt;
            convex += t == -90;
        }
        if (convex != 4) return std::nullopt;
    }
    return Refinement{std::move(w.g), std::move(w.origin)};
}

}  // namespace sylva::layout
