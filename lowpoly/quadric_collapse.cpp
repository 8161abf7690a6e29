#include "lowpoly/quadric_collapse.h"

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cfloat>
#include <cmath>
#include <glm/geometric.hpp>
#include <numeric>

#include "core/disjoint_sets.h"
#include "lowpoly/triangle_crossing.h"

namespace sylva {

void CollapseMesh::Quadric::add_plane(double na, double nb, double nc, double nd, double weight) {
    a += weight * (na * na);
    b += weight * (na * nb);
    c += weight * (na * nc);
    d += weight * (na * nd);
    e += weight * (nb * nb);
    f += weight * (nb * nc);
    g += weight * (nb * nd);
    h += weight * (nc * nc);
    i += weight * (nc * nd);
    j += weight * (nd * nd);
}

CollapseMesh::Quadric& CollapseMesh::Quadric::operator+=(const Quadric& q) {
    a += q.a, b += q.b, c += q.c, d += q.d, e += q.e;
    f += q.f, g += q.g, h += q.h, i += q.i, j += q.j;
    return *this;
}

// As OpenMesh's QuadricT evaluates it: the decimater's priorities stay what they were.
double CollapseMesh::Quadric::operator()(const glm::dvec3& p) const {
    const double x = p.x, y = p.y, z = p.z;
    return a * x * x + 2.0 * b * x * y + 2.0 * c * x * z + 2.0 * d * x + e * y * y +
           2.0 * f * y * z + 2.0 * g * y + h * z * z + 2.0 * i * z + j;
}

namespace {

// The smallest i below n for which ok(i) is false (n when there is none), with ok called
// once for every i, on several cores.
template <typename Ok>
std::size_t first_failing(std::size_t n, const Ok& ok) {
    return tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, n, 4096), n,
        [&](const tbb::blocked_range<std::size_t>& r, std::size_t first) {
            for (std::size_t i = r.begin(); i < r.end(); ++i)
                if (!ok(i)) first = std::min(first, i);
            return first;
        },
        [](std::size_t a, std::size_t b) { return std::min(a, b); });
}

}  // namespace

bool CollapseMesh::build(std::span<const Mesh* const> parts, std::size_t* bad_part) {
    std::size_t nv = 0, nf = 0;
    for (const Mesh* m : parts) {
        nv += m->positions.size();
        nf += m->triangles.size();
    }
    part_count_ = parts.size();
    position_.clear();
    position_.reserve(nv);
    part_.clear();
    part_.reserve(nv);
    corner_.clear();
    corner_.reserve(3 * nf);
    std::vector<std::uint32_t> face_part;
    face_part.reserve(nf);
    auto fail = [&](std::size_t k) {
        if (bad_part) *bad_part = k;
        return false;
    };
    for (std::size_t k = 0; k < parts.size(); ++k) {
        const Mesh& m = *parts[k];
        const auto base = static_cast<std::uint32_t>(position_.size());
        for (const glm::vec3& p : m.positions) {
            position_.emplace_back(p);
            part_.push_back(static_cast<std::uint32_t>(k));
        }
        for (const auto& t : m.triangles) {
            if (t[0] >= m.positions.size() || t[1] >= m.positions.size() ||
                t[2] >= m.positions.size() || t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
                return fail(k);
            for (std::uint32_t v : t) corner_.push_back(base + v);
            face_part.push_back(static_cast<std::uint32_t>(k));
        }
    }
    const std::size_t halfedges = corner_.size();
    // Halfedges leaving each vertex (CSR), with where each goes and where the halfedge
    // before it in its triangle (one entering the vertex) comes from.
    std::vector<std::uint32_t> first(nv + 1, 0), leaving(halfedges), leaving_to(halfedges),
        entering_from(halfedges);
    for (std::uint32_t v : corner_) ++first[v + 1];
    for (std::size_t v = 0; v < nv; ++v) first[v + 1] += first[v];
    {
        std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
        for (std::uint32_t h = 0; h < halfedges; ++h) {
            const std::uint32_t i = fill[corner_[h]]++;
            leaving[i] = h;
            leaving_to[i] = to(h);
            entering_from[i] = corner_[prev(h)];
        }
    }
    // The opposites and the fans are found on every core; a failure reports the part of the
    // first failing halfedge or vertex, as one pass in order would. The opposite of a -> b is
    // the one halfedge b -> a: entering a, so among a's own lists (read in order, where b's
    // would be anywhere in memory, and a search there would cost most of the pass). None is
    // a boundary or misoriented, two or more non-manifold or misoriented.
    opposite_.assign(halfedges, kNone);
    const std::size_t bad_halfedge = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, nv, 1024), std::size_t{halfedges},
        [&](const tbb::blocked_range<std::size_t>& r, std::size_t first_bad) {
            for (std::size_t a = r.begin(); a < r.end(); ++a)
                for (std::uint32_t i = first[a]; i < first[a + 1]; ++i) {
                    std::uint32_t found = kNone, matches = 0;
                    for (std::uint32_t j = first[a]; j < first[a + 1]; ++j) {
                        const bool match = entering_from[j] == leaving_to[i];
                        matches += match;
                        found = match ? prev(leaving[j]) : found;
                    }
                    if (matches == 1)
                        opposite_[leaving[i]] = found;
                    else
                        first_bad = std::min<std::size_t>(first_bad, leaving[i]);
                }
            return first_bad;
        },
        [](std::size_t a, std::size_t b) { return std::min(a, b); });
    if (bad_halfedge < halfedges) return fail(face_part[bad_halfedge / 3]);
    const std::size_t unpaired =
        first_failing(halfedges, [&](std::size_t h) { return opposite_[opposite_[h]] == h; });
    if (unpaired < halfedges) return fail(face_part[unpaired / 3]);
    // Each vertex's faces form one fan: turning around it visits all its halfedges.
    outgoing_.assign(nv, kNone);
    const std::size_t bad_vertex = first_failing(nv, [&](std::size_t v) {
        if (first[v] == first[v + 1]) return true;
        const std::uint32_t start = leaving[first[v]];
        std::uint32_t h = start, count = 0;
        do {
            h = turn(h);
            if (++count > first[v + 1] - first[v]) break;
        } while (h != start);
        outgoing_[v] = start;
        return count == first[v + 1] - first[v];
    });
    if (bad_vertex < nv) return fail(part_[bad_vertex]);
    face_alive_.assign(nf, 1);
    live_faces_ = nf;

    // Pieces: vertices joined by triangles, numbered in vertex order.
    DisjointSets sets(nv);
    for (std::size_t f = 0; f < nf; ++f) {
        sets.unite(corner_[3 * f + 1], corner_[3 * f]);
        sets.unite(corner_[3 * f + 2], corner_[3 * f]);
    }
    std::vector<std::uint32_t> slot(nv, kNone);
    piece_.assign(nv, 0);
    std::uint32_t pieces = 0;
    for (std::uint32_t v = 0; v < nv; ++v) {
        std::uint32_t& s = slot[sets.find(v)];
        if (s == kNone) s = pieces++;
        piece_[v] = s;
    }
    piece_count_ = pieces;
    return true;
}

std::size_t CollapseMesh::triangle_floor() const {
    // Per piece with triangles: V - E + F = 2 - 2 genus, E = 3F / 2.
    std::vector<long> vertices(piece_count_, 0), faces(piece_count_, 0);
    for (std::uint32_t v = 0; v < position_.size(); ++v)
        if (outgoing_[v] != kNone) ++vertices[piece_[v]];
    for (std::size_t f = 0; f < face_alive_.size(); ++f)
        if (face_alive_[f]) ++faces[piece_[corner_[3 * f]]];
    std::size_t floor = 0;
    for (std::size_t p = 0; p < piece_count_; ++p) {
        if (faces[p] == 0) continue;
        const long genus = std::max(0L, (2 - (vertices[p] - faces[p] / 2)) / 2);
        floor += 4 + 12 * static_cast<std::size_t>(genus);
    }
    return floor;
}

void CollapseMesh::update_normal(std::uint32_t face) {
    const glm::dvec3& a = position_[corner_[3 * face]];
    const glm::dvec3 n =
        glm::cross(position_[corner_[3 * face + 1]] - a, position_[corner_[3 * face + 2]] - a);
    const double length = glm::length(n);
    normal_[face] = length != 0.0 ? n / length : glm::dvec3(0.0);
}

void CollapseMesh::start(const CollapseSettings& settings, CancelFlag cancel) {
    min_cos_ = std::cos(settings.max_normal_turn_degrees * M_PI / 180.0);
    min_cos2_ = min_cos_ * min_cos_;
    min_twice_area2_ = settings.min_twice_area * settings.min_twice_area;
    foot_height_ = settings.foot_height;
    min_foot_vertices_ = settings.min_foot_vertices;
    lazy_ = settings.lazy_legality;
    passes_ = settings.passes;
    keep_apart_ = settings.keep_apart;
    guarding_ = false;
    cancel_ = cancel;
    const std::size_t nv = position_.size(), nf = face_alive_.size();

    normal_.assign(nf, glm::dvec3(0.0));
    quadric_.assign(nv, Quadric());
    piece_volume_.assign(piece_count_, 0.0);
    for (std::uint32_t f = 0; f < nf; ++f) {
        if (!face_alive_[f]) continue;
        update_normal(f);
        const glm::dvec3 &p0 = position_[corner_[3 * f]], &p1 = position_[corner_[3 * f + 1]],
                         &p2 = position_[corner_[3 * f + 2]];
        // ModQuadricT's quadric: the face's plane weighted by its area.
        glm::dvec3 n = glm::cross(p1 - p0, p2 - p0);
        double area = glm::length(n);
        if (area > FLT_MIN) {
            n /= area;
            area *= 0.5;
        }
        Quadric q;
        q.add_plane(n.x, n.y, n.z, -glm::dot(p0, n), area);
        for (int k = 0; k < 3; ++k) quadric_[corner_[3 * f + k]] += q;
        piece_volume_[piece_[corner_[3 * f]]] += glm::dot(p0, glm::cross(p1, p2)) / 6.0;
    }
    // A small closed piece can fold through itself over several collapses and come out
    // inside out; no collapse may take a piece below a sliver of its volume. Inner shells
    // (negative volume by nature) are left alone.
    piece_floor_.resize(piece_count_);
    for (std::size_t i = 0; i < piece_count_; ++i) piece_floor_[i] = 1e-3 * piece_volume_[i];
    foot_vertices_.assign(piece_count_, 0);
    for (std::uint32_t v = 0; v < nv; ++v)
        if (outgoing_[v] != kNone && is_foot(v)) ++foot_vertices_[piece_[v]];

    own_error_.assign(nv, 0.0);
    for (std::uint32_t v = 0; v < nv; ++v) own_error_[v] = quadric_[v](position_[v]);
    target_.assign(nv, kNone);
    verified_.assign(nv, 0);
    priority_.assign(nv, -1.0f);
    mark_.assign(nv, 0);
    stamp_ = 0;
    heap_position_.assign(nv, kNone);
    heap_.clear();
    heap_.reserve(nv);
    collapses_ = 0;
    heap_filled_ = false;  // collapse_to() may make passes first
}

void CollapseMesh::prepare_heap() {
    if (!heap_filled_) fill_heap();
}

void CollapseMesh::fill_heap() {
    heap_.clear();
    std::fill(heap_position_.begin(), heap_position_.end(), kNone);
    for (std::uint32_t v = 0; v < position_.size(); ++v) {
        if ((v & 4095) == 4095) throw_if_cancelled(cancel_);
        if (outgoing_[v] == kNone) continue;
        queue_vertex(v, /*place=*/false);
        if (target_[v] != kNone) heap_.push_back({priority_[v], v});
    }
    for (std::size_t i = heap_.size() / 2; i-- > 0;) heap_down(i);
    for (std::size_t i = 0; i < heap_.size(); ++i)
        heap_position_[heap_[i].vertex] = static_cast<std::uint32_t>(i);
    heap_filled_ = true;
    if (keep_apart_ && live_faces_ <= guard_from_) start_guard();
    throw_if_cancelled(cancel_);
}

CollapseMesh::FaceShape CollapseMesh::shape(std::uint32_t face, std::uint32_t v,
                                            std::uint32_t becomes, const glm::dvec3& p) const {
    FaceShape s;
    s.face = face;
    glm::dvec3 at[3];
    for (int k = 0; k < 3; ++k) {
        const std::uint32_t u = corner_[3 * face + k];
        s.id[k] = u == v ? becomes : u;
        at[k] = u == v ? p : position_[u];
    }
    s.t = crossing_triangle(at[0], at[1], at[2]);
    s.lo = glm::min(glm::min(at[0], at[1]), at[2]);
    s.hi = glm::max(glm::max(at[0], at[1]), at[2]);
    return s;
}

void CollapseMesh::start_guard() {
    // Cells about twice the mean edge: a face then lists in a few cells, and collapses make
    // faces larger than that only near the end, when few are left.
    double length = 0.0;
    std::size_t edges = 0;
    for (std::uint32_t f = 0; f < face_alive_.size(); ++f) {
        if (!face_alive_[f]) continue;
        for (int k = 0; k < 3; ++k)
            length += glm::distance(position_[corner_[3 * f + k]],
                                    position_[corner_[3 * f + (k + 1) % 3]]);
        edges += 3;
    }
    guarding_ = false;
    if (edges == 0 || !(length > 0.0)) return;
    grid_.reset(2.0 * length / static_cast<double>(edges), face_alive_.size());
    listed_.resize(face_alive_.size());
    if (in_fan_.size() != face_alive_.size()) {
        in_fan_.assign(face_alive_.size(), 0);
        fan_stamp_ = 0;
    }
    for (std::uint32_t f = 0; f < face_alive_.size(); ++f)
        if (face_alive_[f]) grid_place(f);
    grid_faces_ = live_faces_;
    guarding_ = true;
}

bool CollapseMesh::listed_as_now(std::uint32_t face) const {
    const FaceShape& s = listed_[face];
    return s.id[0] == corner_[3 * face] && s.id[1] == corner_[3 * face + 1] &&
           s.id[2] == corner_[3 * face + 2];
}

void CollapseMesh::grid_place(std::uint32_t face) {
    listed_[face] = shape(face);
    grid_.place(face, listed_[face].lo, listed_[face].hi);
}

namespace {

bool boxes_meet(const glm::dvec3& alo, const glm::dvec3& ahi, const glm::dvec3& blo,
                const glm::dvec3& bhi) {
    return alo.x <= bhi.x && blo.x <= ahi.x && alo.y <= bhi.y && blo.y <= ahi.y && alo.z <= bhi.z &&
           blo.z <= ahi.z;
}

}  // namespace

inline bool CollapseMesh::shapes_cross(const FaceShape& a, const FaceShape& b) {
    if (!boxes_meet(a.lo, a.hi, b.lo, b.hi)) return false;
    int shared = 0, ia = 0, ib = 0;  // the corners they share, and where one of them stands
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (a.id[i] == b.id[j]) {
                ++shared;
                ia = i;
                ib = j;
            }
    return triangles_cross(a.t, b.t, shared, ia, ib);
}

std::size_t CollapseMesh::crossing_pairs() const {
    std::vector<FaceShape> shapes;
    double length = 0.0;
    for (std::uint32_t f = 0; f < face_alive_.size(); ++f)
        if (face_alive_[f]) {
            shapes.push_back(shape(f));
            length += shapes.back().t.size;
        }
    if (shapes.empty() || !(length > 0.0)) return 0;
    FaceGrid grid;
    grid.reset(2.0 * length / static_cast<double>(shapes.size()), shapes.size());
    for (std::uint32_t i = 0; i < shapes.size(); ++i) grid.place(i, shapes[i].lo, shapes[i].hi);
    std::size_t pairs = 0;
    for (std::uint32_t i = 0; i < shapes.size(); ++i) {
        const FaceShape& a = shapes[i];
        grid.near(a.lo, a.hi, [&](std::uint32_t j) {
            const FaceShape& b = shapes[j];
            if (j > i && piece_[a.id[0]] == piece_[b.id[0]] && shapes_cross(a, b)) ++pairs;
        });
    }
    return pairs;
}

bool CollapseMesh::apart(std::span<const FaceShape> faces, std::uint32_t skip_a,
                         std::uint32_t skip_b) const {
    glm::dvec3 lo = faces.front().lo, hi = faces.front().hi;
    for (std::size_t i = 0; i < faces.size(); ++i) {
        lo = glm::min(lo, faces[i].lo);
        hi = glm::max(hi, faces[i].hi);
        for (std::size_t j = i + 1; j < faces.size(); ++j)
            if (shapes_cross(faces[i], faces[j])) return false;
    }
    if (++fan_stamp_ == 0) {
        std::fill(in_fan_.begin(), in_fan_.end(), 0);
        fan_stamp_ = 1;
    }
    for (const FaceShape& f : faces) in_fan_[f.face] = fan_stamp_;
    // Only faces of the same piece: pieces may overlap (a crown's hulls, a trunk's parts).
    const std::uint32_t piece = piece_[faces.front().id[0]];
    bool crossed = false;
    grid_.near(lo, hi, [&](std::uint32_t g) {
        if (crossed || !face_alive_[g] || g == skip_a || g == skip_b || in_fan_[g] == fan_stamp_)
            return;
        const FaceShape& other = listed_[g];
        if (piece_[other.id[0]] != piece) return;
        for (const FaceShape& f : faces)
            if (shapes_cross(f, other)) {
                crossed = true;
                return;
            }
    });
    return !crossed;
}

bool CollapseMesh::keeps_apart(std::uint32_t v, std::uint32_t becomes, const glm::dvec3& p,
                               std::uint32_t h) const {
    const std::uint32_t skip_a = h == kNone ? kNone : h / 3;
    const std::uint32_t skip_b = h == kNone ? kNone : opposite_[h] / 3;
    fan_.clear();
    for (std::uint32_t g = outgoing_[v];;) {
        const std::uint32_t f = g / 3;
        if (f != skip_a && f != skip_b) fan_.push_back(shape(f, v, becomes, p));
        g = turn(g);
        if (g == outgoing_[v]) break;
    }
    return fan_.empty() || apart(fan_, skip_a, skip_b);
}

bool CollapseMesh::topology_allows(std::uint32_t h) const {
    const std::uint32_t v0 = corner_[h], v1 = to(h), o = opposite_[h];
    const std::uint32_t vl = corner_[prev(h)], vr = corner_[prev(o)];
    if (vl == vr) return false;
    // Link condition: v0 and v1 share no neighbour but vl and vr.
    if (++stamp_ == 0) {
        std::fill(mark_.begin(), mark_.end(), 0);
        stamp_ = 1;
    }
    for (std::uint32_t g = outgoing_[v1];;) {
        mark_[to(g)] = stamp_;
        g = turn(g);
        if (g == outgoing_[v1]) break;
    }
    int valence0 = 0;
    for (std::uint32_t g = outgoing_[v0];;) {
        const std::uint32_t w = to(g);
        ++valence0;
        if (w != vl && w != vr && mark_[w] == stamp_) return false;
        g = turn(g);
        if (g == outgoing_[v0]) break;
    }
    if (valence0 < 3) return false;
    // A tetrahedron would collapse to two triangles back to back: vl and vr joined, both
    // of valence 3.
    auto valence_is_3 = [&](std::uint32_t v) {
        const std::uint32_t g = outgoing_[v];
        return turn(turn(turn(g))) == g && turn(g) != g && turn(turn(g)) != g;
    };
    if (valence_is_3(vl) && valence_is_3(vr)) {
        for (std::uint32_t g = outgoing_[vl];;) {
            if (to(g) == vr) return false;
            g = turn(g);
            if (g == outgoing_[vl]) break;
        }
    }
    return true;
}

bool CollapseMesh::fan_allows(std::uint32_t v, const glm::dvec3& p, std::uint32_t skip_a,
                              std::uint32_t skip_b, double* volume_change) const {
    const glm::dvec3 o = position_[v], d = p - o;
    double six = 0.0;
    for (std::uint32_t h = outgoing_[v];;) {
        const std::uint32_t f = h / 3;
        if (f != skip_a && f != skip_b) {
            const glm::dvec3& a = position_[corner_[next(h)]];
            const glm::dvec3& b = position_[corner_[prev(h)]];
            const glm::dvec3 n = glm::cross(a - p, b - p);
            const double n2 = glm::dot(n, n);
            if (n2 <= min_twice_area2_) return false;
            // cos(turn) = n.old / |n| with a unit old normal.
            const double dn = glm::dot(n, normal_[f]);
            if (min_cos_ >= 0.0 ? !(dn >= 0.0 && dn * dn >= min_cos2_ * n2)
                                : !(dn >= 0.0 || dn * dn <= min_cos2_ * n2))
                return false;
            six += glm::dot(d, glm::cross(a - o, b - o));
        }
        h = turn(h);
        if (h == outgoing_[v]) break;
    }
    *volume_change = six / 6.0;
    return true;
}

bool CollapseMesh::keeps_volume(std::uint32_t v, double change) const {
    const std::uint32_t p = piece_[v];
    return !(piece_floor_[p] > 0.0) || piece_volume_[p] + change > piece_floor_[p];
}

bool CollapseMesh::is_legal(std::uint32_t h, double* volume_change) const {
    const std::uint32_t v0 = corner_[h], v1 = to(h);
    // A foot vertex may only merge into another foot vertex, and only while its piece has
    // more than the fewest.
    if (is_foot(v0) && !(is_foot(v1) && foot_vertices_[piece_[v0]] > min_foot_vertices_))
        return false;
    if (!topology_allows(h)) return false;
    if (!fan_allows(v0, position_[v1], h / 3, opposite_[h] / 3, volume_change) ||
        !keeps_volume(v0, *volume_change))
        return false;
    crossing_ = guarding_ && !keeps_apart(v0, v1, position_[v1], h);
    return !crossing_;
}

float CollapseMesh::error(std::uint32_t h) const {
    // (Q0 + Q1)(p1) = Q0(p1) + Q1(p1), the second term kept per vertex.
    const std::uint32_t v1 = to(h);
    return static_cast<float>(quadric_[corner_[h]](position_[v1]) + own_error_[v1]);
}

void CollapseMesh::queue_vertex(std::uint32_t v, bool place) {
    if (!lazy_) {  // the cheapest legal collapse, tested now
        float best = 0.0f;
        double change = 0.0;
        target_[v] = best_legal(v, &best, &change);
        verified_[v] = 1;
        priority_[v] = best;
        if (!place) return;
        if (target_[v] != kNone)
            heap_place(v);
        else
            heap_remove(v);
        return;
    }
    float best = std::numeric_limits<float>::max();
    std::uint32_t target = kNone;
    const Quadric& q = quadric_[v];
    for (std::uint32_t h = outgoing_[v];;) {
        const std::uint32_t v1 = to(h);
        const auto e = static_cast<float>(q(position_[v1]) + own_error_[v1]);
        if (!(e < 0.0f) && e < best) {
            best = e;
            target = h;
        }
        h = turn(h);
        if (h == outgoing_[v]) break;
    }
    target_[v] = target;
    verified_[v] = 0;
    priority_[v] = best;
    if (!place) return;
    if (target != kNone)
        heap_place(v);
    else
        heap_remove(v);
}

std::uint32_t CollapseMesh::best_legal(std::uint32_t v, float* best, double* volume_change) const {
    // Candidates by error (ties in turning order), tested until one is legal.
    constexpr int kMaxValence = 64;
    std::array<std::pair<float, std::uint32_t>, kMaxValence> candidates;
    int n = 0;
    for (std::uint32_t h = outgoing_[v];;) {
        const float e = error(h);
        if (!(e < 0.0f) && e < std::numeric_limits<float>::max() && n < kMaxValence)
            candidates[n++] = {e, h};
        h = turn(h);
        if (h == outgoing_[v]) break;
    }
    for (int i = 1; i < n; ++i)  // insertion sort: stable, and n is a valence
        for (int j = i; j > 0 && candidates[j].first < candidates[j - 1].first; --j)
            std::swap(candidates[j], candidates[j - 1]);
    for (int i = 0; i < n; ++i) {
        if (is_legal(candidates[i].second, volume_change)) {
            *best = candidates[i].first;
            return candidates[i].second;
        }
        // v's faces would cross another face of its piece: its other collapses move the
        // same faces over the same ground, and testing each costs more than waiting until a
        // neighbour changes.
        if (crossing_) return kNone;
    }
    return kNone;
}

void CollapseMesh::collapse(std::uint32_t h, double volume_change) {
    if (keep_apart_ && !guarding_ && heap_filled_ && live_faces_ <= guard_from_) start_guard();
    const std::uint32_t v0 = corner_[h], v1 = to(h), o = opposite_[h];
    const std::uint32_t piece = piece_[v0];
    piece_volume_[piece] += volume_change;
    if (is_foot(v0)) --foot_vertices_[piece];  // onto another foot vertex
    support_.clear();
    for (std::uint32_t g = outgoing_[v0];;) {
        support_.push_back(to(g));
        g = turn(g);
        if (g == outgoing_[v0]) break;
    }
    const std::uint32_t n1 = next(h), p1 = prev(h), n2 = next(o), p2 = prev(o);
    const std::uint32_t vl = corner_[p1], vr = corner_[p2];
    // Outside the two faces that go: a = vl -> v1, b = v0 -> vl, c = vr -> v0, d = v1 -> vr.
    const std::uint32_t a = opposite_[n1], b = opposite_[p1], c = opposite_[n2], d = opposite_[p2];
    for (std::uint32_t g = outgoing_[v0];;) {
        corner_[g] = v1;
        g = turn(g);
        if (g == outgoing_[v0]) break;
    }
    opposite_[a] = b;
    opposite_[b] = a;
    opposite_[c] = d;
    opposite_[d] = c;
    outgoing_[v1] = b;
    outgoing_[vl] = a;
    outgoing_[vr] = c;
    outgoing_[v0] = kNone;
    face_alive_[h / 3] = 0;
    face_alive_[o / 3] = 0;
    live_faces_ -= 2;
    if (guarding_) {
        grid_.remove(h / 3);
        grid_.remove(o / 3);
        // Faces grow as they go: cells for the faces there are now, once half have gone.
        if (2 * live_faces_ < grid_faces_) start_guard();
    }
    for (std::uint32_t g = outgoing_[v1];;) {
        update_normal(g / 3);
        // v0's old faces moved; v1's own kept their place.
        if (guarding_ && !listed_as_now(g / 3)) grid_place(g / 3);
        g = turn(g);
        if (g == outgoing_[v1]) break;
    }
    quadric_[v1] += quadric_[v0];
    own_error_[v1] = quadric_[v1](position_[v1]);
}

void CollapseMesh::requeue_after(std::uint32_t v0) {
    heap_remove(v0);
    for (std::uint32_t s : support_) queue_vertex(s);
}

float CollapseMesh::front_key() const {
    return heap_.empty() ? std::numeric_limits<float>::infinity() : heap_.front().key;
}

std::size_t CollapseMesh::step(float others_front) {
    // Lazy legality: a vertex waits in the heap with its cheapest collapse by error alone;
    // the link condition and the guards run when it comes to the front. If that collapse is
    // illegal, the cheapest legal one goes back into the heap at its own error (verified)
    // when something else is cheaper now, so collapses still happen in the order of their
    // errors, and a collapse's neighbours cost a quadric evaluation each instead of the
    // legality tests of all their edges.
    const std::uint32_t v = heap_.front().vertex;
    const float popped = priority_[v];
    std::uint32_t h = target_[v];
    heap_remove(v);
    double change = 0.0;
    if (!verified_[v] || !face_alive_[h / 3] || corner_[h] != v || !is_legal(h, &change)) {
        float best = 0.0f;
        h = best_legal(v, &best, &change);
        if (h == kNone) return 0;  // out of the heap until a neighbour changes
        if (best > popped && best > std::min(front_key(), others_front)) {
            target_[v] = h;
            priority_[v] = best;
            verified_[v] = 1;
            heap_place(v);
            return 0;
        }
    }
    collapse(h, change);
    requeue_after(v);
    ++collapses_;
    return 2;
}

void CollapseMesh::waiting_keys(std::vector<float>& keys) const {
    for (const HeapEntry& e : heap_) keys.push_back(e.key);
}

std::size_t CollapseMesh::collapse_up_to(float max_key, std::size_t min_triangles) {
    std::size_t removed = 0;
    while (!heap_.empty() && front_key() <= max_key && live_faces_ > min_triangles)
        removed += step(max_key);
    return removed;
}

namespace {

// A pass's candidate as one number, the bits of its error above its vertex: the numbers
// order as (error, vertex) pairs do (an error is never negative, and the bits of
// non-negative floats order as the floats; -0 is made +0), and a pass picks and sorts one
// number each faster than pairs.
std::uint64_t candidate(float error, std::uint32_t v) {
    return std::uint64_t{std::bit_cast<std::uint32_t>(error + 0.0f)} << 32 | v;
}
float error_of(std::uint64_t candidate) {
    return std::bit_cast<float>(static_cast<std::uint32_t>(candidate >> 32));
}

}  // namespace

bool CollapseMesh::collapse_in_passes(std::size_t until, std::size_t interval,
                                      const std::function<bool(std::size_t)>& step_done) {
    std::vector<std::uint64_t> order;                        // candidate(error, vertex)
    std::vector<std::uint32_t> locked(position_.size(), 0);  // the pass that locked a vertex
    // Passes until the last eighth: a pass files every vertex, the heap only a collapse's
    // neighbours.
    for (std::uint32_t pass = 1; live_faces_ > until && live_faces_ - until > live_faces_ / 8;
         ++pass) {
        throw_if_cancelled(cancel_);
        order.clear();
        for (std::uint32_t v = 0; v < position_.size(); ++v) {
            if (outgoing_[v] == kNone) continue;
            queue_vertex(v, /*place=*/false);
            if (target_[v] != kNone) order.push_back(candidate(priority_[v], v));
        }
        // Half the collapses still needed (two triangles each), and the error of the last of
        // them: the pass makes those within kPassErrorSlack of it, cheapest first (ties by
        // vertex: one order on every machine). Half and 1.2 kept the fidelity of the heap's
        // order at 200 and 800 triangles (sylva-bench-lowpoly --compare-heap); all and 1.5,
        // as meshoptimizer takes them, lost up to 20% of it on the bush at 200.
        constexpr float kPassErrorSlack = 1.2f;
        const std::size_t wanted = std::min((live_faces_ - until + 3) / 4, order.size());
        if (wanted == 0) break;
        std::nth_element(order.begin(), order.begin() + (wanted - 1), order.end());
        const float limit = kPassErrorSlack * error_of(order[wanted - 1]);
        const auto within = std::partition(
            order.begin(), order.end(), [limit](std::uint64_t c) { return error_of(c) <= limit; });
        std::sort(order.begin(), within);
        std::size_t made = 0;
        for (auto c = order.begin(); c != within && live_faces_ > until; ++c) {
            const auto v = static_cast<std::uint32_t>(*c);
            const std::uint32_t h = target_[v];
            // Gone, or its errors changed in this pass: the next pass looks again.
            if (locked[v] == pass || outgoing_[v] == kNone || !face_alive_[h / 3] ||
                corner_[h] != v || locked[to(h)] == pass)
                continue;
            double change = 0.0;
            if (!is_legal(h, &change)) continue;
            locked[to(h)] = pass;
            collapse(h, change);
            ++made;
            ++collapses_;
            if (step_done && interval > 0 && collapses_ % interval == 0 && !step_done(collapses_))
                return false;
        }
        if (made == 0) break;
    }
    return true;
}

void CollapseMesh::collapse_to(std::size_t max_triangles, std::size_t interval,
                               const std::function<bool(std::size_t)>& step_done) {
    // The passes leave the heap the last half of the way, and never less than a few
    // thousand triangles: where each collapse shows, it comes in the order of its error.
    constexpr std::size_t kHeapAtLeast = 4096;
    const std::size_t pass_floor = std::max(2 * max_triangles, kHeapAtLeast);
    // The guard from twice the count asked for: before, faces are too small to reach
    // through the surface (every template at 200-3000: as few crossings as a guard from
    // the heap's start, at a quarter less time).
    guard_from_ = 2 * max_triangles;
    if (passes_ && !heap_filled_ && live_faces_ > pass_floor &&
        !collapse_in_passes(pass_floor, interval, step_done))
        return;
    prepare_heap();
    for (;;) {
        while (!heap_.empty() && live_faces_ > max_triangles) {
            if (step(std::numeric_limits<float>::infinity()) == 0) continue;
            if (step_done && interval > 0 && collapses_ % interval == 0 && !step_done(collapses_))
                return;
        }
        if (live_faces_ <= max_triangles || !relax_guard()) return;
    }
}

bool CollapseMesh::relax_guard() {
    if (!guarding_) return false;
    guarding_ = false;
    keep_apart_ = false;
    fill_heap();
    return !heap_.empty();
}

void collapse_together(std::span<CollapseMesh> meshes, std::size_t max_triangles, CancelFlag cancel,
                       std::size_t part_floor, std::span<const std::size_t> part_of) {
    auto part = [&](std::size_t k) { return part_of.empty() ? k : part_of[k]; };
    tbb::parallel_for(std::size_t{0}, meshes.size(),
                      [&](std::size_t k) { meshes[k].prepare_heap(); });
    std::vector<std::size_t> in_part(meshes.size(), 0);
    std::size_t triangles = 0;
    auto count = [&] {
        std::fill(in_part.begin(), in_part.end(), 0);
        triangles = 0;
        for (std::size_t k = 0; k < meshes.size(); ++k) {
            in_part[part(k)] += meshes[k].triangles();
            triangles += meshes[k].triangles();
        }
    };
    count();
    // The bulk in parallel: the collapses of all meshes up to an error bound are the ones
    // the shared order makes first, whichever mesh makes them when (no collapse changes
    // another mesh). Each round takes the bound below which the heaps hold 70% of the
    // collapses still needed (errors rise as neighbours collapse, so fewer are made), and no
    // mesh makes more than it holds below the bound, nor takes its part below the floor: the
    // budget is never overshot. Rounds go on down to the last few dozen collapses, which go
    // one at a time in the shared order: those cost several microseconds each near the
    // budget, where many fronts are illegal and filed again. (Every template exports the same
    // bytes as with the shared order all the way, at budgets 100 to 3000 and in LOD chains.)
    constexpr std::size_t kSharedAtMost = 64;  // collapses
    constexpr int kMaxRounds = 16;
    std::vector<float> keys;
    for (int round = 0; round < kMaxRounds && !is_cancelled(cancel); ++round) {
        const std::size_t needed = triangles > max_triangles ? (triangles - max_triangles) / 2 : 0;
        if (needed <= kSharedAtMost) break;
        keys.clear();
        for (CollapseMesh& m : meshes) m.waiting_keys(keys);
        const std::size_t take = std::min(keys.size(), needed * 7 / 10);
        if (take == 0) break;
        std::nth_element(keys.begin(), keys.begin() + (take - 1), keys.end());
        const float bound = keys[take - 1];
        std::vector<std::size_t> removed(meshes.size(), 0);
        tbb::parallel_for(std::size_t{0}, meshes.size(), [&](std::size_t k) {
            CollapseMesh& m = meshes[k];
            // Below the bound, and what its part may still give up, in proportion to its size.
            std::vector<float> mine;
            m.waiting_keys(mine);
            const auto below = static_cast<std::size_t>(
                std::count_if(mine.begin(), mine.end(), [&](float key) { return key <= bound; }));
            const std::size_t n = m.triangles(), of_part = in_part[part(k)];
            const std::size_t part_may = of_part > part_floor + 1 ? of_part - part_floor - 1 : 0;
            const std::size_t may =
                std::min(2 * below, part_may * n / std::max<std::size_t>(of_part, 1));
            removed[k] = m.collapse_up_to(bound, n - std::min(n, may));
        });
        count();
        if (std::accumulate(removed.begin(), removed.end(), std::size_t{0}) == 0) break;
    }
    for (std::size_t steps = 1; triangles > max_triangles; ++steps) {
        // The cheapest front of all (ties to the first mesh), and the next cheapest.
        std::size_t cheapest = meshes.size();
        float key = std::numeric_limits<float>::infinity();
        float second = key;
        for (std::size_t k = 0; k < meshes.size(); ++k) {
            if (in_part[part(k)] < part_floor + 2) continue;  // at its floor
            const float front = meshes[k].front_key();
            if (front < key) {
                second = key;
                key = front;
                cheapest = k;
            } else if (front < second) {
                second = front;
            }
        }
        if (cheapest == meshes.size()) {  // no collapse left anywhere
            bool relaxed = false;
            for (CollapseMesh& m : meshes) relaxed = m.relax_guard() || relaxed;
            if (relaxed) continue;
            break;
        }
        const std::size_t removed = meshes[cheapest].step(second);
        in_part[part(cheapest)] -= removed;
        triangles -= removed;
        if ((steps & 255) == 0 && is_cancelled(cancel)) return;
    }
}

// Halfedge collapses keep every vertex on the input surface, so a coarse result is
// inscribed in it (a sphere comes out smaller). Moving each vertex to the minimum of its
// accumulated quadric (the planes of the input it stands for) lets the facets straddle the
// surface instead. A small pull towards the current position keeps flat and ridge
// neighbourhoods (singular quadrics) in place; a move that would fold a triangle is halved,
// then dropped.
void CollapseMesh::relocate() {
    for (std::uint32_t v = 0; v < position_.size(); ++v) {
        if (outgoing_[v] == kNone) continue;
        const Quadric& q = quadric_[v];
        const glm::dvec3 p = position_[v];
        const double mu = 1e-3 * (q.a + q.e + q.h) / 3.0 + 1e-30;
        // (A + mu I) x = mu p - b
        const double m[3][3] = {{q.a + mu, q.b, q.c}, {q.b, q.e + mu, q.f}, {q.c, q.f, q.h + mu}};
        const double r[3] = {mu * p.x - q.d, mu * p.y - q.g, mu * p.z - q.i};
        const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
        if (!(std::abs(det) > 0.0) || !std::isfinite(det)) continue;
        glm::dvec3 x;
        for (int k = 0; k < 3; ++k) {  // Cramer's rule
            double c[3][3];
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) c[i][j] = j == k ? r[i] : m[i][j];
            x[k] = (c[0][0] * (c[1][1] * c[2][2] - c[1][2] * c[2][1]) -
                    c[0][1] * (c[1][0] * c[2][2] - c[1][2] * c[2][0]) +
                    c[0][2] * (c[1][0] * c[2][1] - c[1][1] * c[2][0])) /
                   det;
        }
        if (is_foot(v)) x.y = p.y;  // the foot stays on the ground
        for (double step : {1.0, 0.5}) {
            const glm::dvec3 candidate = p + step * (x - p);
            if (!std::isfinite(candidate.x) || !std::isfinite(candidate.y) ||
                !std::isfinite(candidate.z))
                break;
            double change = 0.0;
            if (fan_allows(v, candidate, kNone, kNone, &change) && keeps_volume(v, change) &&
                (!guarding_ || keeps_apart(v, v, candidate, kNone))) {
                piece_volume_[piece_[v]] += change;
                position_[v] = candidate;
                for (std::uint32_t g = outgoing_[v];;) {
                    update_normal(g / 3);
                    if (guarding_) grid_place(g / 3);
                    g = turn(g);
                    if (g == outgoing_[v]) break;
                }
                break;
            }
        }
    }
}

namespace {

// The edge from `point` with faces of normals n1 and n2, n2's far corner at `far`: a concave
// fold sharper than a right angle (normals more than 90 degrees apart, far above n1's plane).
bool sharp_concave(const glm::dvec3& n1, const glm::dvec3& n2, const glm::dvec3& far,
                   const glm::dvec3& point) {
    return glm::dot(n1, n2) < 0.0 && glm::dot(n1, far - point) > 0.0;
}

// How far the edge from `a` to `b` folds inwards past a right angle: -cos of the angle
// between the unit normals n1 and n2 times the edge's length, where sharp_concave(); else 0.
double fold_excess(const glm::dvec3& n1, const glm::dvec3& n2, const glm::dvec3& far,
                   const glm::dvec3& a, const glm::dvec3& b) {
    if (!sharp_concave(n1, n2, far, a)) return 0.0;
    return -glm::dot(n1, n2) * glm::length(b - a);
}

double signed_volume6(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    return glm::dot(a, glm::cross(b, c));
}

}  // namespace

bool CollapseMesh::flip_unfolds(std::uint32_t h) const {
    const std::uint32_t o = opposite_[h];
    const std::uint32_t v0 = corner_[h], v1 = to(h), vl = corner_[prev(h)], vr = corner_[prev(o)];
    const std::uint32_t fa = h / 3, fb = o / 3;
    if (vl == vr) return false;
    // The quad's sides and the faces beyond them; none may be the quad's own.
    const std::uint32_t side[4] = {opposite_[prev(h)], opposite_[next(o)], opposite_[prev(o)],
                                   opposite_[next(h)]};
    for (std::uint32_t e : side)
        if (e / 3 == fa || e / 3 == fb) return false;
    // v0 and v1 each lose an edge; vl and vr must not be joined already.
    const auto valence = [&](std::uint32_t v) {
        int n = 0;
        for (std::uint32_t g = outgoing_[v];;) {
            ++n;
            g = turn(g);
            if (g == outgoing_[v]) break;
        }
        return n;
    };
    if (valence(v0) <= 3 || valence(v1) <= 3) return false;
    for (std::uint32_t g = outgoing_[vl];;) {
        if (to(g) == vr) return false;
        g = turn(g);
        if (g == outgoing_[vl]) break;
    }
    const glm::dvec3 &p0 = position_[v0], &p1 = position_[v1], &pl = position_[vl],
                     &pr = position_[vr];
    // The new faces (vl, v0, vr) and (vr, v1, vl): not slivers, and filling (a fold inwards
    // becomes one outwards), never carving.
    const glm::dvec3 na = glm::cross(p0 - pl, pr - pl), nb = glm::cross(p1 - pr, pl - pr);
    const double floor2 = std::max(min_twice_area2_, 1e-24);
    if (glm::dot(na, na) <= floor2 || glm::dot(nb, nb) <= floor2) return false;
    const double before = signed_volume6(p0, p1, pl) + signed_volume6(p1, p0, pr);
    const double after = signed_volume6(pl, p0, pr) + signed_volume6(pr, p1, pl);
    if (!(after > before)) return false;
    // Less sharp inward folding among the diagonal and the four sides than before: the
    // only edges whose faces change, so every flip lowers the mesh's total and sweeps end.
    const glm::dvec3 ua = na / std::sqrt(glm::dot(na, na)), ub = nb / std::sqrt(glm::dot(nb, nb));
    const glm::dvec3 &oa = normal_[fa], &ob = normal_[fb];
    const glm::dvec3 corner[4] = {pl, p0, pr, p1};  // each side's start, in side[] order
    double before_excess = fold_excess(oa, ob, pr, p0, p1);
    double after_excess = fold_excess(ua, ub, p1, pl, pr);
    for (int k = 0; k < 4; ++k) {
        const glm::dvec3& beyond = normal_[side[k] / 3];
        const glm::dvec3& far = position_[corner_[prev(side[k])]];
        const glm::dvec3& end = corner[(k + 1) % 4];
        before_excess += fold_excess(k == 0 || k == 3 ? oa : ob, beyond, far, corner[k], end);
        after_excess += fold_excess(k < 2 ? ua : ub, beyond, far, corner[k], end);
    }
    if (!(after_excess < before_excess)) return false;
    if (!guarding_) return true;
    // The two faces as flip() will leave them.
    FaceShape faces[2];
    const std::uint32_t ids[2][3] = {{vl, v0, vr}, {vr, v1, vl}};
    for (int i = 0; i < 2; ++i) {
        const glm::dvec3 &a = position_[ids[i][0]], &b = position_[ids[i][1]],
                         &c = position_[ids[i][2]];
        faces[i].face = i == 0 ? fa : fb;
        for (int k = 0; k < 3; ++k) faces[i].id[k] = ids[i][k];
        faces[i].t = crossing_triangle(a, b, c);
        faces[i].lo = glm::min(glm::min(a, b), c);
        faces[i].hi = glm::max(glm::max(a, b), c);
    }
    return apart(faces, fa, fb);
}

void CollapseMesh::flip(std::uint32_t h) {
    const std::uint32_t o = opposite_[h];
    const std::uint32_t v0 = corner_[h], v1 = to(h), vl = corner_[prev(h)], vr = corner_[prev(o)];
    const std::uint32_t side[4] = {opposite_[prev(h)], opposite_[next(o)], opposite_[prev(o)],
                                   opposite_[next(h)]};
    const std::uint32_t a = h / 3 * 3, b = o / 3 * 3;
    // a: vl -> v0 -> vr -> vl; b: vr -> v1 -> vl -> vr.
    corner_[a] = vl, corner_[a + 1] = v0, corner_[a + 2] = vr;
    corner_[b] = vr, corner_[b + 1] = v1, corner_[b + 2] = vl;
    const auto link = [&](std::uint32_t x, std::uint32_t y) {
        opposite_[x] = y;
        opposite_[y] = x;
    };
    link(a, side[0]);
    link(a + 1, side[1]);
    link(b, side[2]);
    link(b + 1, side[3]);
    link(a + 2, b + 2);
    outgoing_[v0] = a + 1;
    outgoing_[v1] = b + 1;
    outgoing_[vl] = a;
    outgoing_[vr] = b;
    update_normal(a / 3);
    update_normal(b / 3);
    if (guarding_) {
        grid_place(a / 3);
        grid_place(b / 3);
    }
}

std::size_t CollapseMesh::unfold() {
    constexpr int kMaxSweeps = 8;
    // Flips keep their faces alive: the live ones are listed once (a reduced mesh keeps a
    // few hundred of the tens of thousands it came from).
    std::vector<std::uint32_t> live;
    live.reserve(live_faces_);
    for (std::uint32_t f = 0; f < face_alive_.size(); ++f)
        if (face_alive_[f]) live.push_back(f);
    std::size_t flips = 0;
    for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
        std::size_t made = 0;
        for (const std::uint32_t f : live)
            for (std::uint32_t h = 3 * f; h < 3 * f + 3; ++h) {
                if (opposite_[h] < h) continue;  // each edge once
                const std::uint32_t o = opposite_[h];
                if (!sharp_concave(normal_[h / 3], normal_[o / 3], position_[corner_[prev(o)]],
                                   position_[corner_[h]]))
                    continue;
                if (!flip_unfolds(h)) continue;
                flip(h);
                ++made;
            }
        flips += made;
        if (made == 0) break;
    }
    // Halfedges moved: a later collapse_to() files the heap anew.
    if (flips > 0) heap_filled_ = false;
    return flips;
}

std::vector<Mesh> CollapseMesh::extract() const {
    std::vector<Mesh> out(part_count_);
    // Only vertices that a triangle uses; new indices in the old order (deterministic).
    std::vector<std::uint32_t> index(position_.size(), kNone);
    for (std::uint32_t v = 0; v < position_.size(); ++v) {
        if (outgoing_[v] == kNone) continue;
        Mesh& m = out[part_[v]];
        index[v] = static_cast<std::uint32_t>(m.positions.size());
        m.positions.emplace_back(static_cast<float>(position_[v].x),
                                 static_cast<float>(position_[v].y),
                                 static_cast<float>(position_[v].z));
    }
    for (std::size_t f = 0; f < face_alive_.size(); ++f) {
        if (!face_alive_[f]) continue;
        const std::uint32_t a = corner_[3 * f], b = corner_[3 * f + 1], c = corner_[3 * f + 2];
        out[part_[a]].triangles.push_back({index[a], index[b], index[c]});
    }
    return out;
}

// A binary min-heap of vertices by priority; each entry carries its key, so sifting reads
// the heap's own array only.
void CollapseMesh::heap_up(std::size_t i) {
    const HeapEntry entry = heap_[i];
    while (i > 0) {
        const std::size_t parent = (i - 1) / 2;
        if (!(entry.key < heap_[parent].key)) break;
        heap_[i] = heap_[parent];
        heap_position_[heap_[i].vertex] = static_cast<std::uint32_t>(i);
        i = parent;
    }
    heap_[i] = entry;
    heap_position_[entry.vertex] = static_cast<std::uint32_t>(i);
}

void CollapseMesh::heap_down(std::size_t i) {
    const HeapEntry entry = heap_[i];
    const std::size_t n = heap_.size();
    for (;;) {
        std::size_t child = 2 * i + 1;
        if (child >= n) break;
        if (child + 1 < n && heap_[child + 1].key < heap_[child].key) ++child;
        if (!(heap_[child].key < entry.key)) break;
        heap_[i] = heap_[child];
        heap_position_[heap_[i].vertex] = static_cast<std::uint32_t>(i);
        i = child;
    }
    heap_[i] = entry;
    heap_position_[entry.vertex] = static_cast<std::uint32_t>(i);
}

void CollapseMesh::heap_remove(std::uint32_t v) {
    const std::uint32_t i = heap_position_[v];
    if (i == kNone) return;
    heap_position_[v] = kNone;
    const HeapEntry last = heap_.back();
    heap_.pop_back();
    if (last.vertex == v) return;
    heap_[i] = last;
    heap_position_[last.vertex] = i;
    heap_up(i);
    heap_down(heap_position_[last.vertex]);
}

void CollapseMesh::heap_place(std::uint32_t v) {
    std::uint32_t i = heap_position_[v];
    if (i == kNone) {
        i = static_cast<std::uint32_t>(heap_.size());
        heap_.push_back({priority_[v], v});
        heap_position_[v] = i;
    } else {
        heap_[i].key = priority_[v];
    }
    heap_up(i);
    heap_down(heap_position_[v]);
}

}  // namespace sylva
