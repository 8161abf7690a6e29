// The greedy quadric-error edge collapse under decimate() (lowpoly/decimate.h), on flat
// index arrays: closed triangle meshes as corner tables (halfedge h = 3 * face + corner,
// with its opposite), one binary heap of vertices keyed by their cheapest legal halfedge
// collapse (Garland-Heckbert quadrics, the error measured at the kept vertex), the link
// condition, the fold-over and sliver guards, the per-piece volume floor, the foot, and
// near the budget a guard that keeps the faces of a piece from crossing each other. The
// rules are those of OpenMesh's DecimaterT with ModQuadricT; the arrays make a collapse
// several times cheaper than OpenMesh's kernel, whose property lookups and handle checks
// dominated the run (Debian builds it without NDEBUG).
//
// A CollapseMesh is built once from the parts (which checks that each is a closed
// 2-manifold) and can be copied, reduced in steps (collapse_to() twice: a snapshot on the
// way down costs no second reduction), relocated, unfolded and extracted. Not thread-safe:
// one mesh per thread (collapse_together() gives each its own).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <glm/vec3.hpp>
#include <limits>
#include <span>
#include <vector>

#include "core/cancel.h"
#include "core/mesh.h"
#include "lowpoly/face_grid.h"
#include "lowpoly/triangle_crossing.h"

namespace sylva {

struct CollapseSettings {
    // No collapse may turn a remaining triangle's normal by more than this.
    double max_normal_turn_degrees = 75.0;
    // No remaining triangle may get twice its area at or below this (a sliver).
    double min_twice_area = 0.0;
    // Vertices at or below this height are the foot (DecimateSettings::foot_height).
    float foot_height = -std::numeric_limits<float>::infinity();
    // The fewest foot vertices a piece keeps.
    std::size_t min_foot_vertices = 6;
    // See DecimateSettings::lazy_legality.
    bool lazy_legality = true;
    // See DecimateSettings::fast_passes: collapse_to() makes the bulk of its collapses in
    // passes (collapse_in_passes()).
    bool passes = true;
    // See DecimateSettings::keep_apart: once collapse_to() is down to twice the count asked
    // for, no collapse, move or flip makes two faces of a piece cross
    // (lowpoly/triangle_crossing.h), until relax_guard().
    bool keep_apart = true;
};

class CollapseMesh {
  public:
    // The parts in one mesh (they share no vertex, so no collapse joins them). Returns
    // true when every non-empty part is a closed, consistently oriented 2-manifold
    // (triangles of zero area allowed); otherwise false with *bad_part the first part that
    // is not, and *this is unusable.
    bool build(std::span<const Mesh* const> parts, std::size_t* bad_part = nullptr);

    std::size_t triangles() const { return live_faces_; }
    // About where collapses stop: 4 triangles per closed piece and 12 per handle.
    std::size_t triangle_floor() const;

    // Quadrics, pieces, volumes: call once before collapse_to() (which fills the heap).
    void start(const CollapseSettings& settings, CancelFlag cancel);
    // Collapses the cheapest legal edges until at most `max_triangles` are left or no
    // collapse is legal; may be called again with a smaller count. The first call after
    // start() collapses in passes (collapse_in_passes(), with CollapseSettings::passes) down
    // to twice `max_triangles` or a few thousand triangles, then one at a time from the heap.
    // Calls `step` (if set) every `interval` collapses with the number done so far; stops
    // early when it returns false. Throws Cancelled when `cancel` is set while the heap is
    // built.
    void collapse_to(std::size_t max_triangles, std::size_t interval = 0,
                     const std::function<bool(std::size_t)>& step = nullptr);
    // Files every vertex in the heap unless done since start() (collapse_to() and
    // collapse_together() call it; front_key() and step() need it).
    void prepare_heap();
    // The error of the cheapest collapse waiting (+infinity when none is).
    float front_key() const;
    // One turn of collapse_to() for several meshes reduced as one (collapse_together()):
    // the front vertex collapses, or goes back with its cheapest legal collapse when that
    // costs more than its own or another mesh's front (`others_front`). Returns the
    // triangles removed (0 or 2). Precondition: front_key() is finite.
    std::size_t step(float others_front);
    // The errors waiting in the heap (one per vertex with a collapse), appended to `keys`.
    void waiting_keys(std::vector<float>& keys) const;
    // Steps while the front's error is at most `max_key` and more than `min_triangles` are
    // left, each weighed against `max_key` as the other meshes' front; returns the triangles
    // removed.
    std::size_t collapse_up_to(float max_key, std::size_t min_triangles);
    // When no collapse is left that keeps the faces apart (CollapseSettings::keep_apart),
    // lets the rest make faces cross: the guard goes off for good and the heap is filed
    // anew. Returns whether that left a collapse to make (false when it was off already).
    bool relax_guard();
    // The pairs of faces of one piece that cross (lowpoly/triangle_crossing.h): what the
    // guard could not keep apart. About a microsecond per face.
    std::size_t crossing_pairs() const;
    // Moves each vertex to the minimum of its accumulated quadric where the guards allow.
    void relocate();
    // Flips edges where two faces fold inwards sharper than a right angle: of a bent quad's
    // two diagonals one folds in and one out, and the one out fills the valley. A flip is
    // made where the quad's five edges fold inwards less after it (past a right angle,
    // weighted by length), it adds volume, keeps the mesh a closed 2-manifold (no vertex
    // below valence 3, no edge twice) and, while the guard runs, crosses no face; in sweeps
    // over the live faces until none is left (at most 8). Vertices do not move. Returns the
    // flips made.
    std::size_t unfold();
    // The parts as meshes: used vertices in their original order, triangles likewise.
    std::vector<Mesh> extract() const;

  private:
    struct Quadric {
        double a = 0, b = 0, c = 0, d = 0, e = 0, f = 0, g = 0, h = 0, i = 0, j = 0;
        void add_plane(double na, double nb, double nc, double nd, double weight);
        Quadric& operator+=(const Quadric& q);
        double operator()(const glm::dvec3& p) const;
    };
    static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

    static std::uint32_t next(std::uint32_t h) { return h % 3 == 2 ? h - 2 : h + 1; }
    static std::uint32_t prev(std::uint32_t h) { return h % 3 == 0 ? h + 2 : h - 1; }
    std::uint32_t to(std::uint32_t h) const { return corner_[next(h)]; }
    // The next halfedge out of the same vertex (around it, as OpenMesh turns).
    std::uint32_t turn(std::uint32_t h) const { return next(opposite_[h]); }

    // The bulk of a reduction towards `until` triangles, as meshoptimizer's simplifier orders
    // it: each pass files every vertex by its cheapest collapse once, sorts them, and makes
    // those collapses in that order (with the same legality tests as one at a time) up to a
    // little above the error of the last one the pass wants, each vertex at most once (a
    // collapse locks the vertex it keeps, whose errors changed). No heap updates: about
    // half the time per collapse of the heap, which then orders the last collapses
    // exactly. Returns false when `step` asked to stop.
    bool collapse_in_passes(std::size_t until, std::size_t interval,
                            const std::function<bool(std::size_t)>& step);
    // Every vertex filed by its cheapest collapse, then the heap made in one pass (Floyd's).
    void fill_heap();
    void update_normal(std::uint32_t face);
    bool is_foot(std::uint32_t v) const { return position_[v].y <= foot_height_; }
    // The link condition and no tetrahedron collapse (closed meshes).
    bool topology_allows(std::uint32_t h) const;
    // Moving v to p (faces skip_a and skip_b, which a collapse removes, left out) keeps
    // every other triangle around v from turning its normal past the limit or becoming a
    // sliver; *volume_change gets the change of the enclosed volume.
    bool fan_allows(std::uint32_t v, const glm::dvec3& p, std::uint32_t skip_a,
                    std::uint32_t skip_b, double* volume_change) const;
    // A face as a change would leave it: its vertices and their positions, and its box.
    struct FaceShape {
        std::uint32_t face = 0;
        std::uint32_t id[3] = {0, 0, 0};
        CrossingTriangle t;
        glm::dvec3 lo, hi;
    };
    // Face `face` with vertex v as `becomes` at p (v = kNone: as it is).
    FaceShape shape(std::uint32_t face, std::uint32_t v = kNone, std::uint32_t becomes = kNone,
                    const glm::dvec3& p = glm::dvec3(0.0)) const;
    // The guard against crossings (CollapseSettings::keep_apart): every live face in grid_.
    void start_guard();
    void grid_place(std::uint32_t face);
    // grid_ lists `face` with the corners it has now.
    bool listed_as_now(std::uint32_t face) const;
    // Two faces cross, told by the corners they share.
    static bool shapes_cross(const FaceShape& a, const FaceShape& b);
    // No two of `faces` (faces of one piece) cross, nor any of them a listed face of that piece
    // near them but those in `faces` and `skip_a`, `skip_b` (faces a change removes or
    // replaces). Faces of other pieces may cross them.
    bool apart(std::span<const FaceShape> faces, std::uint32_t skip_a, std::uint32_t skip_b) const;
    // Moving v to p as `becomes` (collapsing h, which removes its two faces; kNone: a move)
    // makes no two faces of the piece cross.
    bool keeps_apart(std::uint32_t v, std::uint32_t becomes, const glm::dvec3& p,
                     std::uint32_t h) const;
    // The flip of h's edge to the other diagonal of its quad unfolds (unfold()).
    bool flip_unfolds(std::uint32_t h) const;
    void flip(std::uint32_t h);
    // v's piece stays above its volume floor after a change.
    bool keeps_volume(std::uint32_t v, double change) const;
    // Topology, foot, fan and volume: the collapse of h may go ahead.
    bool is_legal(std::uint32_t h, double* volume_change) const;
    // The error of collapsing h: the summed quadric at the kept vertex.
    float error(std::uint32_t h) const;
    // Files v in the heap by its cheapest collapse (by error alone, or the cheapest legal
    // one without lazy legality), or takes it out; with place = false only sets target_,
    // priority_ and verified_.
    void queue_vertex(std::uint32_t v, bool place = true);
    // v's cheapest legal collapse (kNone if none), its error and volume change.
    std::uint32_t best_legal(std::uint32_t v, float* best, double* volume_change) const;
    // Collapses h (v0 into v1) and leaves v0's old neighbours in support_.
    void collapse(std::uint32_t h, double volume_change);
    // After collapse(): v0 out of the heap, its old neighbours filed again.
    void requeue_after(std::uint32_t v0);

    // Heap of vertices by priority_ (smallest first); heap_position_ is kNone when out.
    void heap_up(std::size_t i);
    void heap_down(std::size_t i);
    void heap_remove(std::uint32_t v);
    void heap_place(std::uint32_t v);

    std::size_t part_count_ = 0, piece_count_ = 0;
    std::vector<glm::dvec3> position_;
    std::vector<std::uint32_t> part_;       // per vertex
    std::vector<std::uint32_t> corner_;     // per halfedge: the vertex it leaves
    std::vector<std::uint32_t> opposite_;   // per halfedge
    std::vector<std::uint32_t> outgoing_;   // per vertex: one halfedge leaving it, or kNone
    std::vector<std::uint8_t> face_alive_;  // per face
    std::size_t live_faces_ = 0;

    // Set by start().
    double min_cos_ = 0, min_cos2_ = 0, min_twice_area2_ = 0;
    float foot_height_ = -std::numeric_limits<float>::infinity();
    std::size_t min_foot_vertices_ = 6;
    bool lazy_ = true;
    bool passes_ = true;
    bool heap_filled_ = false;  // since start(): passes come before the heap
    bool keep_apart_ = true;
    bool guarding_ = false;  // grid_ lists the live faces; changes are checked against it
    FaceGrid grid_;
    std::vector<FaceShape> listed_;              // per face: as grid_ lists it
    std::size_t grid_faces_ = 0;                 // live faces when grid_ was made
    std::size_t guard_from_ = SIZE_MAX;          // live faces from which on the guard runs
    mutable std::vector<FaceShape> fan_;         // scratch of keeps_apart()
    mutable std::vector<std::uint32_t> in_fan_;  // scratch of apart(): faces of the change
    mutable std::uint32_t fan_stamp_ = 0;
    mutable bool crossing_ = false;  // is_legal() refused for a crossing
    CancelFlag cancel_ = nullptr;
    std::vector<glm::dvec3> normal_;  // per face, unit (or zero)
    std::vector<Quadric> quadric_;    // per vertex
    std::vector<std::uint32_t> piece_;
    std::vector<double> piece_volume_, piece_floor_;
    std::vector<std::size_t> foot_vertices_;  // per piece
    std::vector<double> own_error_;           // per vertex: its quadric at its position
    std::vector<std::uint32_t> target_;       // per vertex: its cheapest collapse
    std::vector<std::uint8_t> verified_;      // per vertex: target_ passed the legality tests
    std::vector<float> priority_;
    mutable std::vector<std::uint32_t> mark_;  // scratch of the link condition
    mutable std::uint32_t stamp_ = 0;
    std::vector<std::uint32_t> heap_position_;
    struct HeapEntry {
        float key;
        std::uint32_t vertex;
    };
    std::vector<HeapEntry> heap_;
    std::size_t collapses_ = 0;
    std::vector<std::uint32_t> support_;  // scratch: the neighbours of a collapsing vertex
};

// Collapses across meshes as if they were one (one heap over all of them, the cheapest
// collapse first) until at most `max_triangles` are left in all or none can collapse: the
// same order as one CollapseMesh of all their parts (but for equal errors), since no
// collapse in one changes another. Reducing each mesh alone first (in parallel) to at most
// `max_triangles`, then together, gives nearly that order too: a mesh's own collapses come in the
// same order, except where a collapse found illegal at the front is weighed against the other
// meshes' fronts. The bulk runs on a core per mesh: each collapses up to an error bound,
// which the shared order would all make before any collapse above it (ties and re-filed
// collapses aside); the last few dozen go one at a time. A part stops collapsing where
// one more collapse would take it below `part_floor` triangles; a part is one mesh, or with
// `part_of` (the part of each mesh) the meshes it names alike. Returns early once `cancel`
// is set (polled every 256 steps).
void collapse_together(std::span<CollapseMesh> meshes, std::size_t max_triangles,
                       CancelFlag cancel = nullptr, std::size_t part_floor = 0,
                       std::span<const std::size_t> part_of = {});

}  // namespace sylva
