#include "impostor/view_rasterizer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>

namespace sylva {
namespace {

// A face as the rasterizer needs it: corners in sample coordinates (x right, y down) with
// depth toward the camera, and what a covered sample takes from it.
struct Face {
    glm::vec3 a, b, c;
    glm::vec3 color;
    glm::vec3 normal;
};

// Closed parts are seen from outside only: their faces turned away are hidden behind the
// ones facing the camera and are left out (half the work).
void project(std::span<const BakePart> parts, const ViewFrame& frame, const BakeBounds& bounds,
             float extent, std::vector<Face>& faces, std::vector<glm::vec3>& screen) {
    faces.clear();
    const float scale = 0.5f * extent / bounds.radius;
    for (const BakePart& part : parts) {
        if (!part.mesh) continue;
        const Mesh& mesh = *part.mesh;
        screen.resize(mesh.positions.size());
        for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
            const glm::vec3 p = mesh.positions[v] - bounds.center;
            screen[v] = {0.5f * extent + scale * glm::dot(p, frame.right),
                         0.5f * extent - scale * glm::dot(p, frame.up),
                         glm::dot(p, frame.direction)};
        }
        const bool tinted = part.tint && part.tint->size() == mesh.positions.size();
        for (const auto& t : mesh.triangles) {
            const glm::vec3 &p0 = mesh.positions[t[0]], &p1 = mesh.positions[t[1]],
                            &p2 = mesh.positions[t[2]];
            glm::vec3 n = glm::cross(p1 - p0, p2 - p0);
            const float length = glm::length(n);
            if (!(length > 0.0f)) continue;  // degenerate: covers nothing
            n /= length;
            if (glm::dot(n, frame.direction) < 0.0f) {
                if (!part.two_sided) continue;
                n = -n;
            }
            glm::vec3 color = part.color;
            if (tinted)
                color *= ((*part.tint)[t[0]] + (*part.tint)[t[1]] + (*part.tint)[t[2]]) / 3.0f;
            faces.push_back({screen[t[0]], screen[t[1]], screen[t[2]], color, n});
        }
    }
}

// Per thread, reused from view to view: a bake renders dozens of views on each thread, and
// fresh buffers of this size cost page faults.
struct Scratch {
    std::vector<Face> faces;
    std::vector<glm::vec3> screen;
    std::vector<float> depth;
    std::vector<std::int32_t> owner;
};

}  // namespace

BakeBounds bake_bounds(std::span<const BakePart> parts) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    bool any = false;
    for (const BakePart& part : parts)
        if (part.mesh)
            for (const glm::vec3& p : part.mesh->positions) {
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
                any = true;
            }
    BakeBounds bounds;
    if (!any) return bounds;
    bounds.center = 0.5f * (lo + hi);
    for (const BakePart& part : parts)
        if (part.mesh)
            for (const glm::vec3& p : part.mesh->positions)
                bounds.radius = std::max(bounds.radius, glm::length(p - bounds.center));
    return bounds;
}

ViewImage render_view(std::span<const BakePart> parts, const ViewFrame& frame,
                      const BakeBounds& bounds, int size, int samples) {
    ViewImage image;
    render_view(parts, frame, bounds, size, samples, image);
    return image;
}

void render_view(std::span<const BakePart> parts, const ViewFrame& frame, const BakeBounds& bounds,
                 int size, int samples, ViewImage& image) {
    samples = std::clamp(samples, 1, 8);
    image.size = size;
    const std::size_t pixels = static_cast<std::size_t>(size) * static_cast<std::size_t>(size);
    image.alpha.assign(pixels, 0.0f);
    image.color.assign(pixels, glm::vec3(0.0f));
    image.normal.assign(pixels, glm::vec3(0.0f));
    image.depth.assign(pixels, 0.0f);
    if (size <= 0 || !(bounds.radius > 0.0f)) return;

    const int width = size * samples;
    thread_local Scratch scratch;
    project(parts, frame, bounds, static_cast<float>(width), scratch.faces, scratch.screen);
    const std::vector<Face>& faces = scratch.faces;
    const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(width);
    std::vector<float>& depth = scratch.depth;
    std::vector<std::int32_t>& owner = scratch.owner;
    depth.assign(count, -std::numeric_limits<float>::infinity());
    owner.assign(count, -1);

    for (std::size_t f = 0; f < faces.size(); ++f) {
        const Face& face = faces[f];
        const glm::vec3 &a = face.a, &b = face.b, &c = face.c;
        const float area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        if (area == 0.0f) continue;
        const float inv = 1.0f / area;
        // Samples sit at half-integer coordinates: x + 0.5 for x in the box.
        const int x0 = std::max(0, static_cast<int>(std::ceil(std::min({a.x, b.x, c.x}) - 0.5f)));
        const int x1 =
            std::min(width - 1, static_cast<int>(std::floor(std::max({a.x, b.x, c.x}) - 0.5f)));
        const int y0 = std::max(0, static_cast<int>(std::ceil(std::min({a.y, b.y, c.y}) - 0.5f)));
        const int y1 =
            std::min(width - 1, static_cast<int>(std::floor(std::max({a.y, b.y, c.y}) - 0.5f)));
        for (int y = y0; y <= y1; ++y) {
            const float py = static_cast<float>(y) + 0.5f;
            for (int x = x0; x <= x1; ++x) {
                const float px = static_cast<float>(x) + 0.5f;
                // Barycentric weights, each >= 0 inside whichever way the face winds.
                const float w0 = ((b.x - px) * (c.y - py) - (b.y - py) * (c.x - px)) * inv;
                const float w1 = ((c.x - px) * (a.y - py) - (c.y - py) * (a.x - px)) * inv;
                const float w2 = 1.0f - w0 - w1;
                if (w0 < 0.0f || w1 < 0.0f || w2 < 0.0f) continue;
                const float z = w0 * a.z + w1 * b.z + w2 * c.z;
                const std::size_t s =
                    static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                    static_cast<std::size_t>(x);
                if (z > depth[s]) {
                    depth[s] = z;
                    owner[s] = static_cast<std::int32_t>(f);
                }
            }
        }
    }

    // Resolve: each pixel averages its samples.
    const float per_sample = 1.0f / static_cast<float>(samples * samples);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            int covered = 0;
            glm::vec3 color(0.0f), normal(0.0f);
            float z = 0.0f;
            for (int sy = 0; sy < samples; ++sy)
                for (int sx = 0; sx < samples; ++sx) {
                    const std::size_t s = static_cast<std::size_t>(y * samples + sy) *
                                              static_cast<std::size_t>(width) +
                                          static_cast<std::size_t>(x * samples + sx);
                    if (owner[s] < 0) continue;
                    const Face& face = faces[static_cast<std::size_t>(owner[s])];
                    ++covered;
                    color += face.color;
                    normal += face.normal;
                    z += depth[s];
                }
            if (covered == 0) continue;
            const std::size_t p = static_cast<std::size_t>(y) * static_cast<std::size_t>(size) +
                                  static_cast<std::size_t>(x);
            const float share = 1.0f / static_cast<float>(covered);
            image.alpha[p] = static_cast<float>(covered) * per_sample;
            image.color[p] = color * share;
            const float length = glm::length(normal);
            image.normal[p] = length > 0.0f ? normal / length : frame.direction;
            image.depth[p] = z * share;
        }
}

}  // namespace sylva
