#include "lowpoly/face_grid.h"

#include <algorithm>
#include <cmath>

namespace sylva {
namespace {

// Cell coordinates are kept within 21 bits each (a million cells a side) for the key.
constexpr std::int64_t kReach = (std::int64_t{1} << 20) - 1;

std::int64_t cell_of(double x) {
    const double c = std::floor(x);
    if (!(c > -static_cast<double>(kReach))) return -kReach;  // NaN too
    if (!(c < static_cast<double>(kReach))) return kReach;
    return static_cast<std::int64_t>(c);
}

}  // namespace

void FaceGrid::reset(double cell, std::size_t faces) {
    inverse_cell_ = 1.0 / cell;
    cells_.clear();
    large_.clear();
    if (range_.size() != faces) {
        range_.assign(faces, Range{});
        large_flag_.assign(faces, 0);
        seen_.assign(faces, 0);
        stamp_ = 0;
    } else {  // the same faces again: only those placed since need clearing
        for (std::uint32_t f : placed_) {
            range_[f] = Range{};
            large_flag_[f] = 0;
        }
    }
    placed_.clear();
}

std::uint64_t FaceGrid::key(std::int64_t x, std::int64_t y, std::int64_t z) {
    const auto field = [](std::int64_t v) { return static_cast<std::uint64_t>(v + kReach); };
    return field(x) << 42 | field(y) << 21 | field(z);
}

FaceGrid::Range FaceGrid::range_of(const glm::dvec3& lo, const glm::dvec3& hi) const {
    Range r;
    for (int k = 0; k < 3; ++k) {
        r.lo[k] = static_cast<std::int32_t>(cell_of(lo[k] * inverse_cell_));
        r.hi[k] = static_cast<std::int32_t>(cell_of(hi[k] * inverse_cell_));
    }
    return r;
}

void FaceGrid::place(std::uint32_t face, const glm::dvec3& lo, const glm::dvec3& hi) {
    remove(face);
    placed_.push_back(face);
    const Entry entry{face, lo, hi};
    const Range r = range_of(lo, hi);
    if (r.cells() > kMaxFaceCells) {
        large_flag_[face] = 1;
        large_.push_back(entry);
        return;
    }
    range_[face] = r;
    for (std::int64_t x = r.lo[0]; x <= r.hi[0]; ++x)
        for (std::int64_t y = r.lo[1]; y <= r.hi[1]; ++y)
            for (std::int64_t z = r.lo[2]; z <= r.hi[2]; ++z) cells_[key(x, y, z)].push_back(entry);
}

void FaceGrid::remove(std::uint32_t face) {
    const auto drop = [face](std::vector<Entry>& entries) {
        const auto at = std::find_if(entries.begin(), entries.end(),
                                     [face](const Entry& e) { return e.face == face; });
        *at = entries.back();
        entries.pop_back();
    };
    if (large_flag_[face]) {
        large_flag_[face] = 0;
        drop(large_);
        return;
    }
    const Range r = range_[face];
    if (!r.listed()) return;
    for (std::int64_t x = r.lo[0]; x <= r.hi[0]; ++x)
        for (std::int64_t y = r.lo[1]; y <= r.hi[1]; ++y)
            for (std::int64_t z = r.lo[2]; z <= r.hi[2]; ++z) drop(cells_[key(x, y, z)]);
    range_[face] = Range{};
}

}  // namespace sylva
