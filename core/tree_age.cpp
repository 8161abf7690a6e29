#include "core/tree_age.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

namespace sylva {

double crown_scale_at_age(double age) {
    return 0.25 + 0.75 * std::clamp(age, 0.0, 1.0);
}

Skeleton skeleton_at_age(const Skeleton& mature, double age) {
    age = std::clamp(age, 0.0, 1.0);
    if (age >= 1.0 || mature.segments.empty()) return mature;
    const auto& in = mature.segments;
    const size_t n = in.size();

    // Path distances: d0 at a segment's start, d1 at its end; far: the farthest end beyond.
    std::vector<double> d0(n), d1(n), far(n);
    for (size_t i = 0; i < n; ++i) {
        const Segment& s = in[i];
        assert(s.parent < static_cast<int>(i));
        d0[i] = s.parent >= 0 ? d1[static_cast<size_t>(s.parent)] : 0.0;
        d1[i] = d0[i] + static_cast<double>(glm::distance(s.a, s.b));
        far[i] = d1[i];
    }
    for (size_t i = n; i-- > 0;)
        if (in[i].parent >= 0) {
            double& up = far[static_cast<size_t>(in[i].parent)];
            up = std::max(up, far[i]);
        }
    double longest = 0.0;
    float tip_radius = std::numeric_limits<float>::max();
    for (size_t i = 0; i < n; ++i) longest = std::max(longest, far[i]);
    for (int t : tips(mature)) tip_radius = std::min(tip_radius, in[static_cast<size_t>(t)].rb);
    const double front = (kSeedlingFront + (1.0 - kSeedlingFront) * age) * longest;

    // The radius at a point at distance d of a part whose mature radius there is r.
    auto young_radius = [&](float r, double d, double farthest) {
        const double ahead = farthest - d;
        const double share =
            ahead > 0.0 ? std::clamp((std::min(front, farthest) - d) / ahead, 0.0, 1.0) : 1.0;
        return std::max(static_cast<float>(r * share), std::min(r, tip_radius));
    };

    Skeleton out;
    std::vector<int> index(n, -1);
    for (size_t i = 0; i < n; ++i) {
        if (!(d0[i] < front)) continue;
        Segment s = in[i];
        const double length = d1[i] - d0[i];
        const double grown = length > 0.0 ? std::min(1.0, (front - d0[i]) / length) : 1.0;
        const float rb_mature = s.ra + static_cast<float>(grown) * (s.rb - s.ra);
        s.b = s.a + static_cast<float>(grown) * (s.b - s.a);
        s.ra = young_radius(s.ra, d0[i], far[i]);
        s.rb = young_radius(rb_mature, d0[i] + grown * length, far[i]);
        s.parent = s.parent >= 0 ? index[static_cast<size_t>(s.parent)] : -1;
        index[i] = static_cast<int>(out.segments.size());
        out.segments.push_back(s);
    }

    // Leaf polygons: there once the front passes the nearest segment end, scaled in about
    // their centre over the length of the segment they hang from.
    // Where the front reaches the segment end nearest `p`: 0 before, rising to 1 over that
    // segment's length.
    auto grown_at = [&](const glm::vec3& p) {
        size_t nearest = 0;
        float best = std::numeric_limits<float>::max();
        for (size_t i = 0; i < n; ++i) {
            const float dist = glm::distance(in[i].b, p);
            if (dist < best) best = dist, nearest = i;
        }
        const double length = std::max(d1[nearest] - d0[nearest], 1e-6);
        return std::clamp((front - d1[nearest]) / length, 0.0, 1.0);
    };
    for (size_t k = 0; k < mature.polygons.size(); ++k) {
        const auto& polygon = mature.polygons[k];
        if (polygon.empty()) continue;
        glm::vec3 centre(0.0f);
        for (const glm::vec3& v : polygon) centre += v;
        centre /= static_cast<float>(polygon.size());
        const double grown = grown_at(polygon.front());
        if (grown <= 0.0) continue;
        std::vector<glm::vec3> scaled;
        scaled.reserve(polygon.size());
        for (const glm::vec3& v : polygon)
            scaled.push_back(centre + static_cast<float>(grown) * (v - centre));
        out.polygons.push_back(std::move(scaled));
        if (!mature.polygon_colors.empty()) out.polygon_colors.push_back(polygon_color(mature, k));
    }
    // Organs alike: there once the front passes them, growing to their size.
    for (const Organ& organ : mature.organs) {
        const double grown = grown_at(organ.position);
        if (grown <= 0.0) continue;
        Organ young = organ;
        young.scale *= static_cast<float>(grown);
        out.organs.push_back(std::move(young));
    }
    return out;
}

}  // namespace sylva
