// The only file of Sylva that includes CGAL (its headers take long to compile).
#include "quality/self_intersections.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <cassert>
#include <iterator>
#include <utility>

#include "core/disjoint_sets.h"
#include "quality/weld.h"

namespace sylva {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
using Corners = std::array<std::uint32_t, 3>;  // welded vertices of a triangle

// One piece: its triangles that bound area, as indices into the input mesh.
struct Piece {
    std::vector<std::uint32_t> triangles;
};

// The piece as a Surface_mesh, faces in the order of piece.triangles; false when it is no
// 2-manifold (add_face refuses a face that would make an edge or a vertex complex).
bool build_surface_mesh(const Piece& piece, const std::vector<Corners>& corners,
                        const std::vector<Point>& points, SurfaceMesh& out) {
    std::vector<SurfaceMesh::Vertex_index> local(points.size(), SurfaceMesh::null_vertex());
    for (std::uint32_t t : piece.triangles) {
        std::array<SurfaceMesh::Vertex_index, 3> face;
        for (int k = 0; k < 3; ++k) {
            SurfaceMesh::Vertex_index& v = local[corners[t][k]];
            if (v == SurfaceMesh::null_vertex()) v = out.add_vertex(points[corners[t][k]]);
            face[k] = v;
        }
        if (out.add_face(face[0], face[1], face[2]) == SurfaceMesh::null_face()) return false;
    }
    return true;
}

// CGAL's own test (Polygon_mesh_processing::internal::do_faces_intersect) on two triangles
// given by their corners, for pieces a Surface_mesh cannot hold.
bool soup_triangles_intersect(const Corners& a, const Corners& b, const std::vector<Point>& p) {
    // A shared edge: an intersection only when both lie in one plane, on one side of it.
    for (int i = 0; i < 3; ++i) {
        const std::uint32_t u = a[i], v = a[(i + 1) % 3], w = a[(i + 2) % 3];
        for (int j = 0; j < 3; ++j) {
            const std::uint32_t x = b[j], y = b[(j + 1) % 3], z = b[(j + 2) % 3];
            if ((u == x && v == y) || (u == y && v == x))
                return CGAL::coplanar(p[u], p[v], p[w], p[z]) &&
                       CGAL::coplanar_orientation(p[u], p[v], p[w], p[z]) == CGAL::POSITIVE;
        }
    }
    const Kernel::Triangle_3 ta(p[a[0]], p[a[1]], p[a[2]]);
    const Kernel::Triangle_3 tb(p[b[0]], p[b[1]], p[b[2]]);
    // A shared vertex: an intersection when the edge opposite it in one triangle meets the
    // other triangle.
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (a[i] == b[j])
                return CGAL::do_intersect(
                           ta, Kernel::Segment_3(p[b[(j + 1) % 3]], p[b[(j + 2) % 3]])) ||
                       CGAL::do_intersect(tb,
                                          Kernel::Segment_3(p[a[(i + 1) % 3]], p[a[(i + 2) % 3]]));
    return CGAL::do_intersect(ta, tb);
}

using Box =
    CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::uint32_t,
                                              CGAL::Box_intersection_d::ID_FROM_BOX_ADDRESS>;

// The pairs of a piece that is no 2-manifold: CGAL's box intersection, then the same test
// as self_intersections() per pair of overlapping boxes. Degenerate triangles are left out
// by the caller.
void soup_self_intersections(const Piece& piece, const std::vector<Corners>& corners,
                             const std::vector<Point>& points,
                             std::vector<std::array<std::uint32_t, 2>>& pairs) {
    std::vector<Box> boxes;
    boxes.reserve(piece.triangles.size());
    for (std::uint32_t t : piece.triangles) {
        const Corners& c = corners[t];
        boxes.emplace_back(points[c[0]].bbox() + points[c[1]].bbox() + points[c[2]].bbox(), t);
    }
    // Pointers, as CGAL does: box_self_intersection_d copies the range it is given, and the
    // boxes' ids are their addresses.
    std::vector<const Box*> pointers;
    pointers.reserve(boxes.size());
    for (const Box& b : boxes) pointers.push_back(&b);
    CGAL::box_self_intersection_d<CGAL::Sequential_tag>(
        pointers.begin(), pointers.end(), [&](const Box* a, const Box* b) {
            if (soup_triangles_intersect(corners[a->info()], corners[b->info()], points))
                pairs.push_back({a->info(), b->info()});
        });
}

}  // namespace

SelfIntersections find_self_intersections(const Mesh& mesh) {
    SelfIntersections result;
    const Welding welding = weld_by_position(mesh);
    std::vector<Point> points(welding.count);
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::vec3& q = mesh.positions[v];
        points[welding.vertex[v]] = Point(q.x, q.y, q.z);
    }
    const std::size_t n = mesh.triangles.size();
    std::vector<Corners> corners(n);
    DisjointSets sets(welding.count);
    for (std::size_t t = 0; t < n; ++t) {
        for (int k = 0; k < 3; ++k) {
            assert(mesh.triangles[t][k] < mesh.positions.size());
            corners[t][k] = welding.vertex[mesh.triangles[t][k]];
        }
        sets.unite(corners[t][0], corners[t][1]);
        sets.unite(corners[t][0], corners[t][2]);
    }

    // Pieces in the order of their first triangles; degenerate triangles belong to their
    // piece but are not tested.
    std::vector<std::uint32_t> piece_of_root(welding.count, UINT32_MAX);
    std::vector<Piece> pieces;
    result.piece.resize(n);
    for (std::size_t t = 0; t < n; ++t) {
        std::uint32_t& id = piece_of_root[sets.find(corners[t][0])];
        if (id == UINT32_MAX) {
            id = static_cast<std::uint32_t>(pieces.size());
            pieces.emplace_back();
        }
        result.piece[t] = id;
        const Corners& c = corners[t];
        if (CGAL::collinear(points[c[0]], points[c[1]], points[c[2]]))
            result.degenerate.push_back(static_cast<std::uint32_t>(t));
        else
            pieces[id].triangles.push_back(static_cast<std::uint32_t>(t));
    }
    result.pieces = pieces.size();
    result.pairs_per_piece.assign(pieces.size(), 0);

    for (std::size_t id = 0; id < pieces.size(); ++id) {
        const Piece& piece = pieces[id];
        const std::size_t before = result.pairs.size();
        SurfaceMesh surface;
        if (build_surface_mesh(piece, corners, points, surface)) {
            std::vector<std::pair<SurfaceMesh::Face_index, SurfaceMesh::Face_index>> faces;
            CGAL::Polygon_mesh_processing::self_intersections(surface, std::back_inserter(faces));
            // Faces were added in the order of piece.triangles, so a face's index is its
            // position there.
            for (const auto& [f, g] : faces)
                result.pairs.push_back({piece.triangles[f.idx()], piece.triangles[g.idx()]});
        } else {
            ++result.soup_pieces;
            soup_self_intersections(piece, corners, points, result.pairs);
        }
        result.pairs_per_piece[id] = result.pairs.size() - before;
    }
    for (auto& pair : result.pairs)
        if (pair[0] > pair[1]) std::swap(pair[0], pair[1]);
    std::sort(result.pairs.begin(), result.pairs.end());
    return result;
}

std::size_t self_intersecting_pairs(const Mesh& mesh) {
    return find_self_intersections(mesh).pairs.size();
}

}  // namespace sylva
