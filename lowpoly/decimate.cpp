#include "lowpoly/decimate.h"

#include "marching/mesh_checks.h"

#include <glm/common.hpp>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModBaseT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>
#include <OpenMesh/Tools/Decimater/Observer.hh>

#include <algorithm>
#include <cmath>
#include <limits>

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
using OmMesh = OpenMesh::TriMesh_ArrayKernelT<Traits>;

// Geometric guards for one collapse, in a single pass over the triangles that stay:
// none may turn its normal by more than the limit (no flips, no fold-overs) and none may
// become a sliver of (near) zero area, which check_topology would call degenerate.
// OpenMesh's collapse test (link condition, no tetrahedron collapse) keeps the topology.
template <class MeshT>
class ModGuardsT : public OpenMesh::Decimater::ModBaseT<MeshT> {
public:
    DECIMATING_MODULE(ModGuardsT, MeshT, Guards);

    explicit ModGuardsT(MeshT& mesh) : Base(mesh, true) {}

    void set_limits(double max_turn_degrees, double min_twice_area) {
        min_cos_ = std::cos(max_turn_degrees * M_PI / 180.0);
        min_twice_area_ = min_twice_area;
    }

    float collapse_priority(const CollapseInfo& ci) override {
        MeshT& mesh = Base::mesh();
        for (auto fh : mesh.vf_range(ci.v0)) {
            if (fh == ci.fl || fh == ci.fr) continue;
            typename MeshT::Point p[3];
            int k = 0;
            for (auto vh : mesh.fv_range(fh)) p[k++] = vh == ci.v0 ? ci.p1 : mesh.point(vh);
            const typename MeshT::Normal n = (p[1] - p[0]) % (p[2] - p[0]);
            const double twice_area = n.norm();
            if (twice_area <= min_twice_area_) return Base::ILLEGAL_COLLAPSE;
            if ((n | mesh.normal(fh)) < min_cos_ * twice_area) return Base::ILLEGAL_COLLAPSE;
        }
        return Base::LEGAL_COLLAPSE;
    }

private:
    double min_cos_ = 0.0;
    double min_twice_area_ = 0.0;
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
                throw std::invalid_argument("decimate: part " + std::to_string(k) +
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

// One reduction from scratch down to `target` triangles.
std::vector<Mesh> reduce(std::span<const Mesh* const> parts, std::size_t target,
                         const DecimateSettings& settings, double min_twice_area) {
    OmMesh om;
    OpenMesh::VPropHandleT<int> part_of;
    om.add_property(part_of);
    build(parts, om, part_of);
    om.update_face_normals();

    using Decimater = OpenMesh::Decimater::DecimaterT<OmMesh>;
    Decimater decimater(om);
    OpenMesh::Decimater::ModQuadricT<OmMesh>::Handle quadric;
    typename ModGuardsT<OmMesh>::Handle guards;
    decimater.add(quadric);
    decimater.add(guards);
    decimater.module(quadric).unset_max_err();
    decimater.module(guards).set_limits(settings.max_normal_turn_degrees, min_twice_area);
    decimater.initialize();

    const std::size_t expected = om.n_faces() > target ? (om.n_faces() - target) / 2 : 0;
    ProgressObserver observer(std::max<std::size_t>(expected / 100, 64), expected, settings);
    decimater.set_observer(&observer);
    decimater.decimate_to_faces(0, target);
    if (settings.cancel && settings.cancel->load()) throw DecimationCancelled();
    if (settings.progress) settings.progress(1.0f);
    return extract(om, part_of, parts.size());
}

}  // namespace

DecimateResult decimate(std::span<const Mesh* const> parts, const DecimateSettings& settings) {
    std::size_t input_triangles = 0;
    for (std::size_t k = 0; k < parts.size(); ++k) {
        if (parts[k]->triangles.empty()) continue;
        const MeshTopology topology = check_topology(*parts[k]);
        if (!topology.is_closed_manifold())
            throw std::invalid_argument("decimate: part " + std::to_string(k) +
                                        " is not a closed 2-manifold (" + describe(topology) +
                                        ")");
        input_triangles += parts[k]->triangles.size();
    }

    DecimateResult result;
    auto copy_input = [&] {
        result.parts.clear();
        for (const Mesh* m : parts) result.parts.push_back(*m);
    };
    // Well above check_topology's zero-area threshold (2e-12 of the squared diagonal).
    const double min_twice_area = 1e-9 * bounding_diagonal_squared(parts);

    std::size_t target = settings.max_triangles;
    constexpr int kMaxAttempts = 6;
    if (input_triangles <= target) {
        copy_input();
    } else {
        for (int attempt = 0;; ++attempt) {
            result.parts = reduce(parts, target, settings, min_twice_area);
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
            }
            if (broken.empty()) break;
            ++result.backoffs;
            // Fewer collapses: halfway back towards the input each time.
            target += (input_triangles - target + 1) / 2;
            if (attempt + 1 >= kMaxAttempts || target >= input_triangles) {
                copy_input();
                result.note = "reduction broke the mesh (" + broken +
                              "); returned the input unreduced";
                break;
            }
            result.note = "reduction to fewer triangles broke the mesh (" + broken +
                          "); backed off to " + std::to_string(target) + " triangles";
        }
    }

    result.triangles = count_triangles(result.parts);
    result.within_budget = result.triangles <= settings.max_triangles;
    if (!result.within_budget && result.note.empty())
        result.note = "stopped at " + std::to_string(result.triangles) + " of a budget of " +
                      std::to_string(settings.max_triangles) +
                      " triangles: no further collapse keeps every part closed and manifold "
                      "without folding a triangle";
    return result;
}

DecimateResult decimate(const Mesh& mesh, const DecimateSettings& settings) {
    const Mesh* parts[] = {&mesh};
    return decimate(parts, settings);
}

}  // namespace sylva
