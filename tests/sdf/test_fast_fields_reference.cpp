// The fast fields against the folds they replace, bit for bit: the trunk's cones with their
// constant terms prepared once (and, without a joint blend, measured four at a time in SSE
// lanes), the crown's blend inlined, the bins' distance transform by two chamfer passes.
// Meshes (and the golden export hashes) depend on every bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <random>
#include <vector>

#include "sdf/bin_grid.h"
#include "sdf/capped_cone.h"
#include "sdf/cone_field.h"
#include "sdf/sphere_field.h"

namespace sylva {
namespace {

// IQ's capped cone as first written, every term from the ends at each call.
float reference_distance(const CappedCone& cone, const glm::vec3& p) {
    const float rba = cone.rb - cone.ra;
    const glm::vec3 ba = cone.b - cone.a;
    const glm::vec3 pa = p - cone.a;
    const float baba = glm::dot(ba, ba);
    if (baba <= 0.0f) return glm::length(pa) - std::max(cone.ra, cone.rb);
    const float papa = glm::dot(pa, pa);
    const float paba = glm::dot(pa, ba) / baba;
    const float x = std::sqrt(std::max(papa - paba * paba * baba, 0.0f));
    const float cax = std::max(0.0f, x - (paba < 0.5f ? cone.ra : cone.rb));
    const float cay = std::abs(paba - 0.5f) - 0.5f;
    const float k = rba * rba + baba;
    const float f = std::clamp((rba * (x - cone.ra) + paba * baba) / k, 0.0f, 1.0f);
    const float cbx = x - cone.ra - f * rba;
    const float cby = paba - f;
    const float s = (cbx < 0.0f && cay < 0.0f) ? -1.0f : 1.0f;
    return s * std::sqrt(std::min(cax * cax + cay * cay * baba, cbx * cbx + cby * cby * baba));
}

// The cone field's fold as first written: every candidate in bin order, culled by a bounding
// sphere only, over the same bins.
class ReferenceConeField {
  public:
    ReferenceConeField(std::vector<CappedCone> cones, float margin, float joint_blend)
        : cones_(std::move(cones)), margin_(margin), joint_blend_(joint_blend) {
        std::vector<Aabb> boxes;
        for (const CappedCone& c : cones_) {
            bounds_.push_back(
                {0.5f * (c.a + c.b), 0.5f * glm::length(c.b - c.a) + std::max(c.ra, c.rb)});
            float r = std::max(c.ra, c.rb) + margin_;
            boxes.push_back({glm::min(c.a, c.b) - glm::vec3(r), glm::max(c.a, c.b) + glm::vec3(r)});
        }
        const float inflation = margin_ + joint_blend_;
        bins_ = BinGrid(boxes, kMinBinInMargins * margin_, 40,
                        [&](size_t i, std::span<const glm::vec3> centres, float radius,
                            std::span<std::uint8_t> keep) {
                            for (std::size_t j = 0; j < centres.size(); ++j)
                                keep[j] =
                                    reference_distance(cones_[i], centres[j]) < inflation + radius;
                        });
    }

    float operator()(const glm::vec3& p) const {
        auto near = bins_.candidates(p);
        if (near.empty()) return margin_ + bins_.empty_distance(p);
        float d = margin_;
        for (std::uint32_t i : near) {
            const Bound& b = bounds_[i];
            float reach = d + joint_blend_ + b.radius;
            glm::vec3 offset = p - b.center;
            if (reach > 0.0f && glm::dot(offset, offset) >= reach * reach) continue;
            float next = reference_distance(cones_[i], p);
            d = joint_blend_ > 0.0f ? polynomial_smooth_min(d, next, joint_blend_)
                                    : std::min(d, next);
        }
        return std::min(d, margin_);
    }

  private:
    struct Bound {
        glm::vec3 center;
        float radius;
    };
    std::vector<CappedCone> cones_;
    std::vector<Bound> bounds_;
    float margin_;
    float joint_blend_;
    BinGrid bins_;
};

// Branching chains of cones (joints where ends meet, as a skeleton gives them), with some
// degenerate ones: zero length, zero radius, cylinders.
std::vector<CappedCone> random_tree(std::mt19937& rng, int n) {
    std::uniform_real_distribution<float> u(-1, 1), r(0.02f, 0.3f), len(0.05f, 1.5f);
    std::vector<CappedCone> cones;
    glm::vec3 tip{0.0f};
    float radius = 0.3f;
    for (int i = 0; i < n; ++i) {
        if (i % 7 == 0 && !cones.empty()) {  // branch off an earlier joint
            const CappedCone& from = cones[rng() % cones.size()];
            tip = from.b, radius = from.rb;
        }
        glm::vec3 dir = glm::normalize(glm::vec3(u(rng), u(rng) + 1.5f, u(rng)));
        float next_radius = std::max(0.01f, radius * (0.6f + 0.4f * (u(rng) + 1) / 2));
        switch (i % 11) {
            case 3:
                dir *= 0.0f;
                break;  // a sphere
            case 5:
                next_radius = radius;
                break;  // a cylinder
            case 8:
                next_radius = 0.0f;
                break;  // a point at the end
            default:
                break;
        }
        glm::vec3 end = tip + dir * len(rng);
        cones.push_back({tip, end, radius, next_radius});
        tip = end, radius = std::max(next_radius, 0.02f);
    }
    return cones;
}

// Samples near where values are close: on and near the axes, the joints and the surfaces.
std::vector<glm::vec3> samples_near(std::mt19937& rng, const std::vector<CappedCone>& cones,
                                    int n) {
    std::uniform_real_distribution<float> u(-1, 1), t(-0.2f, 1.2f);
    std::vector<glm::vec3> points;
    for (int i = 0; i < n; ++i) {
        const CappedCone& c = cones[rng() % cones.size()];
        glm::vec3 on_axis = c.a + (c.b - c.a) * t(rng);
        float spread = (i % 4 == 0) ? 1e-4f : (i % 4 == 1) ? 0.02f : (i % 4 == 2) ? 0.3f : 1.5f;
        points.push_back(on_axis + glm::vec3(u(rng), u(rng), u(rng)) * spread);
        if (i % 16 == 0) points.push_back(c.b);  // exactly at a joint
    }
    return points;
}

void expect_same_bits(float fast, float reference, const glm::vec3& p) {
    EXPECT_EQ(std::bit_cast<std::uint32_t>(fast), std::bit_cast<std::uint32_t>(reference))
        << fast << " vs " << reference << " at " << p.x << ", " << p.y << ", " << p.z;
}

TEST(CappedConeReference, PreparedConesGiveTheSameBits) {
    std::mt19937 rng(20);
    const std::vector<CappedCone> cones = random_tree(rng, 200);
    for (const glm::vec3& p : samples_near(rng, cones, 20000))
        for (int i = 0; i < 4; ++i) {
            const CappedCone& c = cones[rng() % cones.size()];
            expect_same_bits(distance(c, p), reference_distance(c, p), p);
            expect_same_bits(distance(prepare(c), p), reference_distance(c, p), p);
        }
}

TEST(ConeFieldReference, SameBitsAsTheBinOrderFold) {
    std::mt19937 rng(21);
    for (float joint_blend : {0.0f, 0.05f, 0.3f})
        for (int tree = 0; tree < 6; ++tree) {
            std::vector<CappedCone> cones = random_tree(rng, 40 + 60 * tree);
            const float margin = 0.05f + 0.05f * float(tree) + joint_blend;
            const ConeField fast(cones, margin, joint_blend);
            const ReferenceConeField reference(cones, margin, joint_blend);
            const std::vector<glm::vec3> points = samples_near(rng, cones, 20000);
            std::vector<float> values(points.size());
            fast.evaluate(points, values);  // visits each point's hint first
            for (std::size_t i = 0; i < points.size(); ++i) {
                const float expected = reference(points[i]);
                expect_same_bits(fast(points[i]), expected, points[i]);
                expect_same_bits(values[i], expected, points[i]);
            }
        }
}

TEST(ConeFieldReference, SameBitsOverManyCandidatesPerBin) {
    // Hundreds of cones through one small region: more candidates than the fast path keeps
    // bounds for on the stack.
    std::mt19937 rng(22);
    std::uniform_real_distribution<float> u(-1, 1), r(0.01f, 0.1f);
    std::vector<CappedCone> cones;
    for (int i = 0; i < 400; ++i)
        cones.push_back({glm::vec3(u(rng), u(rng), u(rng)) * 0.3f,
                         glm::vec3(u(rng), u(rng), u(rng)) * 0.3f, r(rng), r(rng)});
    // Negative radii: no bound holds for them, so they are never culled but still agree.
    cones[7].ra = -0.05f, cones[99].rb = -0.02f;
    for (float joint_blend : {0.0f, 0.1f}) {
        const ConeField fast(cones, 0.4f, joint_blend);
        const ReferenceConeField reference(cones, 0.4f, joint_blend);
        for (const glm::vec3& p : samples_near(rng, cones, 5000))
            expect_same_bits(fast(p), reference(p), p);
    }
}

TEST(ConeFieldReference, SameBitsNearTheAxesOfOverlappingCylinders) {
    // Long thin cylinders along one line, overlapping and a little apart: near the axis each
    // value is x - r with x = sqrt(papa - paba^2 baba), whose cancellation differs from cone
    // to cone by up to sqrt(eps) |pa|, while the capsule bounds carry no such error. Culling
    // by a bound without the rounding allowance would change values here.
    std::mt19937 rng(25);
    std::uniform_real_distribution<float> u(-1, 1), t(0.0f, 1.0f);
    for (int round = 0; round < 8; ++round) {
        const glm::vec3 origin = glm::vec3(u(rng), u(rng), u(rng)) * 50.0f;
        const glm::vec3 dir = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)));
        glm::vec3 side = glm::normalize(glm::cross(dir, glm::vec3(0.3f, 1, 0.2f)));
        std::vector<CappedCone> cones;
        for (int i = 0; i < 12; ++i) {
            const float start = 0.5f * float(i) + 0.01f * u(rng), length = 6.0f + u(rng);
            const glm::vec3 shift = side * (1e-3f * u(rng));
            cones.push_back({origin + shift + dir * start, origin + shift + dir * (start + length),
                             0.05f, 0.05f + (i % 3 == 0 ? 0.0f : 1e-4f * u(rng))});
        }
        for (float joint_blend : {0.0f, 0.02f}) {
            const ConeField fast(cones, 0.1f, joint_blend);
            const ReferenceConeField reference(cones, 0.1f, joint_blend);
            for (int i = 0; i < 20000; ++i) {
                const float off = (i % 2 == 0) ? 1e-5f : 0.04f;
                glm::vec3 p =
                    origin + dir * (12.0f * t(rng)) + glm::vec3(u(rng), u(rng), u(rng)) * off;
                expect_same_bits(fast(p), reference(p), p);
            }
        }
    }
}

// The crown's fold by its definition (sdf/sphere_field.h), one sphere at a time: the
// spheres the bins list within 4 k of the nearest, folded nearest first from the margin.
float reference_sphere_fold(const std::vector<Ball>& balls, std::span<const std::uint32_t> near,
                            const glm::vec3& p, float blend, float margin) {
    float nearest = margin;
    for (std::uint32_t i : near) nearest = std::min(nearest, distance(balls[i], p));
    std::vector<float> folded;
    for (std::uint32_t i : near)
        if (distance(balls[i], p) <= nearest + 4.0f * blend)
            folded.push_back(distance(balls[i], p));
    std::sort(folded.begin(), folded.end());
    float d = margin;
    for (float next : folded)
        d = blend > 0.0f ? local_root_smooth_min(d, next, blend) : std::min(d, next);
    return std::min(std::max(d, nearest - 0.5f * blend), margin);
}

// The field takes its spheres' distances four at a time: the same bits as one at a time.
TEST(SphereFieldReference, SameBitsAsTheFoldOneSphereAtATime) {
    std::mt19937 rng(23);
    std::uniform_real_distribution<float> u(0, 3), r(0.05f, 0.5f), v(-0.5f, 3.5f);
    for (float blend : {0.0f, 0.02f, 0.1f, 0.4f}) {
        std::vector<Ball> balls;
        for (int i = 0; i < 300; ++i) balls.push_back({{u(rng), u(rng), u(rng)}, r(rng)});
        const float margin = 0.3f + 4.0f * blend;
        const SphereField field(balls, blend, margin);
        // The field's bins, rebuilt as its constructor builds them.
        std::vector<Aabb> boxes;
        for (const Ball& b : balls) {
            glm::vec3 rr(b.radius + margin);
            boxes.push_back({b.center - rr, b.center + rr});
        }
        const BinGrid bins(boxes, kMinBinInMargins * margin, 40,
                           [&](size_t i, std::span<const glm::vec3> centres, float radius,
                               std::span<std::uint8_t> keep) {
                               for (std::size_t j = 0; j < centres.size(); ++j)
                                   keep[j] = distance(balls[i], centres[j]) < margin + radius;
                           });
        for (int i = 0; i < 30000; ++i) {
            glm::vec3 p{v(rng), v(rng), v(rng)};
            auto near = bins.candidates(p);
            float reference = near.empty() ? margin + bins.empty_distance(p)
                                           : reference_sphere_fold(balls, near, p, blend, margin);
            expect_same_bits(field(p), reference, p);
        }
    }
}

// empty_distance() from the chamfer passes against the chessboard distance by brute force.
TEST(BinGrid, EmptyDistanceIsTheChessboardDistanceToTheNearestListedBin) {
    std::mt19937 rng(24);
    std::uniform_real_distribution<float> u(0, 10), s(0.0f, 0.6f);
    for (int round = 0; round < 4; ++round) {
        std::vector<Aabb> boxes;
        for (int i = 0; i < 3 + 4 * round; ++i) {
            glm::vec3 lo{u(rng), u(rng) * (round == 3 ? 0.2f : 1.0f), u(rng)};
            boxes.push_back({lo, lo + glm::vec3(s(rng), s(rng), s(rng))});
        }
        // A thin shell of boxes leaves most bins empty and far from any listed one.
        const BinGrid bins(boxes, 0.1f, 30);
        Aabb all = boxes[0];
        for (const Aabb& b : boxes)
            all.min = glm::min(all.min, b.min), all.max = glm::max(all.max, b.max);
        const glm::vec3 extent = all.max - all.min;
        const float size = std::max(std::max({extent.x, extent.y, extent.z}) / 30.0f, 0.1f);
        const glm::ivec3 dims = glm::max(glm::ivec3(glm::ceil(extent / size)), glm::ivec3(1));
        auto centre = [&](int x, int y, int z) {
            return all.min + (glm::vec3(x, y, z) + 0.5f) * size;
        };
        std::vector<glm::ivec3> listed;
        for (int z = 0; z < dims.z; ++z)
            for (int y = 0; y < dims.y; ++y)
                for (int x = 0; x < dims.x; ++x)
                    if (!bins.candidates(centre(x, y, z)).empty()) listed.push_back({x, y, z});
        ASSERT_FALSE(listed.empty());
        for (int z = 0; z < dims.z; ++z)
            for (int y = 0; y < dims.y; ++y)
                for (int x = 0; x < dims.x; ++x) {
                    int k = std::numeric_limits<int>::max();
                    for (const glm::ivec3& l : listed)
                        k = std::min(
                            k, std::max({std::abs(l.x - x), std::abs(l.y - y), std::abs(l.z - z)}));
                    const float expected = k <= 1 ? 0.0f : static_cast<float>(k - 1) * size;
                    EXPECT_EQ(bins.empty_distance(centre(x, y, z)), expected)
                        << x << " " << y << " " << z;
                }
    }
}

}  // namespace
}  // namespace sylva
