#include "tree/organ_surfaces.h"

#include <array>
#include <cmath>
#include <numbers>

namespace sylva {
namespace {

constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;

// A closed body of revolution about +y: rings of `sides` vertices at heights y with radii r
// (the first and last ring may have radius 0: they become single pole vertices). `twist`
// turns every other ring by half a side, so the facets alternate like cone scales.
OrganSurface revolve(std::string_view name, std::string_view description, float size, int sides,
                     const std::vector<std::array<float, 2>>& rings, bool twist) {
    OrganSurface s{name, description, size, {}, {}, true};
    Mesh& m = s.mesh;
    std::vector<std::uint32_t> first;  // per ring: its first vertex
    std::vector<int> count;            // per ring: 1 (a pole) or sides
    for (std::size_t k = 0; k < rings.size(); ++k) {
        const auto [y, r] = rings[k];
        first.push_back(static_cast<std::uint32_t>(m.positions.size()));
        const float v = static_cast<float>(k) / static_cast<float>(rings.size() - 1);
        if (r == 0.0f) {
            m.positions.push_back({0.0f, y, 0.0f});
            s.uv.push_back({0.5f, v});
            count.push_back(1);
            continue;
        }
        const float offset = twist && k % 2 == 1 ? 0.5f : 0.0f;
        for (int i = 0; i < sides; ++i) {
            const float a = kTwoPi * (static_cast<float>(i) + offset) / static_cast<float>(sides);
            m.positions.push_back({r * std::cos(a), y, -r * std::sin(a)});
            s.uv.push_back({(static_cast<float>(i) + offset) / static_cast<float>(sides), v});
        }
        count.push_back(sides);
    }
    // Consecutive rings joined. Angles run from +x towards -z, which seen from outside
    // (from +x, say) goes right to left; going up and around, each triangle is listed so
    // that it turns counter-clockwise seen from outside.
    auto add = [&m](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        m.triangles.push_back({a, c, b});
    };
    for (std::size_t k = 0; k + 1 < rings.size(); ++k) {
        const std::uint32_t a = first[k], b = first[k + 1];
        const auto n = static_cast<std::uint32_t>(sides);
        if (count[k] == 1) {
            for (std::uint32_t i = 0; i < n; ++i) add(a, b + i, b + (i + 1) % n);
        } else if (count[k + 1] == 1) {
            for (std::uint32_t i = 0; i < n; ++i) add(a + i, b, a + (i + 1) % n);
        } else {
            const bool shifted = twist && (k + 1) % 2 == 1;  // ring k+1 sits half a side on
            for (std::uint32_t i = 0; i < n; ++i) {
                const std::uint32_t j = (i + 1) % n;
                if (shifted) {
                    add(a + i, b + i, a + j);
                    add(a + j, b + i, b + j);
                } else {
                    add(a + i, b + i, b + j);
                    add(a + i, b + j, a + j);
                }
            }
        }
    }
    return s;
}

// A five-petalled blossom facing +z: a star of petal tips and notches around a centre at
// y = 0.5, fanned (open, one-sided; the organ part's material is double-sided).
OrganSurface blossom() {
    OrganSurface s{"blossom", "a flat five-petalled blossom (fruit trees in spring)", 0.08f, {}, {},
                   false};
    Mesh& m = s.mesh;
    m.positions.push_back({0.0f, 0.5f, 0.0f});
    s.uv.push_back({0.5f, 0.5f});
    constexpr int kPoints = 10;
    for (int i = 0; i < kPoints; ++i) {
        const float a = kTwoPi * static_cast<float>(i) / kPoints;
        const float r = i % 2 == 0 ? 0.5f : 0.22f;
        m.positions.push_back({r * std::sin(a), 0.5f + r * std::cos(a), 0.0f});
        s.uv.push_back({0.5f + r * std::sin(a), 0.5f + r * std::cos(a)});
    }
    for (std::uint32_t i = 0; i < kPoints; ++i)
        m.triangles.push_back({0, 1 + (i + 1) % kPoints, 1 + i});
    return s;
}

const std::vector<OrganSurface>& surfaces() {
    static const std::vector<OrganSurface> all = [] {
        std::vector<OrganSurface> out;
        // An apple hangs from its stalk at the base: a flattened ball, dimpled where the
        // stalk enters (36 triangles).
        out.push_back(revolve(
            "apple", "an apple: a faceted ball, dimpled at the stalk", 0.14f, 6,
            {{0.08f, 0.0f}, {0.05f, 0.28f}, {0.3f, 0.5f}, {0.72f, 0.46f}, {1.0f, 0.0f}}, false));
        out.back().hangs = true;
        // A conifer cone: a spindle of staggered scales from a short stalk (42 triangles).
        out.push_back(revolve("cone", "a conifer cone: a spindle of staggered scales", 0.16f, 6,
                              {{0.0f, 0.0f},
                               {0.12f, 0.16f},
                               {0.35f, 0.22f},
                               {0.6f, 0.2f},
                               {0.82f, 0.13f},
                               {1.0f, 0.0f}},
                              true));
        // A berry or a cherry: a small faceted ball (24 triangles).
        out.push_back(revolve("berry", "a berry or cherry: a small faceted ball", 0.05f, 6,
                              {{0.0f, 0.0f}, {0.25f, 0.45f}, {0.75f, 0.45f}, {1.0f, 0.0f}}, false));
        out.back().hangs = true;
        out.push_back(blossom());
        return out;
    }();
    return all;
}

}  // namespace

const OrganSurface* find_organ_surface(std::string_view name) {
    for (const OrganSurface& s : surfaces())
        if (s.name == name) return &s;
    return nullptr;
}

std::vector<std::string> organ_surface_names() {
    std::vector<std::string> names;
    for (const OrganSurface& s : surfaces()) names.emplace_back(s.name);
    return names;
}

}  // namespace sylva
