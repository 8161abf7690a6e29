// Points hashed into cubic cells of one size: which stored points may lie within `cell` of
// a query (the 27 cells around it). What the near-duplicate merges (cone_field.h,
// sphere_field.h) and the crown's close pairs (tree/crown_merge.cpp) look up.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/vec3.hpp>
#include <unordered_map>
#include <vector>

namespace sylva {

class PointHash {
  public:
    // cell > 0; a query finds every stored point within `cell` of it (and some farther).
    explicit PointHash(float cell) : cell_(cell) {}

    void insert(const glm::vec3& p, std::uint32_t id) { cells_[key(p, 0, 0, 0)].push_back(id); }

    // f(id) for every id stored in the 27 cells around p, each cell once.
    template <class F>
    void for_each_near(const glm::vec3& p, F&& f) const {
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    auto found = cells_.find(key(p, dx, dy, dz));
                    if (found == cells_.end()) continue;
                    for (std::uint32_t id : found->second) f(id);
                }
    }

  private:
    // Cell coordinates in double and clamped, so far or non-finite points stay defined (they
    // share the outermost cells: slower, never wrong, as a query checks real distances).
    std::uint64_t key(const glm::vec3& p, int dx, int dy, int dz) const {
        const int offset[3] = {dx, dy, dz};
        std::uint64_t k = 0;
        for (int i = 0; i < 3; ++i) {
            double c = std::floor(double(p[i]) / double(cell_));
            c = std::isnan(c) ? 0.0 : std::clamp(c, -1e6, 1e6) + offset[i];
            k = k << 21 | (static_cast<std::uint64_t>(static_cast<std::int64_t>(c)) & 0x1fffff);
        }
        return k;
    }

    float cell_;
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
};

}  // namespace sylva
