#include "lowpoly/prism_tube.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <numbers>

namespace sylva {
namespace {

// A tube's base starts inside another tube (its parent's, or the piece before it at a cut):
// drawn this much thinner there, no corner of it lands on one of the other's, which would
// join the two into one surface that passes through itself.
constexpr float kBaseInset = 0.97f;

// Distance of p from the segment a-b, and where along it (0..1) the nearest point lies.
float distance_to_segment(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, float& t) {
    const glm::vec3 d = b - a;
    const float len2 = glm::dot(d, d);
    t = len2 > 0.0f ? std::clamp(glm::dot(p - a, d) / len2, 0.0f, 1.0f) : 0.0f;
    return glm::distance(p, a + t * d);
}

void keep_between(const TubeAxis& axis, std::size_t first, std::size_t last, float tolerance,
                  std::vector<char>& keep) {
    if (last <= first + 1) return;
    std::size_t far = first;
    float far_error = tolerance;
    for (std::size_t i = first + 1; i < last; ++i) {
        float t = 0.0f;
        const float off =
            distance_to_segment(axis.points[i], axis.points[first], axis.points[last], t);
        const float radius = axis.radii[first] + t * (axis.radii[last] - axis.radii[first]);
        // A radius error shows twice, on both sides of the branch.
        const float error = std::max(off, 2.0f * std::abs(axis.radii[i] - radius));
        if (error > far_error) {
            far_error = error;
            far = i;
        }
    }
    if (far == first) return;
    keep[far] = 1;
    keep_between(axis, first, far, tolerance, keep);
    keep_between(axis, far, last, tolerance, keep);
}

// The unit direction of segment i (points i to i + 1).
glm::vec3 direction(const TubeAxis& axis, std::size_t i) {
    return glm::normalize(axis.points[i + 1] - axis.points[i]);
}

// The angle between two unit directions, degrees.
float bend_degrees(const glm::vec3& a, const glm::vec3& b) {
    return glm::degrees(std::acos(std::clamp(glm::dot(a, b), -1.0f, 1.0f)));
}

// The circumradius whose regular polygon with `sides` corners has a mean width (its
// perimeter over pi) of twice `radius`.
float circumradius(float radius, int sides) {
    const float n = static_cast<float>(sides);
    return radius * std::numbers::pi_v<float> / (n * std::sin(std::numbers::pi_v<float> / n));
}

// How far the mitre at a bend of `degrees` reaches along the axis from the joint, for a
// tube of `radius` with `sides` corners.
float mitre_reach(float radius, int sides, float degrees) {
    return circumradius(radius, sides) * std::tan(glm::radians(0.5f * degrees));
}

// `v` turned by the rotation that takes unit `from` to unit `to` (the shortest one), then
// made perpendicular to `to`: a frame carried along a bending axis without twist.
glm::vec3 carry(const glm::vec3& v, const glm::vec3& from, const glm::vec3& to) {
    const glm::vec3 axis = glm::cross(from, to);
    const float s = glm::length(axis), c = glm::dot(from, to);
    glm::vec3 out = v;
    if (s > 1e-7f) {
        const glm::vec3 k = axis / s;
        out = v * c + glm::cross(k, v) * s + k * glm::dot(k, v) * (1.0f - c);
    }
    out -= glm::dot(out, to) * to;
    return glm::normalize(out);
}

// A unit vector perpendicular to unit `d`, as close to `hint` as can be.
glm::vec3 perpendicular(const glm::vec3& d, const glm::vec3& hint) {
    glm::vec3 p = hint - glm::dot(hint, d) * d;
    if (glm::length(p) < 1e-4f) {
        const glm::vec3 other = std::abs(d.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
        p = other - glm::dot(other, d) * d;
    }
    return glm::normalize(p);
}

}  // namespace

TubeAxis simplify_axis(const TubeAxis& axis, float tolerance) {
    const std::size_t n = axis.points.size();
    if (n <= 2) return axis;
    std::vector<char> keep(n, 0);
    keep.front() = keep.back() = 1;
    keep_between(axis, 0, n - 1, tolerance, keep);
    TubeAxis out;
    out.pointed = axis.pointed;
    for (std::size_t i = 0; i < n; ++i)
        if (keep[i]) {
            out.points.push_back(axis.points[i]);
            out.radii.push_back(axis.radii[i]);
        }
    return out;
}

std::vector<TubeAxis> tube_pieces(const TubeAxis& axis, int sides) {
    // Without points that repeat the one before.
    TubeAxis clean;
    for (std::size_t i = 0; i < axis.points.size(); ++i) {
        if (!clean.points.empty() &&
            glm::distance(clean.points.back(), axis.points[i]) <= 1e-3f * axis.radii[i])
            continue;
        clean.points.push_back(axis.points[i]);
        clean.radii.push_back(axis.radii[i]);
    }
    std::vector<TubeAxis> pieces;
    if (clean.points.size() < 2) return pieces;
    const std::size_t n = clean.points.size();
    // bend[i]: the angle at inner point i (0 at the ends).
    std::vector<float> bend(n, 0.0f);
    for (std::size_t i = 1; i + 1 < n; ++i)
        bend[i] = bend_degrees(direction(clean, i - 1), direction(clean, i));
    // cut[i]: a piece ends and the next starts at point i.
    std::vector<char> cut(n, 0);
    for (std::size_t i = 1; i + 1 < n; ++i) cut[i] = bend[i] > kMaxTubeBendDegrees;
    // A segment whose two mitres reach past each other: cut at its sharper end, which takes
    // that mitre away (a cut point is an end of both its pieces, square to its segment).
    for (std::size_t i = 0; i + 1 < n; ++i) {
        const float length = glm::distance(clean.points[i], clean.points[i + 1]);
        const float a = cut[i] ? 0.0f : mitre_reach(clean.radii[i], sides, bend[i]);
        const float b = cut[i + 1] ? 0.0f : mitre_reach(clean.radii[i + 1], sides, bend[i + 1]);
        if (a + b < 0.9f * length) continue;
        if (bend[i] >= bend[i + 1] && i > 0)
            cut[i] = 1;
        else if (i + 1 < n - 1)
            cut[i + 1] = 1;
        else if (i > 0)
            cut[i] = 1;
    }
    TubeAxis piece;
    for (std::size_t i = 0; i < n; ++i) {
        piece.points.push_back(clean.points[i]);
        piece.radii.push_back(clean.radii[i]);
        if (i + 1 < n && cut[i] && piece.points.size() >= 2) {
            pieces.push_back(std::move(piece));
            piece = TubeAxis{};
            piece.points.push_back(clean.points[i]);
            piece.radii.push_back(clean.radii[i]);
        }
    }
    piece.pointed = axis.pointed;
    if (piece.points.size() >= 2) pieces.push_back(std::move(piece));
    return pieces;
}

std::size_t tube_triangles(std::size_t points, int sides, bool pointed) {
    if (points < 2 || sides < 3) return 0;
    const auto k = static_cast<std::size_t>(sides);
    const std::size_t segments = points - 1;
    return pointed ? (k - 2) + 2 * k * (segments - 1) + k : 2 * (k - 2) + 2 * k * segments;
}

void append_tube(Mesh& mesh, const TubeAxis& axis, int sides, glm::vec3 side) {
    const std::size_t n = axis.points.size();
    if (n < 2 || sides < 3) return;
    const auto k = static_cast<std::uint32_t>(sides);
    const std::size_t rings = axis.pointed ? n - 1 : n;
    const auto first = static_cast<std::uint32_t>(mesh.positions.size());
    // `dir` is the segment coming into ring i (the first segment at the base), `u` square to
    // it; at a bend both are carried on to the next segment after the ring.
    glm::vec3 dir = direction(axis, 0);
    glm::vec3 u = perpendicular(dir, side);
    for (std::size_t i = 0; i < rings; ++i) {
        const bool bend = i > 0 && i + 1 < n;
        // The ring's plane: square to the axis at the ends, halving the bend in between. Its
        // corners lie on lines along `dir` through the square ring's, so each face of the
        // segment before is flat.
        const glm::vec3 plane = bend ? glm::normalize(dir + direction(axis, i)) : dir;
        const glm::vec3 v = glm::cross(dir, u);
        const float r = circumradius(axis.radii[i], sides) * (i == 0 ? kBaseInset : 1.0f);
        for (std::uint32_t j = 0; j < k; ++j) {
            const float a =
                2.0f * std::numbers::pi_v<float> * static_cast<float>(j) / static_cast<float>(k);
            const glm::vec3 d = std::cos(a) * u + std::sin(a) * v;
            const float shift = -r * glm::dot(d, plane) / glm::dot(dir, plane);
            mesh.positions.push_back(axis.points[i] + r * d + shift * dir);
        }
        if (bend) {
            const glm::vec3 next = direction(axis, i);
            u = carry(u, dir, next);
            dir = next;
        }
    }
    auto ring = [&](std::size_t i, std::uint32_t j) {
        return first + static_cast<std::uint32_t>(i) * k + j % k;
    };
    // The base cap faces backwards along the axis, the sides outwards.
    for (std::uint32_t j = 1; j + 1 < k; ++j)
        mesh.triangles.push_back({ring(0, 0), ring(0, j + 1), ring(0, j)});
    for (std::size_t i = 0; i + 1 < rings; ++i)
        for (std::uint32_t j = 0; j < k; ++j) {
            mesh.triangles.push_back({ring(i, j), ring(i, j + 1), ring(i + 1, j + 1)});
            mesh.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i + 1, j)});
        }
    if (axis.pointed) {
        const auto apex = static_cast<std::uint32_t>(mesh.positions.size());
        // The point lies past the tip by a quarter of the last segment times the tip's share
        // of the radius before it: a cone thins to nothing where the branch keeps that
        // radius (its field ends in a round cap), and the longer point gives back part of
        // the outline the cone loses.
        const glm::vec3 last = axis.points[n - 1] - axis.points[n - 2];
        mesh.positions.push_back(axis.points.back() +
                                 kTipReach * last * (axis.radii[n - 1] / axis.radii[n - 2]));
        for (std::uint32_t j = 0; j < k; ++j)
            mesh.triangles.push_back({ring(rings - 1, j), ring(rings - 1, j + 1), apex});
    } else {
        for (std::uint32_t j = 1; j + 1 < k; ++j)
            mesh.triangles.push_back(
                {ring(rings - 1, 0), ring(rings - 1, j), ring(rings - 1, j + 1)});
    }
}

}  // namespace sylva
