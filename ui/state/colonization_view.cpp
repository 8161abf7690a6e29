#include "ui/state/colonization_view.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <utility>

#include "colonization/colonization_growth.h"

namespace sylva::studio {
namespace {

// A point of the boundary's profile: distance from the axis as a fraction of the half width
// (r) and height above the bottom as a fraction of the full height (t), both in [0, 1].
struct Profile {
    float r, t;
};

// The meridian from bottom (u = 0) to top (u = 1), matching envelope.cpp's `inside`.
Profile profile(EnvelopeShape shape, float u) {
    const float pi = glm::pi<float>();
    switch (shape) {
        case EnvelopeShape::Sphere:
        case EnvelopeShape::Ellipsoid:
            return {std::sin(pi * u), 0.5f * (1.0f - std::cos(pi * u))};
        case EnvelopeShape::Cone:
            return {1.0f - u, u};
        case EnvelopeShape::Cylinder:
            return {1.0f, u};
        case EnvelopeShape::Hemisphere:
            return {std::cos(0.5f * pi * u), std::sin(0.5f * pi * u)};
    }
    return {0.0f, 0.0f};
}

}  // namespace

bool grows_by_colonization(const TreeTemplate& tree_template) {
    return tree_template.growth == colonization_growth.name;
}

std::vector<glm::vec3> envelope_wire(const Envelope& envelope, int meridians, int rings,
                                     int steps) {
    assert(meridians >= 1 && rings >= 1 && steps >= 1);
    // bounds() knows how each shape fills its extents (a sphere takes the largest).
    const Box box = bounds(envelope);
    const glm::vec3 half = 0.5f * (box.max - box.min);
    const float height = box.max.y - box.min.y;
    auto at = [&](Profile p, float angle) {
        return glm::vec3(envelope.base.x + half.x * p.r * std::cos(angle),
                         envelope.base.y + height * p.t,
                         envelope.base.z + half.z * p.r * std::sin(angle));
    };
    const float two_pi = glm::two_pi<float>();
    std::vector<glm::vec3> lines;
    for (int m = 0; m < meridians; ++m) {
        const float angle = two_pi * static_cast<float>(m) / static_cast<float>(meridians);
        for (int s = 0; s < steps; ++s) {
            const float u0 = static_cast<float>(s) / static_cast<float>(steps);
            const float u1 = static_cast<float>(s + 1) / static_cast<float>(steps);
            lines.push_back(at(profile(envelope.shape, u0), angle));
            lines.push_back(at(profile(envelope.shape, u1), angle));
        }
    }
    for (int k = 0; k <= rings; ++k) {
        const Profile p =
            profile(envelope.shape, static_cast<float>(k) / static_cast<float>(rings));
        if (p.r < 1e-3f) continue;  // a pole or an apex: no ring
        for (int s = 0; s < steps; ++s) {
            lines.push_back(at(p, two_pi * static_cast<float>(s) / static_cast<float>(steps)));
            lines.push_back(at(p, two_pi * static_cast<float>(s + 1) / static_cast<float>(steps)));
        }
    }
    return lines;
}

std::vector<glm::vec3> template_envelope_wire(const TreeTemplate& tree_template) {
    return envelope_wire(template_envelope(colonization_params(tree_template.params)));
}

std::vector<glm::vec3> template_attraction_points(const TreeTemplate& tree_template) {
    // The same call colonization_growth's grow() makes; the tests check the two agree.
    const ColonizationParams& p = colonization_params(tree_template.params);
    return attraction_points(template_envelope(p), p.attraction_points, p.point_distribution,
                             tree_template.params.seed);
}

std::vector<glm::vec3> attraction_points_alive(const TreeTemplate& tree_template, int step) {
    ColonizationSettings settings = colonization_settings(tree_template.params);
    // The growth is deterministic and its steps do not look ahead: stopped at `step`, it is
    // where the whole growth was after that step.
    settings.max_iterations = std::clamp(step, 0, settings.max_iterations);
    // Rooted where colonization_growth roots it.
    return colonize(template_attraction_points(tree_template), glm::vec3(0.0f), settings).remaining;
}

int last_iteration(const Skeleton& skeleton) {
    int last = 0;
    for (const Segment& s : skeleton.segments) last = std::max(last, s.iteration);
    return last;
}

std::vector<glm::vec3> replay_lines(const Skeleton& skeleton, int iteration) {
    std::vector<glm::vec3> lines;
    for (const Segment& s : skeleton.segments)
        if (s.iteration <= iteration) lines.insert(lines.end(), {s.a, s.b});
    return lines;
}

}  // namespace sylva::studio
