#include "lowpoly/decimate.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/BaseDecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>
#include <OpenMesh/Tools/Decimater/Observer.hh>
#include <OpenMesh/Tools/Utils/HeapT.hh>
#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <limits>

#include "core/disjoint_sets.h"
#include "core/errors.h"
#include "lowpoly/handle_cutting.h"
#include "marching/mesh_checks.h"

namespace sylva {
namespace {

// Doubles for points: quadric errors of a metre-sized tree reach 1e-12 and below.
struct Traits : OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;
    using Normal = OpenMesh::Vec3d;
    VertexAttributes(OpenMesh::Attributes::Status);
    EdgeAttributes(OpenMesh::Attributes::Status);
    FaceAttributes(OpenMesh::Attributes::Status | OpenMesh::Attributes::Normal);
};

// Debian builds libOpenMeshCore without NDEBUG, so every property access inside the
// library checks a type name string, and OpenMesh's generic circulators are heavy. The
// decimater asks is_collapse_ok() and find_halfedge() for every candidate collapse (dozens
// per collapse): those two were three quarters of the run time. The same tests, here,
// compile to inline code; the decimater templates (BaseDecimaterT::is_collapse_legal)
// find these members by name before the library's.
struct OmMesh : OpenMesh::TriMesh_ArrayKernelT<Traits> {
    // Calls f(h) for every halfedge going out of v (v must not be isolated).
    template <class F>
    bool all_outgoing(VertexHandle v, F&& f) const {
        const HalfedgeHandle start = halfedge_handle(v);
        HalfedgeHandle h = start;
        do {
            if (!f(h)) return false;
            h = next_halfedge_handle(opposite_halfedge_handle(h));
        } while (h != start);
        return true;
    }

    HalfedgeHandle find_halfedge(VertexHandle from, VertexHandle to) const {
        HalfedgeHandle found;
        if (!halfedge_handle(from).is_valid()) return found;
        all_outgoing(from, [&](HalfedgeHandle h) {
            if (to_vertex_handle(h) != to) return true;
            found = h;
            return false;
        });
        return found;
    }

    // OpenMesh's TriConnectivity::is_collapse_ok, with the one-ring intersection (the
    // link condition) done on a small array instead of tag bits.
    bool is_collapse_ok(HalfedgeHandle v0v1) {
        if (status(edge_handle(v0v1)).deleted()) return false;
        const HalfedgeHandle v1v0 = opposite_halfedge_handle(v0v1);
        const VertexHandle v0 = to_vertex_handle(v1v0), v1 = to_vertex_handle(v0v1);
        if (status(v0).deleted() || status(v1).deleted()) return false;
        // The edges v1-vl and vl-v0 (and v0-vr, vr-v1) must not both be boundary edges.
        VertexHandle vl, vr;
        if (!is_boundary(v0v1)) {
            const HalfedgeHandle h1 = next_halfedge_handle(v0v1), h2 = next_halfedge_handle(h1);
            vl = to_vertex_handle(h1);
            if (is_boundary(opposite_halfedge_handle(h1)) &&
                is_boundary(opposite_halfedge_handle(h2)))
                return false;
        }
        if (!is_boundary(v1v0)) {
            const HalfedgeHandle h1 = next_halfedge_handle(v1v0), h2 = next_halfedge_handle(h1);
            vr = to_vertex_handle(h1);
            if (is_boundary(opposite_halfedge_handle(h1)) &&
                is_boundary(opposite_halfedge_handle(h2)))
                return false;
        }
        if (vl == vr) return false;
        if (is_boundary(v0) && is_boundary(v1) && !is_boundary(v0v1) && !is_boundary(v1v0))
            return false;
        // Link condition: v0 and v1 share no neighbour but vl and vr.
        constexpr int kMaxValence = 64;
        VertexHandle ring[kMaxValence];
        int n = 0;
        if (!all_outgoing(v1, [&](HalfedgeHandle h) {
                if (n == kMaxValence) return false;  // never seen; refuse rather than overflow
                ring[n++] = to_vertex_handle(h);
                return true;
            }))
            return false;
        return all_outgoing(v0, [&](HalfedgeHandle h) {
            const VertexHandle v = to_vertex_handle(h);
            if (v == vl || v == vr) return true;
            for (int i = 0; i < n; ++i)
                if (ring[i] == v) return false;
            return true;
        });
    }
};

// Geometric guards for one collapse: no triangle that stays may turn its normal by more
// than the limit (no flips, no fold-overs) or shrink to a sliver of (near) zero area,
// which check_topology would call degenerate. OpenMesh's collapse test (link condition, no
// tetrahedron collapse) keeps the topology.
class Guards {
  public:
    Guards(double max_turn_degrees, double min_twice_area)
        : min_cos_(std::cos(max_turn_degrees * M_PI / 180.0)),
          min_twice_area_squared_(min_twice_area * min_twice_area) {}

    // Walks v0's outgoing halfedges (each face around v0 is v0 -> a -> b, with v0 moved
    // to p1) in plain arithmetic and squares: this runs for every promising candidate.
    bool hold(const OmMesh& mesh, const OpenMesh::Decimater::CollapseInfoT<OmMesh>& ci) const {
        return fan_within_limits(mesh, ci.v0, ci.p1, ci.fl, ci.fr);
    }

    // Moving v to `to` keeps every triangle around it within the limits (the same test for
    // a vertex that moves instead of one that merges).
    bool allow_move(const OmMesh& mesh, OmMesh::VertexHandle v, const OmMesh::Point& to) const {
        return fan_within_limits(mesh, v, to, OmMesh::FaceHandle(), OmMesh::FaceHandle());
    }

  private:
    // Every face around v, with v moved to `to` (faces `skip_a` and `skip_b`, which a
    // collapse removes, left out), keeps a non-sliver area and turns its normal by no more
    // than the limit.
    bool fan_within_limits(const OmMesh& mesh, OmMesh::VertexHandle v, const OmMesh::Point& to,
                           OmMesh::FaceHandle skip_a, OmMesh::FaceHandle skip_b) const {
        const double px = to[0], py = to[1], pz = to[2];
        const double min_cos2 = min_cos_ * min_cos_;
        return mesh.all_outgoing(v, [&](OmMesh::HalfedgeHandle h) {
            const auto fh = mesh.face_handle(h);
            if (!fh.is_valid() || fh == skip_a || fh == skip_b) return true;
            const auto& a = mesh.point(mesh.to_vertex_handle(h));
            const auto& b = mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h)));
            const double ax = a[0] - px, ay = a[1] - py, az = a[2] - pz;
            const double bx = b[0] - px, by = b[1] - py, bz = b[2] - pz;
            const double nx = ay * bz - az * by, ny = az * bx - ax * bz, nz = ax * by - ay * bx;
            const double n2 = nx * nx + ny * ny + nz * nz;
            if (n2 <= min_twice_area_squared_) return false;
            // cos(turn) = n.old / |n| with a unit old normal.
            const auto& old = mesh.normal(fh);
            const double d = nx * old[0] + ny * old[1] + nz * old[2];
            return min_cos_ >= 0.0 ? (d >= 0.0 && d * d >= min_cos2 * n2)
                                   : (d >= 0.0 || d * d <= min_cos2 * n2);
        });
    }

    double min_cos_;
    double min_twice_area_squared_;
};

// OpenMesh's greedy decimater (BaseDecimaterT, ModQuadricT, one heap entry per vertex
// holding its cheapest legal halfedge collapse) with the checks reordered. DecimaterT
// tests every candidate for legality before scoring it; here the quadric error comes
// first, and the link condition and the guards run only for a candidate cheaper than the
// vertex's best so far. The choice is the same; the run time is about half, which is
// what brings a 100k-triangle tree under half a second.
class LazyDecimater : public OpenMesh::Decimater::BaseDecimaterT<OmMesh> {
  public:
    using Base = OpenMesh::Decimater::BaseDecimaterT<OmMesh>;
    using VertexHandle = OmMesh::VertexHandle;
    using HalfedgeHandle = OmMesh::HalfedgeHandle;
    using Quadric = OpenMesh::Geometry::Quadricd;

    LazyDecimater(OmMesh& mesh, const Guards& guards, float foot_height)
        : Base(mesh), mesh_(mesh), guards_(guards), foot_height_(foot_height) {
        add(quadric_);
        module(quadric_).unset_max_err();
        mesh_.add_property(target_);
        mesh_.add_property(priority_);
        mesh_.add_property(position_);
        mesh_.add_property(quadric_sum_);
        mesh_.add_property(piece_);
    }
    ~LazyDecimater() override {
        mesh_.remove_property(piece_);
        mesh_.remove_property(target_);
        mesh_.remove_property(priority_);
        mesh_.remove_property(position_);
        mesh_.remove_property(quadric_sum_);
    }

    // Collapses until at most `max_faces` triangles are left or no legal collapse is.
    // Throws Cancelled once `cancel` is set while the heap is built (the collapses poll it
    // through the observer).
    void decimate_to_faces(std::size_t max_faces, CancelFlag cancel) {
        if (!is_initialized() && !initialize()) return;
        throw_if_cancelled(cancel);
        std::size_t faces = mesh_.n_faces();
        // ModQuadricT keeps its quadrics to itself; the same sums, kept here, place the
        // vertices at the end (relocate()).
        for (VertexHandle v : mesh_.vertices()) mesh_.property(quadric_sum_, v) = Quadric();
        label_pieces();
        for (auto f : mesh_.faces()) {
            const auto n = mesh_.normal(f);
            const auto& p = mesh_.point(mesh_.to_vertex_handle(mesh_.halfedge_handle(f)));
            Quadric q(n[0], n[1], n[2], -(n | p));
            q *= 0.5 * mesh_.calc_face_area(f);
            for (VertexHandle v : mesh_.fv_range(f)) mesh_.property(quadric_sum_, v) += q;
        }
        Heap heap(HeapInterface{mesh_, priority_, position_});
        heap_ = &heap;
        heap.reserve(mesh_.n_vertices());
        for (VertexHandle v : mesh_.vertices()) {
            if ((v.idx() & 4095) == 4095) throw_if_cancelled(cancel);
            heap.reset_heap_position(v);
            if (!mesh_.status(v).deleted()) heap_vertex(v);
        }
        std::vector<VertexHandle> support;
        std::size_t collapses = 0;
        while (!heap.empty() && faces > max_faces) {
            const VertexHandle v = heap.front();
            const HalfedgeHandle h = mesh_.property(target_, v);
            heap.pop_front();
            CollapseInfo ci(mesh_, h);
            // The entry may be stale: check again, and look for a new target if it is.
            if (!is_collapse_legal(ci) || !guards_.hold(mesh_, ci) || !keeps_shape(ci)) {
                heap_vertex(v);
                continue;
            }
            piece_volume_[piece(ci.v0)] += volume_change(ci);
            if (is_foot(ci.v0)) --foot_vertices_[piece(ci.v0)];  // onto another foot vertex
            support.clear();
            mesh_.all_outgoing(ci.v0, [&](HalfedgeHandle o) {
                support.push_back(mesh_.to_vertex_handle(o));
                return true;
            });
            faces -= (mesh_.is_boundary(ci.v0v1) || mesh_.is_boundary(ci.v1v0)) ? 1 : 2;
            preprocess_collapse(ci);
            mesh_.collapse(h);
            for (auto f : mesh_.vf_range(ci.v1)) mesh_.set_normal(f, mesh_.calc_face_normal(f));
            postprocess_collapse(ci);
            mesh_.property(quadric_sum_, ci.v1) += mesh_.property(quadric_sum_, ci.v0);
            for (VertexHandle s : support) heap_vertex(s);
            if (!notify_observer(++collapses)) break;
        }
        heap_ = nullptr;
    }

    // Halfedge collapses keep every vertex on the input surface, so a coarse result is
    // inscribed in it (a sphere comes out smaller). Moving each vertex to the minimum of
    // its accumulated quadric (the planes of the input it stands for) lets the facets
    // straddle the surface instead. A small pull towards the current position keeps flat
    // and ridge neighbourhoods (singular quadrics) in place; a move that would fold a
    // triangle is halved, then dropped.
    void relocate() {
        for (VertexHandle v : mesh_.vertices()) {
            if (mesh_.status(v).deleted() || !mesh_.halfedge_handle(v).is_valid()) continue;
            const Quadric& q = mesh_.property(quadric_sum_, v);
            const OmMesh::Point p = mesh_.point(v);
            const double mu = 1e-3 * (q.a() + q.e() + q.h()) / 3.0 + 1e-30;
            // (A + mu I) x = mu p - b
            const double m[3][3] = {
                {q.a() + mu, q.b(), q.c()}, {q.b(), q.e() + mu, q.f()}, {q.c(), q.f(), q.h() + mu}};
            const double r[3] = {mu * p[0] - q.d(), mu * p[1] - q.g(), mu * p[2] - q.i()};
            const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                               m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
            if (!(std::abs(det) > 0.0) || !std::isfinite(det)) continue;
            OmMesh::Point x;
            for (int k = 0; k < 3; ++k) {  // Cramer's rule
                double c[3][3];
                for (int i = 0; i < 3; ++i)
                    for (int j = 0; j < 3; ++j) c[i][j] = j == k ? r[i] : m[i][j];
                x[k] = (c[0][0] * (c[1][1] * c[2][2] - c[1][2] * c[2][1]) -
                        c[0][1] * (c[1][0] * c[2][2] - c[1][2] * c[2][0]) +
                        c[0][2] * (c[1][0] * c[2][1] - c[1][1] * c[2][0])) /
                       det;
            }
            if (is_foot(v)) x[1] = p[1];  // the foot stays on the ground
            for (double step : {1.0, 0.5}) {
                const OmMesh::Point candidate = p + step * (x - p);
                if (!std::isfinite(candidate[0]) || !std::isfinite(candidate[1]) ||
                    !std::isfinite(candidate[2]))
                    break;
                const std::size_t p_of_v = piece(v);
                const double change =
                    volume_change(v, candidate, OmMesh::FaceHandle(), OmMesh::FaceHandle());
                const bool keeps = !(piece_floor_[p_of_v] > 0.0) ||
                                   piece_volume_[p_of_v] + change > piece_floor_[p_of_v];
                if (keeps && guards_.allow_move(mesh_, v, candidate)) {
                    piece_volume_[p_of_v] += change;
                    mesh_.set_point(v, candidate);
                    for (auto f : mesh_.vf_range(v)) mesh_.set_normal(f, mesh_.calc_face_normal(f));
                    break;
                }
            }
        }
    }

  private:
    struct HeapInterface {
        OmMesh& mesh;
        OpenMesh::VPropHandleT<float> priority;
        OpenMesh::VPropHandleT<int> position;
        bool less(VertexHandle a, VertexHandle b) {
            return mesh.property(priority, a) < mesh.property(priority, b);
        }
        bool greater(VertexHandle a, VertexHandle b) {
            return mesh.property(priority, a) > mesh.property(priority, b);
        }
        int get_heap_position(VertexHandle v) { return mesh.property(position, v); }
        void set_heap_position(VertexHandle v, int p) { mesh.property(position, v) = p; }
    };
    using Heap = OpenMesh::Utils::HeapT<VertexHandle, HeapInterface>;

    // Connected pieces and their enclosed volumes. Each collapse guards its own fan, but
    // a small closed piece can still fold through itself over several collapses and come
    // out inside out (a tetrahedron of negative volume); tracking each piece's volume
    // forbids the collapse that would take it below a sliver of what it had.
    void label_pieces() {
        DisjointSets sets(mesh_.n_vertices());
        for (auto f : mesh_.faces()) {
            if (mesh_.status(f).deleted()) continue;
            std::uint32_t first = UINT32_MAX;
            for (VertexHandle v : mesh_.fv_range(f)) {
                const auto i = static_cast<std::uint32_t>(v.idx());
                if (first == UINT32_MAX)
                    first = i;
                else
                    sets.unite(i, first);
            }
        }
        std::vector<int> slot(mesh_.n_vertices(), -1);
        piece_volume_.clear();
        for (VertexHandle v : mesh_.vertices()) {
            int& s = slot[sets.find(static_cast<std::uint32_t>(v.idx()))];
            if (s < 0) {
                s = static_cast<int>(piece_volume_.size());
                piece_volume_.push_back(0.0);
            }
            mesh_.property(piece_, v) = s;
        }
        for (auto f : mesh_.faces()) {
            if (mesh_.status(f).deleted()) continue;
            auto it = mesh_.cfv_iter(f);
            const auto a = mesh_.point(*it), b = mesh_.point(*++it), c = mesh_.point(*++it);
            piece_volume_[piece(*it)] += (a | (b % c)) / 6.0;
        }
        foot_vertices_.assign(piece_volume_.size(), 0);
        for (VertexHandle v : mesh_.vertices())
            if (!mesh_.status(v).deleted() && is_foot(v)) ++foot_vertices_[piece(v)];
        piece_floor_.resize(piece_volume_.size());
        for (std::size_t i = 0; i < piece_volume_.size(); ++i)
            piece_floor_[i] = 1e-3 * piece_volume_[i];
    }

    std::size_t piece(VertexHandle v) const {
        return static_cast<std::size_t>(mesh_.property(piece_, v));
    }

    // The change of the enclosed volume when v0 moves to p1 and the faces fl, fr vanish:
    // measured from v0, every face through v0 starts with no volume, so the change is the
    // volume each remaining face sweeps with its corner moving to p1.
    double volume_change(const CollapseInfo& ci) const {
        return volume_change(ci.v0, ci.p1, ci.fl, ci.fr);
    }

    // The same for v moving to `to`, faces skip_a and skip_b (if valid) left out.
    double volume_change(VertexHandle v, const OmMesh::Point& to, OmMesh::FaceHandle skip_a,
                         OmMesh::FaceHandle skip_b) const {
        const auto& o = mesh_.point(v);
        const auto d = to - o;
        double six = 0.0;
        mesh_.all_outgoing(v, [&](HalfedgeHandle h) {
            const auto f = mesh_.face_handle(h);
            if (!f.is_valid() || f == skip_a || f == skip_b) return true;
            const auto a = mesh_.point(mesh_.to_vertex_handle(h)) - o;
            const auto b = mesh_.point(mesh_.to_vertex_handle(mesh_.next_halfedge_handle(h))) - o;
            six += d | (a % b);
            return true;
        });
        return six / 6.0;
    }

    bool keeps_shape(const CollapseInfo& ci) const { return keeps_volume(ci) && keeps_foot(ci); }

    // A foot vertex may only merge into another foot vertex, and only while its piece has
    // more than kMinFootVertices.
    bool keeps_foot(const CollapseInfo& ci) const {
        if (!is_foot(ci.v0)) return true;
        return is_foot(ci.v1) && foot_vertices_[piece(ci.v0)] > kMinFootVertices;
    }

    bool is_foot(VertexHandle v) const { return mesh_.point(v)[1] <= foot_height_; }

    // Inner shells (negative volume by nature) are left alone.
    bool keeps_volume(const CollapseInfo& ci) const {
        const std::size_t p = piece(ci.v0);
        if (!(piece_floor_[p] > 0.0)) return true;
        return piece_volume_[p] + volume_change(ci) > piece_floor_[p];
    }

    // Finds v's cheapest legal collapse and files it in the heap (or takes v out).
    void heap_vertex(VertexHandle v) {
        OpenMesh::Decimater::ModQuadricT<OmMesh>& quadric = module(quadric_);
        float best = std::numeric_limits<float>::max();
        HalfedgeHandle target;
        mesh_.all_outgoing(v, [&](HalfedgeHandle h) {
            const CollapseInfo ci(mesh_, h);
            const float error = quadric.collapse_priority(ci);
            if (error < 0.0f || !(error < best)) return true;
            if (!is_collapse_legal(ci) || !guards_.hold(mesh_, ci) || !keeps_shape(ci)) return true;
            best = error;
            target = h;
            return true;
        });
        mesh_.property(target_, v) = target;
        if (target.is_valid()) {
            mesh_.property(priority_, v) = best;
            if (heap_->is_stored(v))
                heap_->update(v);
            else
                heap_->insert(v);
        } else {
            mesh_.property(priority_, v) = -1.0f;
            if (heap_->is_stored(v)) heap_->remove(v);
        }
    }

    OmMesh& mesh_;
    Guards guards_;
    OpenMesh::Decimater::ModQuadricT<OmMesh>::Handle quadric_;
    OpenMesh::VPropHandleT<HalfedgeHandle> target_;
    OpenMesh::VPropHandleT<float> priority_;
    OpenMesh::VPropHandleT<int> position_;
    OpenMesh::VPropHandleT<Quadric> quadric_sum_;
    OpenMesh::VPropHandleT<int> piece_;
    std::vector<double> piece_volume_;
    std::vector<double> piece_floor_;
    float foot_height_;
    std::vector<std::size_t> foot_vertices_;  // per piece
    Heap* heap_ = nullptr;
};

class ProgressObserver : public OpenMesh::Decimater::Observer {
  public:
    ProgressObserver(std::size_t interval, std::size_t expected, const DecimateSettings& s)
        : Observer(interval), expected_(std::max<std::size_t>(expected, 1)), settings_(s) {}

    void notify(std::size_t step) override {
        if (settings_.progress)
            settings_.progress(std::min(1.0f, static_cast<float>(step) / expected_));
    }
    bool abort() const override { return settings_.cancel && settings_.cancel->load(); }

  private:
    std::size_t expected_;
    const DecimateSettings& settings_;
};

std::string describe(const MeshTopology& t) {
    std::string s;
    auto add = [&s](std::size_t n, const char* what) {
        if (n == 0) return;
        if (!s.empty()) s += ", ";
        s += std::to_string(n) + " " + what;
    };
    add(t.boundary_edges, "boundary edges");
    add(t.non_manifold_edges, "non-manifold edges");
    add(t.misoriented_edges, "misoriented edges");
    add(t.degenerate_triangles, "degenerate triangles");
    add(t.non_manifold_vertices, "non-manifold vertices");
    return s;
}

double bounding_diagonal_squared(std::span<const Mesh* const> parts) {
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
    for (const Mesh* m : parts)
        for (const glm::vec3& p : m->positions) {
            lo = glm::min(lo, glm::dvec3(p));
            hi = glm::max(hi, glm::dvec3(p));
        }
    if (lo.x > hi.x) return 0.0;
    const glm::dvec3 d = hi - lo;
    return d.x * d.x + d.y * d.y + d.z * d.z;
}

// All parts in one OpenMesh mesh (they share no vertex, so no collapse ever joins them);
// a vertex property remembers the part.
void build(std::span<const Mesh* const> parts, OmMesh& om, OpenMesh::VPropHandleT<int> part_of) {
    std::size_t nv = 0, nf = 0;
    for (const Mesh* m : parts) {
        nv += m->positions.size();
        nf += m->triangles.size();
    }
    om.reserve(nv, nf * 3 / 2, nf);
    std::vector<OmMesh::VertexHandle> handles;
    for (std::size_t k = 0; k < parts.size(); ++k) {
        const Mesh& m = *parts[k];
        handles.clear();
        handles.reserve(m.positions.size());
        for (const glm::vec3& p : m.positions) {
            handles.push_back(om.add_vertex(OmMesh::Point(p.x, p.y, p.z)));
            om.property(part_of, handles.back()) = static_cast<int>(k);
        }
        for (const auto& t : m.triangles) {
            auto fh = om.add_face(handles[t[0]], handles[t[1]], handles[t[2]]);
            if (!fh.is_valid())
                throw InputError("decimate: part " + std::to_string(k) +
                                 " has a triangle OpenMesh cannot add (complex "
                                 "edge or vertex)");
        }
    }
}

std::vector<Mesh> extract(const OmMesh& om, OpenMesh::VPropHandleT<int> part_of,
                          std::size_t part_count) {
    std::vector<Mesh> out(part_count);
    // Only vertices that a triangle uses; new indices in the old order (deterministic).
    constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> index(om.n_vertices(), kUnused);
    for (auto fh : om.faces()) {
        if (om.status(fh).deleted()) continue;
        for (auto vh : om.fv_range(fh)) index[vh.idx()] = 0;
    }
    for (auto vh : om.vertices()) {
        if (index[vh.idx()] == kUnused || om.status(vh).deleted()) continue;
        Mesh& m = out[static_cast<std::size_t>(om.property(part_of, vh))];
        index[vh.idx()] = static_cast<std::uint32_t>(m.positions.size());
        const OmMesh::Point& p = om.point(vh);
        m.positions.emplace_back(static_cast<float>(p[0]), static_cast<float>(p[1]),
                                 static_cast<float>(p[2]));
    }
    for (auto fh : om.faces()) {
        if (om.status(fh).deleted()) continue;
        std::array<std::uint32_t, 3> t{};
        int k = 0, part = 0;
        for (auto vh : om.fv_range(fh)) {
            t[k++] = index[vh.idx()];
            part = om.property(part_of, vh);
        }
        out[static_cast<std::size_t>(part)].triangles.push_back(t);
    }
    return out;
}

std::size_t count_triangles(const std::vector<Mesh>& parts) {
    std::size_t n = 0;
    for (const Mesh& m : parts) n += m.triangles.size();
    return n;
}

// Connected components enclosing no positive volume: inner shells, or pieces turned inside out.
std::size_t inward_pieces(const Mesh& mesh) {
    const std::vector<double> volumes = component_volumes(mesh);
    return static_cast<std::size_t>(
        std::count_if(volumes.begin(), volumes.end(), [](double v) { return !(v > 0.0); }));
}

// About where collapses stop: every closed piece keeps at least 4 triangles and every
// handle pins about a dozen more (lowpoly/handle_cutting.h).
std::size_t triangle_floor(std::span<const Mesh* const> parts) {
    std::size_t floor = 0;
    for (const Mesh* m : parts)
        if (!m->triangles.empty()) floor += 4 * component_volumes(*m).size() + 12 * genus(*m);
    return floor;
}

// One reduction from scratch down to `target` triangles.
std::vector<Mesh> reduce(std::span<const Mesh* const> parts, std::size_t target,
                         const DecimateSettings& settings, double min_twice_area) {
    OmMesh om;
    OpenMesh::VPropHandleT<int> part_of;
    om.add_property(part_of);
    build(parts, om, part_of);
    om.update_face_normals();

    LazyDecimater decimater(om, Guards(settings.max_normal_turn_degrees, min_twice_area),
                            settings.foot_height);
    decimater.initialize();
    throw_if_cancelled(settings.cancel);
    const std::size_t expected = om.n_faces() > target ? (om.n_faces() - target) / 2 : 0;
    ProgressObserver observer(std::max<std::size_t>(expected / 100, 64), expected, settings);
    decimater.set_observer(&observer);
    decimater.decimate_to_faces(target, settings.cancel);
    throw_if_cancelled(settings.cancel);
    if (settings.relocate_vertices) decimater.relocate();
    throw_if_cancelled(settings.cancel);
    if (settings.progress) settings.progress(1.0f);
    return extract(om, part_of, parts.size());
}

// Reduction with the safety net: a result that fails check_topology is redone with fewer
// collapses, down to returning the input.
DecimateResult reduce_with_backoff(std::span<const Mesh* const> parts,
                                   const DecimateSettings& settings, double min_twice_area) {
    DecimateResult result;
    std::size_t input_triangles = 0;
    for (const Mesh* m : parts) input_triangles += m->triangles.size();
    auto copy_input = [&] {
        result.parts.clear();
        for (const Mesh* m : parts) result.parts.push_back(*m);
    };
    std::vector<std::size_t> inward_before;
    for (const Mesh* m : parts) inward_before.push_back(inward_pieces(*m));
    std::size_t target = settings.max_triangles;
    constexpr int kMaxAttempts = 6;
    if (input_triangles <= target) {
        copy_input();
    } else {
        for (int attempt = 0;; ++attempt) {
            result.parts = reduce(parts, target, settings, min_twice_area);
            throw_if_cancelled(settings.cancel);
            std::string broken;
            for (std::size_t k = 0; k < result.parts.size(); ++k) {
                if (result.parts[k].triangles.empty() != parts[k]->triangles.empty()) {
                    broken = "part " + std::to_string(k) + " vanished";
                    break;
                }
                if (result.parts[k].triangles.empty()) continue;
                const MeshTopology t = check_topology(result.parts[k]);
                if (!t.is_closed_manifold()) {
                    broken = "part " + std::to_string(k) + " had " + describe(t);
                    break;
                }
                // Collapses guard each triangle's turn, but a small piece can still fold
                // through itself and come out inside out: closed, yet with no volume. (An
                // inner shell, the wall of a hollow, is inward by nature: count only new ones.)
                if (inward_pieces(result.parts[k]) > inward_before[k]) {
                    broken = "part " + std::to_string(k) + " had an inside-out piece";
                    break;
                }
            }
            if (broken.empty()) break;
            ++result.backoffs;
            // Fewer collapses: halfway back towards the input each time.
            target += (input_triangles - target + 1) / 2;
            if (attempt + 1 >= kMaxAttempts || target >= input_triangles) {
                copy_input();
                result.note =
                    "reduction broke the mesh (" + broken + "); returned the input unreduced";
                break;
            }
            result.note = "reduction to fewer triangles broke the mesh (" + broken +
                          "); backed off to " + std::to_string(target) + " triangles";
        }
    }
    result.triangles = count_triangles(result.parts);
    result.within_budget = result.triangles <= settings.max_triangles;
    return result;
}

}  // namespace

DecimateResult decimate(std::span<const Mesh* const> parts, const DecimateSettings& settings) {
    for (std::size_t k = 0; k < parts.size(); ++k) {
        if (parts[k]->triangles.empty()) continue;
        // Slivers of (near) zero area are fine here: marching cubes on a very fine grid
        // makes some, and they are the first collapses. The result has none.
        MeshTopology topology = check_topology(*parts[k]);
        topology.degenerate_triangles = 0;
        if (!topology.is_closed_manifold())
            throw InputError("decimate: part " + std::to_string(k) +
                             " is not a closed 2-manifold (" + describe(topology) + ")");
    }
    // Well above check_topology's zero-area threshold (2e-12 of the squared diagonal).
    const double min_twice_area = 1e-9 * bounding_diagonal_squared(parts);
    // Handles and pieces set a floor no collapse goes below. When it is above the budget
    // the direct reduction is wasted work (the slowest part of a crossing-branch tree):
    // go straight to the intermediate one and cut handles there.
    throw_if_cancelled(settings.cancel);
    const std::size_t floor = triangle_floor(parts);
    throw_if_cancelled(settings.cancel);
    const bool handles_pin = settings.cut_handles && floor > settings.max_triangles;
    DecimateResult result;
    if (!handles_pin) result = reduce_with_backoff(parts, settings, min_twice_area);

    // Over budget at the floor: handles pin the remaining triangles. Cut them where the
    // parts still have detail (an intermediate reduction to a few times the floor, so the
    // final one can still share the budget well between the parts), shortest loops
    // first, then reduce the cut parts to the budget; repeat while it helps.
    if (handles_pin || (!result.within_budget && settings.cut_handles && result.backoffs == 0)) {
        // Progress already reached 1; the passes below only poll the cancel flag.
        DecimateSettings quiet = settings;
        quiet.progress = nullptr;
        DecimateSettings intermediate = quiet;
        intermediate.max_triangles =
            std::max(4 * settings.max_triangles, 4 * (handles_pin ? floor : result.triangles));
        DecimateResult detailed = reduce_with_backoff(parts, intermediate, min_twice_area);
        if (handles_pin) {
            result = detailed;  // the best so far, measured against the real budget
            result.within_budget = result.triangles <= settings.max_triangles;
        }
        std::vector<Mesh> cut = std::move(detailed.parts);
        int handles_cut = 0;
        for (int round = 0; round < 8 && !result.within_budget && detailed.backoffs == 0; ++round) {
            throw_if_cancelled(settings.cancel);
            std::vector<std::size_t> genera;
            std::size_t total_genus = 0;
            for (const Mesh& m : cut)
                total_genus += genera.emplace_back(m.triangles.empty() ? 0 : genus(m));
            if (total_genus == 0) break;
            // A handle pins about a dozen triangles at the floor.
            const std::size_t wanted = std::clamp<std::size_t>(
                (result.triangles - settings.max_triangles + 7) / 8, 1, total_genus);
            std::size_t done = 0;
            for (std::size_t k = 0; k < cut.size(); ++k) {
                const std::size_t share = (wanted * genera[k] + total_genus - 1) / total_genus;
                if (share > 0) done += cut_handles(cut[k], share, settings.cancel);
            }
            if (done == 0) break;
            handles_cut += static_cast<int>(done);
            std::vector<const Mesh*> pointers;
            for (const Mesh& m : cut) pointers.push_back(&m);
            DecimateResult again = reduce_with_backoff(pointers, quiet, min_twice_area);
            // Keep the last clean result, and only take a better one.
            if (again.triangles >= result.triangles) break;
            again.handles_cut = handles_cut;
            result = std::move(again);
        }
    }

    if (!result.within_budget && result.note.empty())
        result.note = "stopped at " + std::to_string(result.triangles) + " of a budget of " +
                      std::to_string(settings.max_triangles) +
                      " triangles: no further collapse keeps every part closed and manifold "
                      "without folding a triangle" +
                      (result.handles_cut > 0
                           ? " (after cutting " + std::to_string(result.handles_cut) + " handles)"
                           : std::string());
    return result;
}

DecimateResult decimate(const Mesh& mesh, const DecimateSettings& settings) {
    const Mesh* parts[] = {&mesh};
    return decimate(parts, settings);
}

}  // namespace sylva
