#include "quality/silhouette.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>

#include "core/errors.h"

namespace sylva {
namespace {

// A view's image axes: right and up in the image plane (the view looks along -right x up).
struct ViewAxes {
    glm::dvec3 right;
    glm::dvec3 up;
};

ViewAxes view_axes(int view) {
    if (view == kSilhouetteViews - 1) return {{1.0, 0.0, 0.0}, {0.0, 0.0, -1.0}};  // from above
    const double azimuth = view * 2.0 * std::numbers::pi / (kSilhouetteViews - 1);
    const double elevation = 15.0 * std::numbers::pi / 180.0;
    // Towards the viewer.
    const glm::dvec3 back(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                          std::cos(elevation) * std::cos(azimuth));
    const glm::dvec3 right = glm::normalize(glm::cross(glm::dvec3(0.0, 1.0, 0.0), back));
    return {right, glm::cross(back, right)};
}

// Twice the signed area of (a, b, c): positive when counter-clockwise. The edge's ends are
// taken in one order whichever way a triangle runs it, so a pixel centre on an edge gets the
// same answer from both triangles of the edge, and from a triangle and its mirror image.
double edge(double ax, double ay, double bx, double by, double cx, double cy) {
    if (ax > bx || (ax == bx && ay > by)) return -((ax - bx) * (cy - by) - (ay - by) * (cx - bx));
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

void rasterize_view(std::span<const Mesh* const> meshes, const SilhouetteFrame& frame,
                    int resolution, const ViewAxes& axes, std::vector<std::uint8_t>& image) {
    const double scale = resolution / (2.0 * frame.radius);
    std::vector<double> xs, ys;
    for (const Mesh* mesh : meshes) {
        assert(mesh);
        // Pixel coordinates of every vertex, once.
        xs.resize(mesh->positions.size());
        ys.resize(mesh->positions.size());
        for (std::size_t v = 0; v < mesh->positions.size(); ++v) {
            const glm::dvec3 p = glm::dvec3(mesh->positions[v]) - frame.center;
            xs[v] = (glm::dot(p, axes.right) + frame.radius) * scale;
            ys[v] = (glm::dot(p, axes.up) + frame.radius) * scale;
        }
        for (const auto& t : mesh->triangles) {
            const double x0 = xs[t[0]], y0 = ys[t[0]], x1 = xs[t[1]], y1 = ys[t[1]];
            const double x2 = xs[t[2]], y2 = ys[t[2]];
            const double area = edge(x0, y0, x1, y1, x2, y2);
            if (area == 0.0) continue;  // seen edge-on: it covers no pixel centre
            const double sign = area > 0.0 ? 1.0 : -1.0;
            // The pixel centres (i + 0.5) inside the triangle's box, clamped to the image
            // before the cast (a candidate may lie far outside the frame).
            const double top = resolution - 1;
            const auto first = [top](double low) {
                return static_cast<int>(std::clamp(std::ceil(low - 0.5), 0.0, top + 1.0));
            };
            const auto last = [top](double high) {
                return static_cast<int>(std::clamp(std::floor(high - 0.5), -1.0, top));
            };
            const int i0 = first(std::min({x0, x1, x2})), i1 = last(std::max({x0, x1, x2}));
            const int j0 = first(std::min({y0, y1, y2})), j1 = last(std::max({y0, y1, y2}));
            for (int j = j0; j <= j1; ++j) {
                const double cy = j + 0.5;
                std::uint8_t* row = image.data() + static_cast<std::size_t>(j) * resolution;
                for (int i = i0; i <= i1; ++i) {
                    const double cx = i + 0.5;
                    if (sign * edge(x0, y0, x1, y1, cx, cy) >= 0.0 &&
                        sign * edge(x1, y1, x2, y2, cx, cy) >= 0.0 &&
                        sign * edge(x2, y2, x0, y0, cx, cy) >= 0.0)
                        row[i] = 1;
                }
            }
        }
    }
}

}  // namespace

SilhouetteFrame silhouette_frame(std::span<const Mesh* const> meshes) {
    glm::dvec3 low(std::numeric_limits<double>::max());
    glm::dvec3 high(std::numeric_limits<double>::lowest());
    bool any = false;
    for (const Mesh* mesh : meshes) {
        assert(mesh);
        for (const auto& t : mesh->triangles)
            for (std::uint32_t v : t) {
                low = glm::min(low, glm::dvec3(mesh->positions[v]));
                high = glm::max(high, glm::dvec3(mesh->positions[v]));
                any = true;
            }
    }
    if (!any) throw InputError("silhouette: the reference meshes have no triangles");
    SilhouetteFrame frame;
    frame.center = 0.5 * (low + high);
    for (const Mesh* mesh : meshes)
        for (const auto& t : mesh->triangles)
            for (std::uint32_t v : t)
                frame.radius = std::max(frame.radius,
                                        glm::length(glm::dvec3(mesh->positions[v]) - frame.center));
    // A reference of one point still gets an image.
    frame.radius = 1.25 * std::max(frame.radius, 1e-6);
    return frame;
}

Silhouettes rasterize_silhouettes(std::span<const Mesh* const> meshes, const SilhouetteFrame& frame,
                                  int resolution) {
    assert(resolution >= 1 && frame.radius > 0.0);
    Silhouettes out;
    out.resolution = resolution;
    for (int view = 0; view < kSilhouetteViews; ++view) {
        out.views[view].assign(static_cast<std::size_t>(resolution) * resolution, 0);
        rasterize_view(meshes, frame, resolution, view_axes(view), out.views[view]);
    }
    return out;
}

SilhouetteScore silhouette_iou(const Silhouettes& reference, const Silhouettes& candidate) {
    assert(reference.resolution == candidate.resolution);
    SilhouetteScore score;
    for (int view = 0; view < kSilhouetteViews; ++view) {
        const std::vector<std::uint8_t>& a = reference.views[view];
        const std::vector<std::uint8_t>& b = candidate.views[view];
        std::size_t both = 0, either = 0;
        for (std::size_t p = 0; p < a.size(); ++p) {
            both += a[p] & b[p];
            either += a[p] | b[p];
        }
        score.views[view] = either == 0 ? 1.0 : static_cast<double>(both) / either;
        score.mean += score.views[view];
    }
    score.mean /= kSilhouetteViews;
    return score;
}

SilhouetteScore silhouette_iou(std::span<const Mesh* const> reference,
                               std::span<const Mesh* const> candidate, int resolution) {
    const SilhouetteFrame frame = silhouette_frame(reference);
    return silhouette_iou(rasterize_silhouettes(reference, frame, resolution),
                          rasterize_silhouettes(candidate, frame, resolution));
}

}  // namespace sylva
