#include "tree/organs.h"

#include <algorithm>
#include <bit>
#include <glm/geometric.hpp>
#include <numeric>
#include <string>

#include "core/errors.h"
#include "tree/organ_surfaces.h"

namespace sylva {
namespace {

void end_organ(OrganMesh& out, bool polygon) {
    out.first_vertex.push_back(static_cast<std::uint32_t>(out.mesh.positions.size()));
    out.first_triangle.push_back(static_cast<std::uint32_t>(out.mesh.triangles.size()));
    out.polygon.push_back(polygon ? 1 : 0);
}

void add_surface(OrganMesh& out, const Organ& organ, const OrganSurface& surface) {
    const float size = (organ.size > 0.0f ? organ.size : surface.size) * organ.scale;
    // Right, heading, up: a right-handed frame (U = H x L), so surfaces keep their winding.
    glm::vec3 heading = organ.heading, left = organ.left;
    if (surface.hangs) {
        // Straight down, turned about the vertical as the turtle's left says.
        heading = glm::vec3(0.0f, -1.0f, 0.0f);
        glm::vec3 l(left.x, 0.0f, left.z);
        if (glm::length(l) < 1e-4f) l = glm::vec3(organ.up.x, 0.0f, organ.up.z);
        left = glm::length(l) < 1e-4f ? glm::vec3(-1.0f, 0.0f, 0.0f) : glm::normalize(l);
    }
    const glm::vec3 up = glm::cross(heading, left);
    const glm::vec3 x = -left * size, y = heading * size, z = up * size;
    const auto first = static_cast<std::uint32_t>(out.mesh.positions.size());
    for (std::size_t v = 0; v < surface.mesh.positions.size(); ++v) {
        const glm::vec3& p = surface.mesh.positions[v];
        out.mesh.positions.push_back(organ.position + p.x * x + p.y * y + p.z * z);
        out.uv.push_back(surface.uv[v]);
        out.color.push_back(organ.color);
    }
    for (const auto& t : surface.mesh.triangles)
        out.mesh.triangles.push_back({first + t[0], first + t[1], first + t[2]});
    end_organ(out, false);
}

// A polygon fanned from its first vertex, with a card's UVs: v from the first vertex (0) to
// the farthest (1), u across in the polygon's plane (0.5 on that axis).
void add_polygon(OrganMesh& out, const std::vector<glm::vec3>& polygon, int color) {
    const glm::vec3 base = polygon.front();
    glm::vec3 along(0.0f, 1.0f, 0.0f), normal(0.0f);
    float length = 0.0f;
    for (const glm::vec3& p : polygon)
        if (const float d = glm::distance(p, base); d > length) length = d, along = (p - base) / d;
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
        normal += glm::cross(polygon[i] - base, polygon[i + 1] - base);
    glm::vec3 across = glm::cross(normal, along);
    const float n = glm::length(across);
    across = n > 0.0f ? across / n : glm::vec3(1.0f, 0.0f, 0.0f);
    const float scale = length > 0.0f ? 1.0f / length : 0.0f;
    const auto first = static_cast<std::uint32_t>(out.mesh.positions.size());
    for (const glm::vec3& p : polygon) {
        out.mesh.positions.push_back(p);
        out.uv.push_back({std::clamp(0.5f + glm::dot(p - base, across) * scale, 0.0f, 1.0f),
                          std::clamp(glm::dot(p - base, along) * scale, 0.0f, 1.0f)});
        out.color.push_back(color);
    }
    for (std::uint32_t i = 1; i + 1 < polygon.size(); ++i)
        out.mesh.triangles.push_back({first, first + i, first + i + 1});
    end_organ(out, true);
}

// Organ k of `in` appended to `out`, its vertices `keep` (indices into the organ, in
// outline order) when given: a polygon fanned again from the first kept one.
void copy_organ(const OrganMesh& in, std::size_t k, OrganMesh& out,
                const std::vector<std::uint32_t>* keep = nullptr) {
    const std::uint32_t v0 = in.first_vertex[k], v1 = in.first_vertex[k + 1];
    const auto first = static_cast<std::uint32_t>(out.mesh.positions.size());
    if (keep) {
        for (std::uint32_t i : *keep) {
            out.mesh.positions.push_back(in.mesh.positions[v0 + i]);
            out.uv.push_back(in.uv[v0 + i]);
            out.color.push_back(in.color[v0 + i]);
        }
        for (std::uint32_t i = 1; i + 1 < keep->size(); ++i)
            out.mesh.triangles.push_back({first, first + i, first + i + 1});
        return end_organ(out, true);
    }
    out.mesh.positions.insert(out.mesh.positions.end(), in.mesh.positions.begin() + v0,
                              in.mesh.positions.begin() + v1);
    out.uv.insert(out.uv.end(), in.uv.begin() + v0, in.uv.begin() + v1);
    out.color.insert(out.color.end(), in.color.begin() + v0, in.color.begin() + v1);
    for (std::uint32_t t = in.first_triangle[k]; t < in.first_triangle[k + 1]; ++t) {
        const auto& tri = in.mesh.triangles[t];
        out.mesh.triangles.push_back(
            {tri[0] - v0 + first, tri[1] - v0 + first, tri[2] - v0 + first});
    }
    end_organ(out, in.polygon[k] != 0);
}

// The four vertices a polygon keeps as a quad: its base (vertex 0), its tip (the farthest
// from the base) and on either side of the base-tip axis the farthest from it, in outline
// order; all of them when it has four or fewer.
std::vector<std::uint32_t> quad_of(const OrganMesh& in, std::size_t k) {
    const std::uint32_t v0 = in.first_vertex[k], n = in.first_vertex[k + 1] - v0;
    std::vector<std::uint32_t> keep(n);
    std::iota(keep.begin(), keep.end(), 0u);
    if (n <= 4) return keep;
    const auto at = [&](std::uint32_t i) { return in.mesh.positions[v0 + i]; };
    std::uint32_t tip = 1;
    for (std::uint32_t i = 1; i < n; ++i)
        if (glm::distance(at(i), at(0)) > glm::distance(at(tip), at(0))) tip = i;
    const glm::vec3 axis = at(tip) - at(0);
    glm::vec3 normal(0.0f);
    for (std::uint32_t i = 1; i + 1 < n; ++i)
        normal += glm::cross(at(i) - at(0), at(i + 1) - at(0));
    const glm::vec3 across = glm::cross(normal, axis);
    std::uint32_t low = 0, high = 0;
    float lowest = 0.0f, highest = 0.0f;
    for (std::uint32_t i = 1; i < n; ++i) {
        if (i == tip) continue;
        const float d = glm::dot(at(i) - at(0), across);
        if (d < lowest || low == 0) lowest = d, low = i;
        if (d > highest || high == 0) highest = d, high = i;
    }
    std::vector<std::uint32_t> quad{0, tip, low, high};
    std::sort(quad.begin(), quad.end());
    quad.erase(std::unique(quad.begin(), quad.end()), quad.end());
    return quad;
}

std::string known_surfaces() {
    std::string known;
    for (const std::string& name : organ_surface_names())
        known += (known.empty() ? "" : ", ") + name;
    return known;
}

}  // namespace

OrganMesh tree_organs(const Skeleton& skeleton, const TreeParams& params) {
    OrganMesh out;
    for (const Organ& organ : skeleton.organs) {
        const OrganSurface* surface = find_organ_surface(organ.surface);
        if (!surface)
            throw InputError("the grammar places an unknown organ '~" + organ.surface +
                             "' (known: " + known_surfaces() + ")");
        add_surface(out, organ, *surface);
    }
    if (params.polygon_part == PolygonPart::Organs)
        for (std::size_t k = 0; k < skeleton.polygons.size(); ++k)
            if (skeleton.polygons[k].size() >= 3)
                add_polygon(out, skeleton.polygons[k], polygon_color(skeleton, k));
    return out;
}

OrganMesh thin_organs(const OrganMesh& organs, std::size_t max_triangles) {
    if (organs.mesh.triangles.size() <= max_triangles) return organs;
    const std::size_t n = organs.organs();
    // Polygons become quads first: a leaf or petal reads as one from afar.
    OrganMesh simpler;
    for (std::size_t k = 0; k < n; ++k) {
        if (organs.polygon[k]) {
            const std::vector<std::uint32_t> quad = quad_of(organs, k);
            copy_organ(organs, k, simpler, &quad);
        } else {
            copy_organ(organs, k, simpler);
        }
    }
    if (simpler.mesh.triangles.size() <= max_triangles) return simpler;
    // The order: organ indices sorted by their bit-reversed position in a power-of-two
    // range, so each prefix of the order is spread evenly over the tree.
    const unsigned bits = static_cast<unsigned>(std::bit_width(std::max<std::size_t>(n, 1) - 1));
    auto reversed = [bits](std::size_t i) {
        std::size_t r = 0;
        for (unsigned b = 0; b < bits; ++b) r |= ((i >> b) & 1u) << (bits - 1 - b);
        return r;
    };
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return reversed(a) < reversed(b); });
    std::vector<bool> keep(n, false);
    std::size_t triangles = 0;
    for (std::size_t k : order) {
        const std::size_t own = simpler.first_triangle[k + 1] - simpler.first_triangle[k];
        if (triangles + own > max_triangles) break;
        triangles += own;
        keep[k] = true;
    }
    OrganMesh out;
    for (std::size_t k = 0; k < n; ++k)
        if (keep[k]) copy_organ(simpler, k, out);
    return out;
}

}  // namespace sylva
