// The crown: spheres joined by Heuer's (2022) smooth union ("root smooth min" after Inigo
// Quilez), evaluated fast through a bin grid like the trunk's cones.
//
// root_smooth_min(a, b, k) = (a + b - sqrt((a - b)^2 + k^2)) / 2 lies below min(a, b) by at
// most k/2 (where a == b) and blends the two gradients convexly, so it stays 1-Lipschitz.
// Its reach is unbounded, though: a sphere far away still lowers the value by about
// k^2 / (4 |a - b|), so which spheres a sample sees would show as jumps in the field. The
// crown therefore fades the blend width out between |a - b| = 2k and 4k
// (local_root_smooth_min): identical to Heuer's blend where spheres meet, exactly min
// farther away, still 1-Lipschitz, and spheres beyond the margin cannot matter.
//
// The fold starts at the margin and goes nearest sphere first: a sphere at least 4 k beyond the
// running value leaves it unchanged, and the running value is never above the nearest sphere's, so
// only the spheres within 4 k of the nearest take part (one to a dozen of the few dozen a sample's
// bin lists), and the value does not depend on the order the spheres are listed in. Where the
// nearest changes, the two are at one distance, so the sorted values, and the field, stay
// continuous.
//
// Folded over many spheres the blend would add up (six spheres at one distance lower the
// value by 1.5 k, a thousand by 3.8 k), swelling the union past the box it is meshed in.
// The fold is therefore kept within k/2 of the hard union, the most two spheres lower it:
// max(fold, min - k/2) of two 1-Lipschitz functions is 1-Lipschitz.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "sdf/bin_grid.h"

namespace sylva {

struct Ball {
    glm::vec3 center{0.0f};
    float radius = 0.0f;
};

float distance(const Ball& ball, const glm::vec3& p);

// The balls with near-coincident duplicates merged: a ball whose centre lies within
// `tolerance` of an earlier kept ball's is folded into it, which takes the larger radius; the
// union moves by at most `tolerance`. Thousands of tips at one place (brackets that redraw a
// branch, with or without tiny turns) would otherwise cost every sample near them a visit
// each, and fold the smooth union thousands of times. Order of first appearance is kept.
std::vector<Ball> merge_coincident_balls(std::vector<Ball> balls, float tolerance);

// How the spheres fuse.
enum class SphereBlend {
    RootSmoothMin,   // Heuer's (2022) choice; 1-Lipschitz (see above)
    PaskoSavchenko,  // Heuer 2022, eq. 2.13: (a + b - sqrt(a^2 + b^2 - 2 alpha a b)) / (1 + alpha)
};

// Heuer's (2022) equation 2.13 on signed distances (negative inside): alpha = 1 is the hard
// union, smaller alpha blends more. Not a distance bound: it can steepen the field up to
// (2 + sqrt(2 (1 - alpha))) / (1 + alpha) times, so meshers must not skip space with it.
float pasko_savchenko_union(float a, float b, float alpha);

float root_smooth_min(float a, float b, float k);

// root_smooth_min with the blend width faded to 0 between |a - b| = 2k and 4k. Inline: the
// crown's fold calls it for every sphere near every sample.
inline float local_root_smooth_min(float a, float b, float k) {
    float x = std::abs(a - b);
    if (x >= 4.0f * k) return std::min(a, b);
    // Smoothstep from 1 at 2k to 0 at 4k: its slope (at most 0.75 / k) keeps the blend
    // 1-Lipschitz (d/dx sqrt(x^2 + w^2) = (x + w w') / sqrt(...) stays within [-1, 1]).
    float t = std::clamp((x - 2.0f * k) / (2.0f * k), 0.0f, 1.0f);
    float w = k * (1.0f - t * t * (3.0f - 2.0f * t));
    return 0.5f * (a + b - std::sqrt(x * x + w * w));
}

class SphereField {
  public:
    // blend = k of root_smooth_min (Heuer 2022: P_Cfus), or alpha of the Pasko-Savchenko
    // union; blend 0 with RootSmoothMin gives the hard union.
    SphereField(std::vector<Ball> balls, float blend, float margin,
                SphereBlend kind = SphereBlend::RootSmoothMin);

    // The smooth union of all spheres where it is below margin - 4 * blend; elsewhere a
    // value between margin - 4 * blend and the distance to the nearest sphere (far away a
    // distance transform over the bins gives it), so with the root blend meshers may skip
    // blocks whose centre value exceeds their half-diagonal.
    float operator()(const glm::vec3& p) const;
    // values[i] = (*this)(points[i]) for spans of the same size: one call per batch of
    // points (as a mesher samples them) rather than one per point. Thread-safe.
    void evaluate(std::span<const glm::vec3> points, std::span<float> values) const;

    const std::vector<Ball>& balls() const { return balls_; }
    float blend() const { return blend_; }
    // True when the field is 1-Lipschitz (below margin - 4 blend), so space may be skipped.
    bool is_distance_bound() const { return kind_ == SphereBlend::RootSmoothMin; }

  private:
    std::vector<Ball> balls_;
    float blend_;
    float margin_;
    SphereBlend kind_;
    BinGrid bins_;
};

}  // namespace sylva
