// Closed, outward-oriented meshes built by hand for the quality tests.
#pragma once

#include <array>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <map>
#include <utility>
#include <vector>

#include "core/mesh.h"

namespace sylva::test {

// Appends `b` to `a` (indices shifted, nothing welded).
inline void append(Mesh& a, const Mesh& b) {
    const auto offset = static_cast<std::uint32_t>(a.positions.size());
    a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
    for (const auto& t : b.triangles)
        a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
}

// The axis-aligned box from `low` to `high`: 8 vertices, 12 triangles.
inline Mesh box(glm::vec3 low, glm::vec3 high) {
    Mesh m;
    for (int i = 0; i < 8; ++i)
        m.positions.push_back(
            {i & 1 ? high.x : low.x, i & 2 ? high.y : low.y, i & 4 ? high.z : low.z});
    // Each face as a quad, counter-clockwise seen from outside.
    const std::uint32_t quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (const auto& q : quads) {
        m.triangles.push_back({q[0], q[1], q[2]});
        m.triangles.push_back({q[0], q[2], q[3]});
    }
    return m;
}

inline Mesh octahedron() {
    Mesh m;
    m.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                   {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    return m;
}

// The icosahedron subdivided `levels` times, on the unit sphere.
inline Mesh icosphere(int levels) {
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    Mesh m;
    m.positions = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                   {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                   {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                   {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                   {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (glm::vec3& p : m.positions) p = glm::normalize(p);
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> middle;
        const auto mid = [&](std::uint32_t a, std::uint32_t b) {
            const auto key = std::minmax(a, b);
            auto [it, added] = middle.try_emplace(key, 0);
            if (added) {
                it->second = static_cast<std::uint32_t>(m.positions.size());
                m.positions.push_back(glm::normalize(m.positions[a] + m.positions[b]));
            }
            return it->second;
        };
        std::vector<std::array<std::uint32_t, 3>> finer;
        for (const auto& [a, b, c] : m.triangles) {
            const std::uint32_t ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
            finer.push_back({a, ab, ca});
            finer.push_back({b, bc, ab});
            finer.push_back({c, ca, bc});
            finer.push_back({ab, bc, ca});
        }
        m.triangles = std::move(finer);
    }
    return m;
}

// The polygon (counter-clockwise in x, z seen from above) extruded from y = 0 to `height`;
// caps fanned from the polygon's corner `hub`, which must see every other corner.
inline Mesh prism(const std::vector<glm::vec2>& polygon, float height, std::uint32_t hub = 0) {
    Mesh m;
    const auto n = static_cast<std::uint32_t>(polygon.size());
    for (const glm::vec2& p : polygon) m.positions.push_back({p.x, 0.0f, p.y});
    for (const glm::vec2& p : polygon) m.positions.push_back({p.x, height, p.y});
    // Counter-clockwise in (x, z) is clockwise seen from +y, so the top cap reverses it.
    for (std::uint32_t k = 1; k + 1 < n; ++k) {
        const std::uint32_t a = (hub + k) % n, b = (hub + k + 1) % n;
        m.triangles.push_back({hub, a, b});
        m.triangles.push_back({n + hub, n + b, n + a});
    }
    for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t j = (i + 1) % n;
        m.triangles.push_back({i, n + i, n + j});
        m.triangles.push_back({i, n + j, j});
    }
    return m;
}

inline Mesh flipped(Mesh m) {
    for (auto& t : m.triangles) std::swap(t[1], t[2]);
    return m;
}

}  // namespace sylva::test
