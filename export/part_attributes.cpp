#include "export/part_attributes.h"

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <numeric>
#include <span>

#include "core/disjoint_sets.h"
#include "core/random.h"

namespace sylva {
namespace {

constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;

// A number in [0, 1) from a key and the seed, the same on every machine.
float hash01(std::uint64_t key, std::uint64_t seed) {
    Random random(seed * 0x9e3779b97f4a7c15ULL ^ key);
    return static_cast<float>(random.uniform());
}

std::uint64_t position_key(const glm::vec3& p) {
    std::uint32_t bits[3];
    std::memcpy(bits, &p, sizeof bits);
    return (std::uint64_t(bits[0]) * 0x9e3779b1u) ^ (std::uint64_t(bits[1]) << 21) ^
           (std::uint64_t(bits[2]) << 42) ^ bits[2];
}

float sway(const glm::vec3& p, const TreeFrame& frame) {
    const float h =
        std::clamp((p.y - frame.ground) / std::max(frame.top - frame.ground, 1e-6f), 0.0f, 1.0f);
    return h * h;
}

// Per-piece variation times crown occlusion; empty when both are off.
glm::vec3 tint(const glm::vec3& p, float piece_hash, const TreeFrame& frame,
               const EngineSettings& settings) {
    const float v = std::clamp(settings.color_variation, 0.0f, 1.0f);
    const float r1 = piece_hash, r2 = std::fmod(piece_hash * 7.31f, 1.0f),
                r3 = std::fmod(piece_hash * 13.7f, 1.0f);
    glm::vec3 t = glm::vec3(1.0f - 0.35f * v * r1) *
                  glm::vec3(1.0f - 0.2f * v * r2, 1.0f, 1.0f - 0.2f * v * r3);
    const float occlusion = std::clamp(settings.crown_occlusion, 0.0f, 1.0f);
    const float depth =
        1.0f - glm::length((p - frame.crown_center) / glm::max(frame.crown_half_extent, 1e-6f));
    t *= 1.0f - 0.6f * occlusion * std::clamp(depth, 0.0f, 1.0f);
    return glm::clamp(t, 0.0f, 1.0f);
}

bool wants_tint(const EngineSettings& s) {
    return s.color_variation > 0.0f || s.crown_occlusion > 0.0f;
}

// Pieces: the sets of vertices joined by triangles; each vertex's piece is its set's
// smallest vertex index.
std::vector<std::uint32_t> pieces(const Mesh& mesh) {
    DisjointSets sets(mesh.positions.size());
    for (const auto& t : mesh.triangles) {
        sets.unite(t[0], t[1]);
        sets.unite(t[0], t[2]);
    }
    std::vector<std::uint32_t> smallest(mesh.positions.size(), UINT32_MAX);
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
        std::uint32_t& s = smallest[sets.find(v)];
        s = std::min(s, v);
    }
    std::vector<std::uint32_t> piece(mesh.positions.size());
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) piece[v] = smallest[sets.find(v)];
    return piece;
}

// Per-vertex values to per-corner UVs.
std::vector<std::array<glm::vec2, 3>> corner_uvs(const Mesh& mesh,
                                                 const std::vector<glm::vec2>& uv) {
    std::vector<std::array<glm::vec2, 3>> out;
    out.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles) out.push_back({uv[t[0]], uv[t[1]], uv[t[2]]});
    return out;
}

// The skeleton as branches: a segment continues its parent's branch when it has the
// parent's depth, else it starts a branch of its own.
struct Branches {
    std::vector<int> root;         // per segment: the first segment of its branch
    std::vector<float> start;      // per segment: branch length before it, metres
    std::vector<glm::vec3> dir;    // per segment: unit axis
    std::vector<float> length;     // per segment
    std::vector<glm::vec3> ref;    // per segment: where u = 0.5 points, transported along
    std::vector<float> total;      // per root: the branch's length
    std::vector<int> repeats;      // per root: u repeats around it
    std::vector<float> base_flex;  // per root: the parent's flex where it starts
    std::vector<float> phase;      // per root
};

Branches branches(const Skeleton& skeleton, std::uint64_t seed) {
    const auto& segs = skeleton.segments;
    const std::size_t n = segs.size();
    Branches b{std::vector<int>(n),    std::vector<float>(n),       std::vector<glm::vec3>(n),
               std::vector<float>(n),  std::vector<glm::vec3>(n),   std::vector<float>(n, 0.0f),
               std::vector<int>(n, 1), std::vector<float>(n, 0.0f), std::vector<float>(n, 0.0f)};
    auto continues = [&](std::size_t i) {
        const int p = segs[i].parent;
        return p >= 0 && static_cast<std::size_t>(p) < i &&
               segs[static_cast<std::size_t>(p)].depth == segs[i].depth;
    };
    for (std::size_t i = 0; i < n; ++i) {
        const Segment& s = segs[i];
        const glm::vec3 d = s.b - s.a;
        b.length[i] = glm::length(d);
        b.dir[i] = b.length[i] > 0.0f ? d / b.length[i] : glm::vec3(0, 1, 0);
        glm::vec3 base(0, 0, 1);
        if (continues(i)) {
            const auto p = static_cast<std::size_t>(s.parent);
            b.root[i] = b.root[p];
            b.start[i] = b.start[p] + b.length[p];
            base = b.ref[p];
        } else {
            b.root[i] = static_cast<int>(i);
        }
        glm::vec3 r = base - glm::dot(base, b.dir[i]) * b.dir[i];
        if (glm::length(r) < 1e-4f) {
            base = glm::vec3(1, 0, 0);
            r = base - glm::dot(base, b.dir[i]) * b.dir[i];
        }
        b.ref[i] = glm::normalize(r);
        const auto root = static_cast<std::size_t>(b.root[i]);
        b.total[root] = std::max(b.total[root], b.start[i] + b.length[i]);
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (b.root[i] != static_cast<int>(i)) continue;
        const float circumference = kTwoPi * std::max(segs[i].ra, segs[i].rb);
        b.repeats[i] = std::max(1, static_cast<int>(std::lround(circumference / kBarkTile)));
        const int p = segs[i].parent;
        if (p < 0 || static_cast<std::size_t>(p) >= i || segs[i].depth == 0) {
            b.phase[i] = hash01(i, seed);
            continue;
        }
        // Parents come first, so their root's values are set.
        const auto pr = static_cast<std::size_t>(b.root[static_cast<std::size_t>(p)]);
        const float along =
            b.start[static_cast<std::size_t>(p)] + b.length[static_cast<std::size_t>(p)];
        const bool on_trunk = segs[pr].depth == 0;
        b.base_flex[i] = on_trunk
                             ? 0.0f
                             : b.base_flex[pr] +
                                   (1.0f - b.base_flex[pr]) *
                                       std::clamp(along / std::max(b.total[pr], 1e-6f), 0.0f, 1.0f);
        b.phase[i] = on_trunk ? hash01(i, seed) : b.phase[pr];
    }
    return b;
}

// Distance from p to segment s's surface (its tapered capsule).
float surface_distance(const Segment& s, const glm::vec3& p) {
    const glm::vec3 d = s.b - s.a;
    const float len2 = glm::dot(d, d);
    const float t = len2 > 0.0f ? std::clamp(glm::dot(p - s.a, d) / len2, 0.0f, 1.0f) : 0.0f;
    return std::abs(glm::length(p - (s.a + t * d)) - (s.ra + t * (s.rb - s.ra)));
}

// A uniform grid of the segments' padded boxes, for nearest-segment queries.
class SegmentGrid {
  public:
    explicit SegmentGrid(const Skeleton& skeleton) : segs_(skeleton.segments) {
        if (segs_.empty()) return;
        lo_ = glm::vec3(std::numeric_limits<float>::max());
        glm::vec3 hi(std::numeric_limits<float>::lowest());
        for (const Segment& s : segs_) {
            lo_ = glm::min(lo_, glm::min(s.a, s.b));
            hi = glm::max(hi, glm::max(s.a, s.b));
        }
        const glm::vec3 size = hi - lo_;
        cell_ = std::max({size.x, size.y, size.z, 1e-3f}) / 32.0f;
        lo_ -= glm::vec3(cell_);
        dims_ = glm::ivec3((hi + glm::vec3(cell_) - lo_) / cell_) + 1;
        // Each segment's cells, then a counting sort into one array (segments in order
        // within a cell): two passes over the boxes instead of a vector per cell.
        auto for_each_cell = [&](std::size_t i, auto&& f) {
            const Segment& s = segs_[i];
            const float pad = 1.5f * std::max(s.ra, s.rb) + cell_;
            const glm::ivec3 a = cell_of(glm::min(s.a, s.b) - pad),
                             b = cell_of(glm::max(s.a, s.b) + pad);
            for (int z = a.z; z <= b.z; ++z)
                for (int y = a.y; y <= b.y; ++y)
                    for (int x = a.x; x <= b.x; ++x) f(index(glm::ivec3(x, y, z)));
        };
        start_.assign(static_cast<std::size_t>(dims_.x) * dims_.y * dims_.z + 1, 0);
        for (std::size_t i = 0; i < segs_.size(); ++i)
            for_each_cell(i, [&](std::size_t c) { ++start_[c + 1]; });
        std::partial_sum(start_.begin(), start_.end(), start_.begin());
        items_.resize(start_.back());
        std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
        for (std::size_t i = 0; i < segs_.size(); ++i)
            for_each_cell(i, [&](std::size_t c) { items_[fill[c]++] = static_cast<int>(i); });
    }

    int nearest(const glm::vec3& p) const {
        if (segs_.empty()) return -1;
        const std::size_t c = index(cell_of(p));
        const std::span<const int> near(items_.data() + start_[c], start_[c + 1] - start_[c]);
        int best = -1;
        float best_d = std::numeric_limits<float>::max();
        auto consider = [&](int i) {
            const float d = surface_distance(segs_[static_cast<std::size_t>(i)], p);
            if (d < best_d) best_d = d, best = i;
        };
        if (!near.empty()) {
            for (int i : near) consider(i);
        } else {
            for (std::size_t i = 0; i < segs_.size(); ++i) consider(static_cast<int>(i));
        }
        return best;
    }

  private:
    glm::ivec3 cell_of(const glm::vec3& p) const {
        return glm::clamp(glm::ivec3(glm::floor((p - lo_) / cell_)), glm::ivec3(0), dims_ - 1);
    }
    std::size_t index(const glm::ivec3& c) const {
        return (static_cast<std::size_t>(c.z) * dims_.y + c.y) * dims_.x + c.x;
    }

    const std::vector<Segment>& segs_;
    glm::vec3 lo_{0.0f};
    float cell_ = 1.0f;
    glm::ivec3 dims_{1};
    std::vector<std::uint32_t> start_;  // cell c's segments: items_[start_[c] .. start_[c + 1])
    std::vector<int> items_;
};

// Bark UV of p on segment s: u around (before the seam fix), v along in tiles.
glm::vec2 bark_uv(const Branches& b, std::size_t s, const Segment& seg, const glm::vec3& p) {
    const glm::vec3 rel = p - seg.a;
    const float along = glm::dot(rel, b.dir[s]);
    const glm::vec3 side = glm::cross(b.dir[s], b.ref[s]);
    // atan2 is +-pi on -ref: the seam runs there.
    const float angle = std::atan2(glm::dot(rel, side), glm::dot(rel, b.ref[s]));
    const auto root = static_cast<std::size_t>(b.root[s]);
    return {static_cast<float>(b.repeats[root]) * (angle / kTwoPi + 0.5f),
            (b.start[s] + along) / kBarkTile};
}

}  // namespace

TreeFrame tree_frame(const Mesh& trunk, const Mesh& crown, const Mesh& leaves) {
    TreeFrame frame;
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    glm::vec3 clo = lo, chi = hi;
    for (const Mesh* m : {&trunk, &crown, &leaves})
        for (const glm::vec3& p : m->positions) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
            if (m != &trunk) clo = glm::min(clo, p), chi = glm::max(chi, p);
        }
    if (lo.x > hi.x) return frame;  // no vertex at all
    if (clo.x > chi.x) clo = lo, chi = hi;
    frame.ground = lo.y;
    frame.top = hi.y;
    frame.crown_center = 0.5f * (clo + chi);
    frame.crown_half_extent = 0.5f * (chi - clo);
    return frame;
}

namespace {

// On every core: each vertex scans the segments of its cell, which is slow on a dense twig
// tree's trunk.
std::vector<int> owning_segments(const Mesh& mesh, const SegmentGrid& grid) {
    std::vector<int> owner(mesh.positions.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, owner.size(), 256), [&](const auto& r) {
        for (std::size_t v = r.begin(); v < r.end(); ++v)
            owner[v] = grid.nearest(mesh.positions[v]);
    });
    return owner;
}

// Triangle i's bark UVs: its corners' on their segments, a fork's all on the branch of its
// middle, spanning the shorter way round the branch.
std::array<glm::vec2, 3> bark_uvs(const Branches& b, const Skeleton& skeleton,
                                  const SegmentGrid& grid, const std::vector<int>& owner,
                                  const Mesh& trunk, std::size_t triangle) {
    const auto& segs = skeleton.segments;
    const auto& t = trunk.triangles[triangle];
    auto root_of = [&](int s) { return s < 0 ? -1 : b.root[static_cast<std::size_t>(s)]; };
    std::array<glm::vec2, 3> uv{};
    // A fork's triangles take the branch of their middle, all three corners alike.
    int s = owner[t[0]];
    if (root_of(owner[t[1]]) != root_of(s) || root_of(owner[t[2]]) != root_of(s))
        s = grid.nearest((trunk.positions[t[0]] + trunk.positions[t[1]] + trunk.positions[t[2]]) /
                         3.0f);
    if (s >= 0) {
        for (std::size_t k = 0; k < 3; ++k) {
            const int own = root_of(owner[t[k]]) == root_of(s) ? owner[t[k]] : s;
            uv[k] = bark_uv(b, static_cast<std::size_t>(own), segs[static_cast<std::size_t>(own)],
                            trunk.positions[t[k]]);
        }
        // No triangle wraps around the branch: it spans the shorter way round,
        // the complement of the widest gap between its corners' u on the circle.
        const float repeats = static_cast<float>(b.repeats[static_cast<std::size_t>(root_of(s))]);
        std::array<std::size_t, 3> order{0, 1, 2};
        std::sort(order.begin(), order.end(),
                  [&](std::size_t i, std::size_t j) { return uv[i].x < uv[j].x; });
        const float lo = uv[order[0]].x, mid = uv[order[1]].x, hi = uv[order[2]].x;
        const float gap_low = mid - lo, gap_high = hi - mid, gap_wrap = repeats - (hi - lo);
        if (gap_low > gap_wrap && gap_low >= gap_high) {
            uv[order[0]].x += repeats;
        } else if (gap_high > gap_wrap && gap_high > gap_low) {
            uv[order[0]].x += repeats;
            uv[order[1]].x += repeats;
        }
    }
    return uv;
}

}  // namespace

std::vector<int> owning_segments(const Mesh& mesh, const Skeleton& skeleton) {
    return owning_segments(mesh, SegmentGrid(skeleton));
}

PartAttributes trunk_attributes(const Mesh& trunk, const Skeleton& skeleton, const TreeFrame& frame,
                                const EngineSettings& settings) {
    PartAttributes out;
    const Branches b = branches(skeleton, settings.seed);
    const SegmentGrid grid(skeleton);
    const std::vector<int> owner = owning_segments(trunk, grid);
    const auto& segs = skeleton.segments;
    const std::size_t n = trunk.positions.size();

    if (settings.uvs) {
        // Each triangle alone, on every core (a fork's looks up its nearest segment again).
        out.uv.resize(trunk.triangles.size());
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, trunk.triangles.size(), 256),
                          [&](const auto& r) {
                              for (std::size_t i = r.begin(); i < r.end(); ++i)
                                  out.uv[i] = bark_uvs(b, skeleton, grid, owner, trunk, i);
                          });
    }
    if (settings.wind || wants_tint(settings)) {
        if (settings.wind) out.wind.resize(n);
        if (wants_tint(settings)) out.tint.resize(n);
        for (std::size_t v = 0; v < n; ++v) {
            const glm::vec3& p = trunk.positions[v];
            const int s = owner[v];
            float flex = 0.0f, phase = 0.0f, piece = 0.0f;
            if (s >= 0) {
                const auto si = static_cast<std::size_t>(s);
                const auto root = static_cast<std::size_t>(b.root[si]);
                const float along = b.start[si] + glm::dot(p - segs[si].a, b.dir[si]);
                if (segs[si].depth > 0)
                    flex = b.base_flex[root] +
                           (1.0f - b.base_flex[root]) *
                               std::clamp(along / std::max(b.total[root], 1e-6f), 0.0f, 1.0f);
                phase = b.phase[root];
                piece = hash01(root, settings.seed + 1);
            }
            if (settings.wind) out.wind[v] = {sway(p, frame), flex, phase, 0.0f};
            if (wants_tint(settings)) out.tint[v] = tint(p, piece, frame, settings);
        }
    }
    return out;
}

PartAttributes crown_attributes(const Mesh& crown, const TreeFrame& frame,
                                const EngineSettings& settings) {
    PartAttributes out;
    if (settings.uvs) {
        out.uv.reserve(crown.triangles.size());
        for (const auto& t : crown.triangles) {
            const glm::vec3 a = crown.positions[t[0]], b = crown.positions[t[1]],
                            c = crown.positions[t[2]];
            const glm::vec3 n = glm::abs(glm::cross(b - a, c - a));
            // The axis plane the triangle faces most: drop that axis.
            const int axis = n.x >= n.y && n.x >= n.z ? 0 : n.y >= n.z ? 1 : 2;
            std::array<glm::vec2, 3> uv{};
            for (std::size_t k = 0; k < 3; ++k) {
                const glm::vec3& p = crown.positions[t[k]];
                uv[k] = axis == 0   ? glm::vec2(p.z, p.y)
                        : axis == 1 ? glm::vec2(p.x, p.z)
                                    : glm::vec2(p.x, p.y);
                uv[k] /= kCrownTile;
            }
            out.uv.push_back(uv);
        }
    }
    if (settings.wind || wants_tint(settings)) {
        const std::vector<std::uint32_t> piece = pieces(crown);
        if (settings.wind) out.wind.resize(crown.positions.size());
        if (wants_tint(settings)) out.tint.resize(crown.positions.size());
        for (std::size_t v = 0; v < crown.positions.size(); ++v) {
            const glm::vec3& p = crown.positions[v];
            // A piece is known by its first vertex's place: the same piece in every level
            // of a LOD chain rarely keeps it, but the phase only has to differ between
            // pieces of one level.
            const std::uint64_t key = position_key(crown.positions[piece[v]]);
            if (settings.wind)
                out.wind[v] = {sway(p, frame), 0.5f, hash01(key, settings.seed), 0.0f};
            if (wants_tint(settings))
                out.tint[v] = tint(p, hash01(key, settings.seed + 1), frame, settings);
        }
    }
    return out;
}

PartAttributes leaf_attributes(const Mesh& leaves, const TreeFrame& frame,
                               const EngineSettings& settings) {
    PartAttributes out;
    const std::size_t n = leaves.positions.size();
    const std::vector<std::uint32_t> base = pieces(leaves);
    // Per leaf (by its base vertex): the farthest vertex's distance, the leaf's axis and
    // normal.
    std::vector<float> length(n, 0.0f);
    std::vector<glm::vec3> along(n, glm::vec3(0, 1, 0)), across(n, glm::vec3(1, 0, 0));
    for (std::size_t v = 0; v < n; ++v) {
        const glm::vec3 d = leaves.positions[v] - leaves.positions[base[v]];
        const float l = glm::length(d);
        if (l > length[base[v]]) length[base[v]] = l, along[base[v]] = d / l;
    }
    std::vector<bool> has_across(n, false);
    for (const auto& t : leaves.triangles) {
        const std::uint32_t leaf = base[t[0]];
        if (has_across[leaf]) continue;
        const glm::vec3 normal = glm::cross(leaves.positions[t[1]] - leaves.positions[t[0]],
                                            leaves.positions[t[2]] - leaves.positions[t[0]]);
        const glm::vec3 side = glm::cross(normal, along[leaf]);
        if (glm::length(side) > 0.0f) {
            across[leaf] = glm::normalize(side);
            has_across[leaf] = true;
        }
    }
    std::vector<glm::vec2> uv(n);
    for (std::size_t v = 0; v < n; ++v) {
        const std::uint32_t leaf = base[v];
        const glm::vec3 d = leaves.positions[v] - leaves.positions[leaf];
        const float l = std::max(length[leaf], 1e-6f);
        uv[v] = {std::clamp(0.5f + glm::dot(d, across[leaf]) / l, 0.0f, 1.0f),
                 std::clamp(glm::dot(d, along[leaf]) / l, 0.0f, 1.0f)};
    }
    if (settings.uvs) out.uv = corner_uvs(leaves, uv);
    if (settings.wind) out.wind.resize(n);
    if (wants_tint(settings)) out.tint.resize(n);
    for (std::size_t v = 0; v < n; ++v) {
        const glm::vec3& p = leaves.positions[v];
        const std::uint64_t key = position_key(leaves.positions[base[v]]);
        if (settings.wind)
            out.wind[v] = {sway(p, frame), 1.0f, hash01(key, settings.seed), uv[v].y};
        if (wants_tint(settings))
            out.tint[v] = tint(p, hash01(key, settings.seed + 1), frame, settings);
    }
    return out;
}

}  // namespace sylva
