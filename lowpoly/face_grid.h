// A uniform hash grid of triangles' bounding boxes: which faces of a mesh lie near a box.
// The reduction's guard against self-intersections asks it for the faces near each collapse
// (CollapseMesh, lowpoly/quadric_collapse.h), and updates it as collapses change faces.
//
// Each face is listed in every cell its box overlaps; a face overlapping more than
// kMaxFaceCells cells is kept in one list that every query visits. Not thread-safe: one grid
// per mesh, used by the thread that reduces it.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <unordered_map>
#include <vector>

namespace sylva {

class FaceGrid {
  public:
    static constexpr std::int64_t kMaxFaceCells = 512;

    // Empties the grid for faces 0..faces-1 and cells of edge `cell` (> 0).
    void reset(double cell, std::size_t faces);
    bool empty() const { return range_.empty(); }
    // Lists `face` with its box (lo, hi) in the cells the box overlaps, or moves it there.
    void place(std::uint32_t face, const glm::dvec3& lo, const glm::dvec3& hi);
    void remove(std::uint32_t face);
    // Calls visit(face) once for each listed face whose box meets the box (lo, hi). The
    // boxes are kept in the cells, so faces far from it cost a comparison in memory read in
    // order.
    template <typename Visit>
    void near(const glm::dvec3& lo, const glm::dvec3& hi, const Visit& visit) const {
        if (++stamp_ == 0) {
            std::fill(seen_.begin(), seen_.end(), 0);
            stamp_ = 1;
        }
        const auto once = [&](const Entry& e) {
            if (!e.meets(lo, hi) || seen_[e.face] == stamp_) return;
            seen_[e.face] = stamp_;
            visit(e.face);
        };
        for (const Entry& e : large_) once(e);
        const Range r = range_of(lo, hi);
        if (r.cells() > kMaxFaceCells) {  // a box as large as that: every face
            for (const auto& [key, entries] : cells_)
                for (const Entry& e : entries) once(e);
            return;
        }
        for (std::int64_t x = r.lo[0]; x <= r.hi[0]; ++x)
            for (std::int64_t y = r.lo[1]; y <= r.hi[1]; ++y)
                for (std::int64_t z = r.lo[2]; z <= r.hi[2]; ++z) {
                    const auto cell = cells_.find(key(x, y, z));
                    if (cell == cells_.end()) continue;
                    for (const Entry& e : cell->second) once(e);
                }
    }

  private:
    struct Entry {
        std::uint32_t face;
        glm::dvec3 lo, hi;
        bool meets(const glm::dvec3& l, const glm::dvec3& h) const {
            return lo.x <= h.x && l.x <= hi.x && lo.y <= h.y && l.y <= hi.y && lo.z <= h.z &&
                   l.z <= hi.z;
        }
    };
    struct Range {
        std::int32_t lo[3] = {0, 0, 0}, hi[3] = {-1, -1, -1};  // empty: not listed
        bool listed() const { return lo[0] <= hi[0]; }
        std::int64_t cells() const {
            return std::int64_t{hi[0] - lo[0] + 1} * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1);
        }
    };
    Range range_of(const glm::dvec3& lo, const glm::dvec3& hi) const;
    static std::uint64_t key(std::int64_t x, std::int64_t y, std::int64_t z);

    double inverse_cell_ = 1.0;
    std::unordered_map<std::uint64_t, std::vector<Entry>> cells_;
    std::vector<Range> range_;  // per face
    std::vector<std::uint8_t> large_flag_;
    std::vector<Entry> large_;
    std::vector<std::uint32_t> placed_;  // faces placed since reset() (repeats allowed)
    mutable std::vector<std::uint32_t> seen_;
    mutable std::uint32_t stamp_ = 0;
};

}  // namespace sylva
