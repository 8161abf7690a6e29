#include "tree/leaf_cards.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "core/random.h"
#include "tree/leaf_thinning.h"

namespace sylva {
namespace {

// A card leans off its patch's outward direction by up to this, and turns about it by up
// to kMaxTurn, so that cards side by side do not read as one tiled surface.
constexpr float kMaxTilt = 0.45f;  // radians, about 26 degrees
constexpr float kMaxTurn = 0.6f;   // radians, about 34 degrees
// A card's half-length and half-width over its leaves' farthest spread along and across it:
// a diamond through the farthest leaf points would cover only half of the patch.
constexpr float kCover = 1.25f;
// Leaves of a patch lie alike (a frond's leaflets, a twig's leaves in a row) when their
// normals, each turned to the outward side, sum to more than this share of their count:
// then the card lies as they do, not facing out of the crown, and runs along them.
constexpr float kAlike = 0.7f;
// The grid grows by this factor until its occupied cells fit the budget, then is refined.
constexpr float kGrowth = 1.2f;
constexpr int kRefinements = 6;
// Cells within this many cells of a patch give the leaves around it, whose centre lies
// inwards of the patch on a crown's surface.
constexpr int kAround = 2;
// A card in the open (no crown surface in its cell or the cells beside it) has at most this
// many times its leaves' area: a patch of a few leaves spread apart would otherwise get a card
// across the sky between them (a shrub's twigs, a palm's fronds). Over a crown a card keeps
// its size, its overlap lies on the crown and covers what the crown's reduction lost at its
// rim. Measured with sylva-bench-look: 1.5 to 2 keep the most of the outline.
constexpr float kOpenCover = 1.75f;

struct LeafSpot {
    glm::vec3 centre{0.0f};              // the mean of its vertices
    float length = 0.0f;                 // its farthest vertex from its base
    glm::vec3 along{0.0f, 1.0f, 0.0f};   // from its base to that vertex
    glm::vec3 normal{0.0f, 0.0f, 1.0f};  // its first triangle's
    float area = 0.0f;                   // its triangles' area
};

// Out of the crown at a point: away from the crown's spine, a vertical segment through the
// leaves' middle that stops a horizontal radius short of their top and bottom, so cards on
// a tall crown's sides face sideways, on its top upwards, on a round crown away from its
// centre.
class Outward {
  public:
    explicit Outward(const std::vector<LeafSpot>& spots) {
        glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
        for (const LeafSpot& s : spots) lo = glm::min(lo, s.centre), hi = glm::max(hi, s.centre);
        middle_ = 0.5f * (lo + hi);
        const float radius = 0.5f * std::max(hi.x - lo.x, hi.z - lo.z);
        low_ = std::min(lo.y + radius, middle_.y);
        high_ = std::max(hi.y - radius, middle_.y);
    }
    // The middle of the leaves' box.
    const glm::vec3& middle() const { return middle_; }
    glm::vec3 operator()(const glm::vec3& p) const {
        const glm::vec3 d = p - glm::vec3(middle_.x, std::clamp(p.y, low_, high_), middle_.z);
        return glm::length(d) > 1e-6f ? glm::normalize(d) : glm::vec3(0.0f, 1.0f, 0.0f);
    }

  private:
    glm::vec3 middle_{0.0f};
    float low_ = 0.0f, high_ = 0.0f;
};

// Appends one card, a diamond from its base (first) to its tip, facing along `normal`.
void append_card(Mesh& out, const glm::vec3& centre, const glm::vec3& along,
                 const glm::vec3& across, float half_length, float half_width) {
    const auto first = static_cast<std::uint32_t>(out.positions.size());
    out.positions.push_back(centre - along * half_length);  // the base
    out.positions.push_back(centre - across * half_width);
    out.positions.push_back(centre + along * half_length);
    out.positions.push_back(centre + across * half_width);
    out.triangles.push_back({first, first + 1, first + 2});
    out.triangles.push_back({first, first + 2, first + 3});
}

std::uint64_t pack(const glm::ivec3& c) {
    constexpr std::int64_t kBias = 1 << 20;
    return (static_cast<std::uint64_t>(c.x + kBias) << 42) |
           (static_cast<std::uint64_t>(c.y + kBias) << 21) |
           static_cast<std::uint64_t>(c.z + kBias);
}

glm::ivec3 cell_of(const glm::vec3& p, const glm::vec3& origin, float cell) {
    return glm::ivec3(glm::floor((p - origin) / cell));
}

// `v` turned about unit `axis` by `angle`.
glm::vec3 turn(const glm::vec3& v, const glm::vec3& axis, float angle) {
    return v * std::cos(angle) + glm::cross(axis, v) * std::sin(angle) +
           axis * glm::dot(axis, v) * (1.0f - std::cos(angle));
}

}  // namespace

Mesh leaf_cards(const Mesh& leaves, const LeafCardSettings& settings) {
    Mesh out;
    const std::size_t max_cards = settings.max_triangles / 2;
    if (leaves.triangles.empty() || max_cards == 0) return out;
    const std::vector<LeafPiece> pieces = split_leaves(leaves);
    std::vector<LeafSpot> spots(pieces.size());
    std::vector<std::vector<std::uint32_t>> vertices(pieces.size());
    glm::vec3 origin(std::numeric_limits<float>::max());
    for (std::size_t l = 0; l < pieces.size(); ++l) {
        std::vector<std::uint32_t>& vs = vertices[l];
        for (std::uint32_t f : pieces[l].triangles)
            vs.insert(vs.end(), leaves.triangles[f].begin(), leaves.triangles[f].end());
        std::sort(vs.begin(), vs.end());
        vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
        LeafSpot& spot = spots[l];
        glm::vec3 sum(0.0f);
        const glm::vec3 base = leaves.positions[pieces[l].base];
        for (std::uint32_t v : vs) {
            sum += leaves.positions[v];
            const float d = glm::distance(base, leaves.positions[v]);
            if (d > spot.length) {
                spot.length = d;
                spot.along = (leaves.positions[v] - base) / d;
            }
        }
        spot.centre = sum / static_cast<float>(vs.size());
        for (std::uint32_t f : pieces[l].triangles) {
            const auto& g = leaves.triangles[f];
            spot.area +=
                0.5f * glm::length(glm::cross(leaves.positions[g[1]] - leaves.positions[g[0]],
                                              leaves.positions[g[2]] - leaves.positions[g[0]]));
        }
        const auto& t = leaves.triangles[pieces[l].triangles.front()];
        const glm::vec3 n = glm::cross(leaves.positions[t[1]] - leaves.positions[t[0]],
                                       leaves.positions[t[2]] - leaves.positions[t[0]]);
        if (glm::length(n) > 0.0f) spot.normal = glm::normalize(n);
        origin = glm::min(origin, spot.centre);
    }
    const Outward outward(spots);

    // Few enough leaves: a card each, lying as the leaf lies (turned to face out).
    if (spots.size() <= max_cards) {
        for (std::size_t l = 0; l < spots.size(); ++l) {
            const LeafSpot& spot = spots[l];
            const glm::vec3 normal =
                glm::dot(spot.normal, outward(spot.centre)) < 0.0f ? -spot.normal : spot.normal;
            const glm::vec3 across = glm::cross(normal, spot.along);
            float half_length = 0.0f, half_width = 0.0f;
            for (std::uint32_t v : vertices[l]) {
                const glm::vec3 d = leaves.positions[v] - spot.centre;
                half_length = std::max(half_length, std::abs(glm::dot(d, spot.along)));
                half_width = std::max(half_width, std::abs(glm::dot(d, across)));
            }
            append_card(out, spot.centre, spot.along, across, half_length, half_width);
        }
        return out;
    }
    std::vector<float> lengths;
    for (const LeafSpot& s : spots) lengths.push_back(s.length);
    std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
    float cell = std::max(settings.min_leaves_across * lengths[lengths.size() / 2], 1e-4f);

    // The grid: cells as small as allowed while their count fits the budget. They grow by
    // kGrowth until the count fits, then the size is halved down between the last two
    // (kRefinements times), so the cards use most of the budget.
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(pieces.size());
    auto patches_at = [&](float size) {
        for (std::size_t l = 0; l < pieces.size(); ++l)
            keyed[l] = {pack(cell_of(spots[l].centre, origin, size)),
                        static_cast<std::uint32_t>(l)};
        std::sort(keyed.begin(), keyed.end());
        std::size_t count = 0;
        for (std::size_t i = 0; i < keyed.size(); ++i)
            count += i == 0 || keyed[i].first != keyed[i - 1].first;
        return count;
    };
    if (patches_at(cell) > max_cards) {
        float too_small = cell;
        while (patches_at(cell *= kGrowth) > max_cards) too_small = cell;
        for (int k = 0; k < kRefinements; ++k) {
            const float mid = 0.5f * (too_small + cell);
            (patches_at(mid) > max_cards ? too_small : cell) = mid;
        }
    }
    const std::size_t cells = patches_at(cell);
    // Each occupied cell's leaves: how many and their centres' sum.
    struct Patch {
        glm::vec3 sum{0.0f};
        float count = 0.0f;
    };
    std::unordered_map<std::uint64_t, Patch> patches;
    patches.reserve(cells);
    for (const auto& [key, l] : keyed) {
        Patch& p = patches[key];
        p.sum += spots[l].centre;
        p.count += 1.0f;
    }

    // The cells the crown's surface passes through.
    std::unordered_set<std::uint64_t> crown_cells;
    if (settings.crown != nullptr)
        for (const glm::vec3& p : settings.crown->positions)
            crown_cells.insert(pack(cell_of(p, origin, cell)));
    auto on_crown = [&](const glm::ivec3& at) {
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    if (crown_cells.count(pack(at + glm::ivec3(dx, dy, dz))) > 0) return true;
        return false;
    };

    Random random(settings.seed ^ 0xca4d5eedULL);
    for (std::size_t begin = 0; begin < keyed.size();) {
        std::size_t end = begin;
        while (end < keyed.size() && keyed[end].first == keyed[begin].first) ++end;
        const Patch& patch = patches[keyed[begin].first];
        const glm::vec3 centre = patch.sum / patch.count;
        const glm::ivec3 at = cell_of(centre, origin, cell);
        Patch around;
        for (int dz = -kAround; dz <= kAround; ++dz)
            for (int dy = -kAround; dy <= kAround; ++dy)
                for (int dx = -kAround; dx <= kAround; ++dx) {
                    const auto it = patches.find(pack(at + glm::ivec3(dx, dy, dz)));
                    if (it == patches.end()) continue;
                    around.sum += it->second.sum;
                    around.count += it->second.count;
                }
        // Out of the crown: away from the leaves around the patch and from the crown's spine.
        glm::vec3 normal = outward(centre);
        const glm::vec3 away = centre - around.sum / around.count;
        if (glm::length(away) > 0.1f * cell) normal += glm::normalize(away);
        normal = glm::length(normal) > 1e-6f ? glm::normalize(normal) : glm::vec3(0, 1, 0);
        // How the patch's leaves lie: their normals, each turned to the first's side, and
        // their lengths; the card faces away from the leaves' middle (else out of the crown).
        glm::vec3 lie(0.0f), lie_along(0.0f);
        const glm::vec3 first = spots[keyed[begin].second].normal;
        for (std::size_t i = begin; i < end; ++i) {
            const LeafSpot& spot = spots[keyed[i].second];
            lie += glm::dot(spot.normal, first) < 0.0f ? -spot.normal : spot.normal;
            lie_along += spot.along;
        }
        const bool alike = glm::length(lie) > kAlike * static_cast<float>(end - begin);
        const float facing = glm::dot(lie, centre - outward.middle());
        if (facing < 0.0f || (facing == 0.0f && glm::dot(lie, normal) < 0.0f)) lie = -lie;
        const float u[3] = {static_cast<float>(random.uniform()),
                            static_cast<float>(random.uniform()),
                            static_cast<float>(random.uniform())};
        // Leaned off the outward direction about a random axis across it.
        glm::vec3 side = std::abs(normal.y) < 0.9f ? glm::cross(normal, glm::vec3(0, 1, 0))
                                                   : glm::cross(normal, glm::vec3(1, 0, 0));
        side = turn(glm::normalize(side), normal, 2.0f * std::numbers::pi_v<float> * u[0]);
        normal = alike ? glm::normalize(lie) : glm::normalize(turn(normal, side, kMaxTilt * u[1]));
        // Its length runs upwards where it can (as leaves hang from twigs), turned a little.
        glm::vec3 along = glm::vec3(0, 1, 0) - normal.y * normal;
        if (glm::length(along) < 1e-3f) along = glm::cross(side, normal);
        along =
            glm::normalize(turn(glm::normalize(along), normal, kMaxTurn * (2.0f * u[2] - 1.0f)));
        if (alike) {
            const glm::vec3 a = lie_along - glm::dot(lie_along, normal) * normal;
            if (glm::length(a) > 1e-4f) along = glm::normalize(a);
        }
        const glm::vec3 across = glm::cross(normal, along);
        // As far along and across as its leaves reach.
        float half_length = 0.25f * cell, half_width = 0.25f * cell;
        for (std::size_t i = begin; i < end; ++i)
            for (std::uint32_t v : vertices[keyed[i].second]) {
                const glm::vec3 d = leaves.positions[v] - centre;
                half_length = std::max(half_length, kCover * std::abs(glm::dot(d, along)));
                half_width = std::max(half_width, kCover * std::abs(glm::dot(d, across)));
            }
        // In the open, no larger than its leaves allow.
        float leaf_area = 0.0f;
        for (std::size_t i = begin; i < end; ++i) leaf_area += spots[keyed[i].second].area;
        const float card_area = 2.0f * half_length * half_width;
        if (card_area > kOpenCover * leaf_area && !on_crown(at)) {
            const float shrink = std::sqrt(kOpenCover * leaf_area / card_area);
            half_length *= shrink;
            half_width *= shrink;
        }
        append_card(out, centre, along, across, half_length, half_width);
        begin = end;
    }
    return out;
}

}  // namespace sylva
