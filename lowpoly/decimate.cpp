#include "lowpoly/decimate.h"

#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_group.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <glm/common.hpp>
#include <limits>
#include <numeric>

#include "core/errors.h"
#include "core/mesh_checks.h"
#include "lowpoly/handle_cutting.h"
#include "lowpoly/merge_meshes.h"
#include "lowpoly/quadric_collapse.h"

namespace sylva {
namespace {

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

// One CollapseMesh per part (built in parallel; each part is reduced on its own thread
// first, see reduce()); throws InputError naming the first part that is not a closed
// 2-manifold (zero-area triangles are fine, as check_topology says: marching cubes on a
// very fine grid makes some, and they are the first collapses).
using PartMeshes = std::vector<CollapseMesh>;

PartMeshes build_checked(std::span<const Mesh* const> parts, std::span<const std::size_t> part_of) {
    PartMeshes meshes(parts.size());
    std::vector<std::uint8_t> built(parts.size(), 0);
    tbb::parallel_for(std::size_t{0}, parts.size(), [&](std::size_t k) {
        const Mesh* one[] = {parts[k]};
        built[k] = meshes[k].build(one);
    });
    for (std::size_t bad = 0; bad < parts.size(); ++bad) {
        if (built[bad]) continue;
        std::string what = describe(check_topology(*parts[bad]));
        if (what.empty()) what = "a triangle with a repeated vertex";
        throw InputError("decimate: part " + std::to_string(part_of[bad]) +
                         " is not a closed 2-manifold (" + what + ")");
    }
    return meshes;
}

std::size_t triangles_in(const PartMeshes& meshes) {
    std::size_t n = 0;
    for (const CollapseMesh& m : meshes) n += m.triangles();
    return n;
}

std::vector<Mesh> extract(const PartMeshes& meshes) {
    std::vector<Mesh> parts;
    for (const CollapseMesh& m : meshes) parts.push_back(std::move(m.extract().front()));
    return parts;
}

struct Reduction {
    std::vector<Mesh> parts;
    // The parts on the way down, at the snapshot count, before relocation (empty unless
    // asked for).
    std::vector<Mesh> snapshot;
};

// How far a lane (half a part, Lanes below) goes alone: down to its share of what its part
// may keep, times this. For the budget half as much again, so that the shared order has
// collapses of both lanes to choose from; for handle cutting's intermediate count, which
// the reduction after the cuts shares by error again, its share. Whole parts go alone down
// to what all parts may keep and share by error: a part reduced by its size (a crown of a
// few hulls beside a trunk of 10k triangles) could not get its triangles back.
constexpr double kLaneSlack = 1.5;
constexpr double kIntermediateLaneSlack = 1.0;

// One reduction from scratch down to `target` triangles; with snapshot_at > target, also
// the parts as they were at snapshot_at triangles (the start of handle cutting, which then
// needs no reduction of its own). The parts share the budget as one mesh would (one order
// of collapses by error, collapse_together()); the bulk of it, each part down to what all
// parts together may keep (a lane: lane_slack), runs on a thread per part or lane (the
// calling thread takes the first and reports progress).
Reduction reduce(PartMeshes meshes, std::size_t target, std::size_t snapshot_at,
                 const DecimateSettings& settings, std::span<const double> min_twice_area,
                 std::span<const std::size_t> part_of, double lane_slack) {
    CollapseSettings cs;
    cs.max_normal_turn_degrees = settings.max_normal_turn_degrees;
    cs.foot_height = settings.foot_height;
    cs.min_foot_vertices = kMinFootVertices;
    cs.lazy_legality = settings.lazy_legality;
    cs.passes = settings.fast_passes;
    cs.keep_apart = settings.keep_apart;
    const std::size_t alone = std::max(target, snapshot_at);
    std::vector<std::size_t> in_part(meshes.size(), 0);
    for (std::size_t k = 0; k < meshes.size(); ++k) in_part[part_of[k]] += meshes[k].triangles();
    auto alone_for = [&](std::size_t k) {
        const std::size_t n = meshes[k].triangles(), of_part = in_part[part_of[k]];
        if (n == of_part) return alone;
        return static_cast<std::size_t>(
            std::ceil(lane_slack * static_cast<double>(alone) * static_cast<double>(n) /
                      static_cast<double>(of_part)));
    };
    const std::size_t first = meshes.empty() ? 0 : meshes[0].triangles();
    const std::size_t expected = first > alone ? (first - alone) / 2 : 0;
    const std::size_t interval = std::max<std::size_t>(expected / 100, 64);
    auto reported = [&](std::size_t done) {
        if (settings.progress)
            settings.progress(0.9f * std::min(1.0f, static_cast<float>(done) /
                                                        std::max<std::size_t>(expected, 1)));
        return !is_cancelled(settings.cancel);
    };
    auto polled = [&](std::size_t) { return !is_cancelled(settings.cancel); };
    std::vector<std::exception_ptr> errors(meshes.size());
    auto reduce_alone = [&](std::size_t k) {
        try {
            CollapseSettings own = cs;
            own.min_twice_area = min_twice_area[k];
            meshes[k].start(own, settings.cancel);
            if (k == 0)
                meshes[k].collapse_to(alone_for(k), interval, reported);
            else
                meshes[k].collapse_to(alone_for(k), 256, polled);
        } catch (...) {
            errors[k] = std::current_exception();
        }
    };
    tbb::task_group others;
    for (std::size_t k = 1; k < meshes.size(); ++k)
        others.run([&reduce_alone, k] { reduce_alone(k); });
    if (!meshes.empty()) reduce_alone(0);
    others.wait();
    for (const std::exception_ptr& error : errors)
        if (error) std::rethrow_exception(error);
    throw_if_cancelled(settings.cancel);
    Reduction out;
    if (snapshot_at > target) {
        collapse_together(meshes, snapshot_at, settings.cancel, settings.part_floor, part_of);
        throw_if_cancelled(settings.cancel);
        out.snapshot = extract(meshes);
    }
    collapse_together(meshes, target, settings.cancel, settings.part_floor, part_of);
    throw_if_cancelled(settings.cancel);
    tbb::parallel_for(std::size_t{0}, meshes.size(), [&](std::size_t k) {
        if (settings.relocate_vertices) meshes[k].relocate();
        if (settings.unfold) meshes[k].unfold();
    });
    throw_if_cancelled(settings.cancel);
    if (settings.progress) settings.progress(1.0f);
    out.parts = extract(meshes);
    return out;
}

// Why a reduction of `input` is not acceptable (empty when it is): a part vanished, is not
// a closed 2-manifold, or has more inside-out pieces than the input had.
std::string broken(const std::vector<Mesh>& reduced, std::span<const Mesh* const> input,
                   std::span<const std::size_t> part_of) {
    // Each part checked on a core of its own; the first part's reason wins.
    std::vector<std::string> why(reduced.size());
    tbb::parallel_for(std::size_t{0}, reduced.size(), [&](std::size_t k) {
        if (reduced[k].triangles.empty() != input[k]->triangles.empty()) {
            why[k] = "part " + std::to_string(part_of[k]) + " vanished";
            return;
        }
        if (reduced[k].triangles.empty()) return;
        const MeshTopology t = check_topology(reduced[k]);
        if (!t.is_closed_manifold()) {
            why[k] = "part " + std::to_string(part_of[k]) + " had " + describe(t);
            return;
        }
        // Slivers the input had may stay (the collapses take them first); new ones may not.
        if (t.zero_area_triangles > 0 &&
            t.zero_area_triangles > check_topology(*input[k]).zero_area_triangles) {
            why[k] = "part " + std::to_string(part_of[k]) + " had " +
                     std::to_string(t.zero_area_triangles) + " zero-area triangles";
            return;
        }
        // Collapses guard each triangle's turn, but a small piece can still fold through
        // itself and come out inside out: closed, yet with no volume. (An inner shell, the
        // wall of a hollow, is inward by nature: count only new ones. The input's are
        // counted only then: most reductions have none, and the input is the larger mesh.)
        const std::size_t inward = inward_pieces(reduced[k]);
        if (inward > 0 && inward > inward_pieces(*input[k]))
            why[k] = "part " + std::to_string(part_of[k]) + " had an inside-out piece";
    });
    for (std::string& w : why)
        if (!w.empty()) return std::move(w);
    return {};
}

// Reduction with the safety net: a result that fails check_topology is redone with fewer
// collapses, down to returning the input. With
// snapshot_at > 0, *snapshot gets the parts at that many triangles (or the input, if it has
// no more), unchecked: most reductions never need it.
DecimateResult reduce_with_backoff(PartMeshes meshes, std::span<const Mesh* const> parts,
                                   std::span<const std::size_t> part_of,
                                   const DecimateSettings& settings,
                                   std::span<const double> min_twice_area,
                                   std::size_t snapshot_at = 0,
                                   std::vector<Mesh>* snapshot = nullptr,
                                   double lane_slack = kLaneSlack) {
    DecimateResult result;
    const std::size_t input_triangles = triangles_in(meshes);
    auto copy_input = [&] {
        result.parts.clear();
        for (const Mesh* m : parts) result.parts.push_back(*m);
    };
    std::size_t target = settings.max_triangles;
    constexpr int kMaxAttempts = 6;
    if (input_triangles <= target) {
        copy_input();
        if (snapshot) *snapshot = result.parts;
    } else {
        for (int attempt = 0;; ++attempt) {
            // The built mesh serves the first attempt; a retry (never seen) builds it again.
            Reduction r = reduce(attempt == 0 ? std::move(meshes) : build_checked(parts, part_of),
                                 target, attempt == 0 && snapshot ? snapshot_at : 0, settings,
                                 min_twice_area, part_of, lane_slack);
            result.parts = std::move(r.parts);
            throw_if_cancelled(settings.cancel);
            if (attempt == 0 && snapshot) *snapshot = std::move(r.snapshot);
            const std::string why = broken(result.parts, parts, part_of);
            if (why.empty()) break;
            ++result.backoffs;
            // Fewer collapses: halfway back towards the input each time.
            target += (input_triangles - target + 1) / 2;
            if (attempt + 1 >= kMaxAttempts || target >= input_triangles) {
                copy_input();
                result.note =
                    "reduction broke the mesh (" + why + "); returned the input unreduced";
                break;
            }
            result.note = "reduction to fewer triangles broke the mesh (" + why +
                          "); backed off to " + std::to_string(target) + " triangles";
        }
    }
    result.triangles = count_triangles(result.parts);
    result.within_budget = result.triangles <= settings.max_triangles;
    return result;
}

// The same from meshes (handle cutting's output).
DecimateResult reduce_with_backoff(const std::vector<Mesh>& meshes,
                                   std::span<const std::size_t> part_of,
                                   const DecimateSettings& settings,
                                   std::span<const double> min_twice_area) {
    std::vector<const Mesh*> pointers;
    for (const Mesh& m : meshes) pointers.push_back(&m);
    return reduce_with_backoff(build_checked(pointers, part_of), pointers, part_of, settings,
                               min_twice_area);
}

// decimate() on the lanes (Lanes): `parts` are the meshes reduced, each of part part_of[k].
DecimateResult decimate_lanes(std::span<const Mesh* const> parts,
                              std::span<const std::size_t> part_of,
                              const DecimateSettings& settings) {
    PartMeshes input = build_checked(parts, part_of);
    // Well above check_topology's zero-area threshold (2e-12 of the squared diagonal), per
    // part (its lanes together): a small part far from a big one (a crown at the end of a
    // 3 km branch) keeps the collapses its own size allows.
    std::vector<double> min_twice_area(parts.size());
    for (std::size_t k = 0; k < parts.size(); ++k) {
        std::vector<const Mesh*> of_part;
        for (std::size_t j = 0; j < parts.size(); ++j)
            if (part_of[j] == part_of[k]) of_part.push_back(parts[j]);
        min_twice_area[k] = 1e-9 * bounding_diagonal_squared(of_part);
    }
    throw_if_cancelled(settings.cancel);
    // Handles and pieces set a floor no collapse goes below. When it is above the budget
    // a direct reduction is wasted work (the slowest part of a crossing-branch tree): go
    // straight to the intermediate one and cut handles there. Otherwise, when the floor is
    // above two thirds of the budget, the direct reduction keeps a snapshot at the
    // intermediate count on its way down, in case the handles pin more than the floor says.
    std::size_t floor = 0;
    for (const CollapseMesh& m : input) floor += m.triangle_floor();
    const bool handles_pin = settings.cut_handles && floor > settings.max_triangles;
    // Where handles are cut: the parts still have detail there (a few times the floor), so
    // the final reduction can still share the budget well between the parts.
    const std::size_t intermediate = 4 * std::max(settings.max_triangles, floor);
    DecimateResult result;
    std::vector<Mesh> snapshot;
    // The snapshot holds the parts' own reductions at the intermediate count, so the passes
    // stop at twice that and the heap does the rest (6,400 -> 800 at 800 triangles): kept
    // only where the handles' floor is above two thirds of the budget. Below, a missed budget
    // reduces to the intermediate afresh (never seen: 347 reductions of 14 templates x 6
    // seeds x budgets 300-3000 missed only with floors at 72-99% of the budget).
    const bool keep_snapshot = settings.cut_handles && 3 * floor > 2 * settings.max_triangles;
    if (!handles_pin)
        result = reduce_with_backoff(std::move(input), parts, part_of, settings, min_twice_area,
                                     keep_snapshot ? intermediate : 0, &snapshot);

    // Over budget at the floor: handles pin the remaining triangles. Cut them, shortest
    // loops first, then reduce the cut parts to the budget; repeat while it helps.
    if (handles_pin || (!result.within_budget && settings.cut_handles && result.backoffs == 0)) {
        // Progress already reached 1 (or belongs to the reduction below); the passes after
        // it only poll the cancel flag.
        DecimateSettings quiet = settings;
        quiet.progress = nullptr;
        DecimateResult detailed;
        if (handles_pin || snapshot.empty() || !broken(snapshot, parts, part_of).empty()) {
            DecimateSettings to_intermediate = handles_pin ? settings : quiet;
            to_intermediate.max_triangles = intermediate;
            // Unrelocated like the snapshot: the vertices stay on the input surface.
            to_intermediate.relocate_vertices = false;
            detailed = reduce_with_backoff(
                handles_pin ? std::move(input) : build_checked(parts, part_of), parts, part_of,
                to_intermediate, min_twice_area, 0, nullptr, kIntermediateLaneSlack);
        } else {
            detailed.parts = std::move(snapshot);
            detailed.triangles = count_triangles(detailed.parts);
        }
        if (handles_pin) {
            result = detailed;  // the best so far, measured against the real budget
            result.within_budget = result.triangles <= settings.max_triangles;
        }
        std::vector<Mesh> cut = std::move(detailed.parts);
        int handles_cut = 0;
        // A budget below what the handles allow leaves the cut parts no room to keep apart:
        // the guard there only refuses collapses (and its relaxed end broke pieces, which the
        // back-off then undid); their crossings are still counted and said.
        DecimateSettings cut_reduction = quiet;
        cut_reduction.keep_apart = false;
        for (int round = 0; round < 8 && !result.within_budget && detailed.backoffs == 0; ++round) {
            throw_if_cancelled(settings.cancel);
            // The parts share no vertex: each is measured and cut on a core of its own.
            std::vector<std::size_t> genera(cut.size(), 0);
            tbb::parallel_for(std::size_t{0}, cut.size(), [&](std::size_t k) {
                if (!cut[k].triangles.empty()) genera[k] = genus(cut[k]);
            });
            const std::size_t total_genus =
                std::accumulate(genera.begin(), genera.end(), std::size_t{0});
            if (total_genus == 0) break;
            // A handle pins about a dozen triangles at the floor.
            const std::size_t wanted = std::clamp<std::size_t>(
                (result.triangles - settings.max_triangles + 7) / 8, 1, total_genus);
            std::vector<std::size_t> cuts(cut.size(), 0);
            tbb::parallel_for(std::size_t{0}, cut.size(), [&](std::size_t k) {
                const std::size_t share = (wanted * genera[k] + total_genus - 1) / total_genus;
                if (share > 0) cuts[k] = cut_handles(cut[k], share, settings.cancel);
            });
            const std::size_t done = std::accumulate(cuts.begin(), cuts.end(), std::size_t{0});
            if (done == 0) break;
            handles_cut += static_cast<int>(done);
            DecimateResult again = reduce_with_backoff(cut, part_of, cut_reduction, min_twice_area);
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
    // Counted once, on what is returned (the reductions on the way may be several).
    if (settings.count_crossings) {
        std::vector<std::size_t> crossing(result.parts.size(), 0);
        tbb::parallel_for(std::size_t{0}, result.parts.size(), [&](std::size_t k) {
            const Mesh* one[] = {&result.parts[k]};
            CollapseMesh m;
            if (!result.parts[k].triangles.empty() && m.build(one))
                crossing[k] = m.crossing_pairs();
        });
        result.crossing_pairs = std::accumulate(crossing.begin(), crossing.end(), std::size_t{0});
    }
    if (result.crossing_pairs > 0)
        result.note += std::string(result.note.empty() ? "" : "; ") +
                       std::to_string(result.crossing_pairs) +
                       " pairs of faces cross inside a piece: the budget left no collapse that "
                       "keeps them apart (parts closer together than a facet)";
    return result;
}

// What a reduction works on: the parts, but a part with more than half of all triangles
// (a trunk beside a small crown, or alone) in two lanes, its connected components dealt so
// that one lane has half of all triangles and the other the rest of the part, reduced with
// the other parts on the other core; collapse_together() keeps both lanes one part for the
// part floor, and they are merged back at the end. Always two lanes, not one per core: the
// same input gives the same output on every machine. A game mesh's trunk comes in pieces
// for this (tree/trunk_pieces.h).
struct Lanes {
    std::vector<Mesh> split;           // the split part's two lanes, if any
    std::vector<const Mesh*> meshes;   // a part or a lane of one, in part order
    std::vector<std::size_t> part_of;  // the part of each
};

Lanes lanes_for(std::span<const Mesh* const> parts) {
    std::size_t total = 0;
    for (const Mesh* m : parts) total += m->triangles.size();
    Lanes lanes;
    for (std::size_t k = 0; k < parts.size(); ++k) {
        const Mesh& part = *parts[k];
        const std::size_t n = part.triangles.size();
        if (lanes.split.empty() && n >= kLaneSplitTriangles && 2 * n > total) {
            std::size_t components = 0;
            std::vector<std::uint32_t> label = component_of_triangles(part, components);
            std::vector<std::size_t> size(components, 0);
            for (std::uint32_t c : label) ++size[c];
            // Largest first, into lane 0 while it stays within half of all triangles.
            std::vector<std::uint32_t> order(components);
            std::iota(order.begin(), order.end(), 0u);
            std::stable_sort(order.begin(), order.end(),
                             [&](std::uint32_t a, std::uint32_t b) { return size[a] > size[b]; });
            std::vector<std::uint32_t> lane(components, 1);
            std::size_t first = 0;
            for (std::uint32_t c : order)
                if (2 * (first + size[c]) <= total + total / 16) {
                    lane[c] = 0;
                    first += size[c];
                }
            // Worth it when the busier core then has at most 85% of the part.
            const std::size_t busier = std::max(first, total - first);
            if (first > 0 && first < n && 20 * busier <= 17 * n) {
                for (std::uint32_t& l : label) l = lane[l];
                lanes.split = split_by_label(part, label, 2);
                for (const Mesh& m : lanes.split) {
                    lanes.meshes.push_back(&m);
                    lanes.part_of.push_back(k);
                }
                continue;
            }
        }
        lanes.meshes.push_back(&part);
        lanes.part_of.push_back(k);
    }
    return lanes;
}

// The reduced lanes as the parts they are of.
std::vector<Mesh> merge_lanes(std::vector<Mesh> reduced, std::span<const std::size_t> part_of,
                              std::size_t parts) {
    if (reduced.size() == parts) return reduced;  // no part was split
    std::vector<Mesh> out(parts);
    for (std::size_t p = 0; p < parts; ++p) {
        std::vector<const Mesh*> of;
        for (std::size_t k = 0; k < reduced.size(); ++k)
            if (part_of[k] == p) of.push_back(&reduced[k]);
        out[p] = merge_meshes(of);
    }
    return out;
}

}  // namespace

DecimateResult decimate(std::span<const Mesh* const> parts, const DecimateSettings& settings) {
    const Lanes lanes = lanes_for(parts);
    DecimateResult result = decimate_lanes(lanes.meshes, lanes.part_of, settings);
    result.parts = merge_lanes(std::move(result.parts), lanes.part_of, parts.size());
    return result;
}

DecimateResult decimate(const Mesh& mesh, const DecimateSettings& settings) {
    const Mesh* parts[] = {&mesh};
    return decimate(parts, settings);
}

}  // namespace sylva
