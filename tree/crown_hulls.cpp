#include "tree/crown_hulls.h"

#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <limits>
#include <vector>

#include "core/convex_hull.h"
#include "core/disjoint_sets.h"
#include "core/mesh_checks.h"
#include "lowpoly/merge_meshes.h"
#include "tree/hull_gap.h"

namespace sylva {
namespace {

// The nearest of `centers` to p (the first of equals).
std::uint32_t nearest_center(const glm::vec3& p, const std::vector<glm::vec3>& centers) {
    std::uint32_t best = 0;
    float best_d = std::numeric_limits<float>::max();
    for (std::uint32_t c = 0; c < centers.size(); ++c) {
        const glm::vec3 d = p - centers[c];
        const float d2 = glm::dot(d, d);
        if (d2 < best_d) {
            best_d = d2;
            best = c;
        }
    }
    return best;
}

// k-means finds its centres on every n-th point, at most this many of them.
constexpr std::size_t kMeansSample = 2048;

// The n of kMeansSample for `points` points.
std::size_t sample_stride(std::size_t points) {
    return (points + kMeansSample - 1) / kMeansSample;
}

struct KMeans {
    std::vector<glm::vec3> centers;
    std::vector<std::uint32_t> sample_cluster;  // of every sample_stride()-th point
};

// Lloyd's k-means on `points`, seeded by farthest-point sampling from the first point
// (deterministic), on every sample_stride()-th point (a marching-cubes crown lists its
// vertices in space order, so the sample covers it evenly).
KMeans k_means_on_sample(const std::vector<glm::vec3>& all, std::size_t k) {
    std::vector<glm::vec3> sample;
    const std::size_t stride = sample_stride(all.size());
    for (std::size_t i = 0; i < all.size(); i += stride) sample.push_back(all[i]);
    const std::vector<glm::vec3>& points = sample;
    std::vector<glm::vec3> centers{points.front()};
    std::vector<float> nearest(points.size(), std::numeric_limits<float>::max());
    while (centers.size() < k) {
        std::size_t far = 0;
        for (std::size_t i = 0; i < points.size(); ++i) {
            nearest[i] = std::min(nearest[i], glm::distance(points[i], centers.back()));
            if (nearest[i] > nearest[far]) far = i;
        }
        if (nearest[far] <= 0.0f) break;
        centers.push_back(points[far]);
    }
    std::vector<std::uint32_t> cluster(points.size(), 0);
    for (int round = 0; round < 20; ++round) {
        bool changed = false;
        for (std::size_t i = 0; i < points.size(); ++i) {
            const std::uint32_t best = nearest_center(points[i], centers);
            changed |= cluster[i] != best;
            cluster[i] = best;
        }
        if (!changed && round > 0) break;
        std::vector<glm::vec3> sum(centers.size(), glm::vec3(0.0f));
        std::vector<std::size_t> count(centers.size(), 0);
        for (std::size_t i = 0; i < points.size(); ++i) {
            sum[cluster[i]] += points[i];
            ++count[cluster[i]];
        }
        for (std::size_t c = 0; c < centers.size(); ++c)
            if (count[c] > 0) centers[c] = sum[c] / static_cast<float>(count[c]);
    }
    return {std::move(centers), std::move(cluster)};
}

// The cluster of each of `all` by k_means_on_sample(): the sample's own, every other point's
// its nearest centre.
std::vector<std::uint32_t> assign_all(const std::vector<glm::vec3>& all, KMeans fit) {
    if (sample_stride(all.size()) == 1) return std::move(fit.sample_cluster);
    std::vector<std::uint32_t> of_all(all.size());
    for (std::size_t i = 0; i < all.size(); ++i) of_all[i] = nearest_center(all[i], fit.centers);
    return of_all;
}

std::vector<std::uint32_t> k_means(const std::vector<glm::vec3>& all, std::size_t k) {
    return assign_all(all, k_means_on_sample(all, k));
}

// `cluster` (of each used vertex, in `points` order) with every cluster whose vertices lie on
// surface pieces apart from each other (two curtains of a willow, two blobs of a honda)
// split into one cluster per piece of at least kApartShare of its vertices: the hull of
// both would bridge the gap between them. Smaller pieces stay with the cluster's largest.
// `index` maps a mesh vertex to its place in `points` (or -1 when unused); `most` caps the
// clusters in all.
std::vector<std::uint32_t> apart_clusters(const Mesh& crown, const std::vector<std::int64_t>& index,
                                          std::vector<std::uint32_t> cluster, std::size_t most) {
    constexpr double kApartShare = 0.1;
    DisjointSets pieces(cluster.size());
    for (const auto& t : crown.triangles)
        for (int k = 0; k < 3; ++k) {
            const auto a = static_cast<std::size_t>(index[t[k]]);
            const auto b = static_cast<std::size_t>(index[t[(k + 1) % 3]]);
            if (cluster[a] == cluster[b])
                pieces.unite(static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b));
        }
    std::vector<std::size_t> size(cluster.size(), 0), in_cluster(cluster.size(), 0);
    for (std::size_t i = 0; i < cluster.size(); ++i) {
        ++size[pieces.find(static_cast<std::uint32_t>(i))];
        ++in_cluster[cluster[i]];
    }
    // Each cluster's largest piece keeps its number; other large pieces get new ones.
    std::vector<std::size_t> largest(cluster.size(), SIZE_MAX);
    for (std::size_t i = 0; i < cluster.size(); ++i) {
        const std::size_t root = pieces.find(static_cast<std::uint32_t>(i));
        std::size_t& best = largest[cluster[i]];
        if (best == SIZE_MAX || size[root] > size[best] ||
            (size[root] == size[best] && root < best))
            best = root;
    }
    // The pieces that become clusters of their own, largest first, up to `pieces` clusters in
    // all: each hull takes a share of the crown's triangles.
    std::vector<std::size_t> apart;
    for (std::size_t i = 0; i < cluster.size(); ++i) {
        const std::size_t root = pieces.find(static_cast<std::uint32_t>(i));
        if (root == i && root != largest[cluster[i]] &&
            static_cast<double>(size[root]) >=
                kApartShare * static_cast<double>(in_cluster[cluster[i]]))
            apart.push_back(root);
    }
    std::sort(apart.begin(), apart.end(), [&](std::size_t a, std::size_t b) {
        return size[a] != size[b] ? size[a] > size[b] : a < b;
    });
    std::uint32_t next = *std::max_element(cluster.begin(), cluster.end()) + 1;
    apart.resize(std::min<std::size_t>(apart.size(), most > next ? most - next : 0));
    std::vector<std::int64_t> renamed(cluster.size(), -1);
    for (const std::size_t root : apart) renamed[root] = next++;
    for (std::size_t i = 0; i < cluster.size(); ++i) {
        const std::int64_t name = renamed[pieces.find(static_cast<std::uint32_t>(i))];
        if (name >= 0) cluster[i] = static_cast<std::uint32_t>(name);
    }
    return cluster;
}

// The height stretches k-means is tried with: clusters of points whose heights count more are
// flatter, and a flat cluster's hull does not reach across the gap between two tiers.
constexpr std::array<float, 2> kHeightStretches{1.0f, 1.5f};
// A stretched clustering replaces the plain one only where its hulls fill less than this share of
// the plain one's gap: a small difference is within what the sampled measure and k-means' seeds
// vary by, and then the rounder clusters read better (an oak's lumps, a windswept crown at 200).
constexpr double kClearlyLess = 0.75;
// The gap is measured on grid cells this many times as wide as k-means' sample points lie apart
// on the crown's surface: finer, a solid lump's sample leaves cells empty and shows gaps of its
// own; coarser, the cells cover the gaps between a tier's blobs.
constexpr double kGapCell = 0.7;
// apart_clusters() of k-means with the kHeightStretches the gap its hulls fill chooses
// (tree/hull_gap.h, summed over the clusters of k-means' sample, on cells of kGapCell): the
// least, a later stretch only when clearly less (kClearlyLess). The clusters are compared before
// apart_clusters() splits them, and on the sample alone, so the choice costs a k-means on the
// sample per stretch.
std::vector<std::uint32_t> least_gap_clusters(const Mesh& crown,
                                              const std::vector<std::int64_t>& index,
                                              const std::vector<glm::vec3>& points,
                                              std::size_t hulls, std::size_t pieces) {
    if (hulls < 2) return apart_clusters(crown, index, k_means(points, hulls), pieces);
    const double area = surface_area(crown);
    const std::size_t stride = sample_stride(points.size());
    const auto cell = static_cast<float>(kGapCell * std::sqrt(area * static_cast<double>(stride) /
                                                              static_cast<double>(points.size())));
    std::array<std::vector<glm::vec3>, kHeightStretches.size()> stretched;
    std::array<KMeans, kHeightStretches.size()> fits;
    std::array<double, kHeightStretches.size()> gaps{};
    // A stretch on each core (at 800 the hulls are made while the other core has nothing to
    // do); the choice below is made in order, so it does not depend on timing.
    tbb::parallel_for(std::size_t{0}, kHeightStretches.size(), [&](std::size_t s) {
        stretched[s].resize(points.size());
        for (std::size_t i = 0; i < points.size(); ++i)
            stretched[s][i] =
                glm::vec3(points[i].x, kHeightStretches[s] * points[i].y, points[i].z);
        fits[s] = k_means_on_sample(stretched[s], hulls);
        std::vector<std::vector<glm::vec3>> members(fits[s].centers.size());
        for (std::size_t j = 0; j < fits[s].sample_cluster.size(); ++j)
            members[fits[s].sample_cluster[j]].push_back(points[j * stride]);
        for (const std::vector<glm::vec3>& m : members) gaps[s] += hull_gap(m, cell);
    });
    std::size_t best = 0;
    for (std::size_t s = 1; s < kHeightStretches.size(); ++s)
        if (gaps[s] < kClearlyLess * gaps[best]) best = s;
    return apart_clusters(crown, index, assign_all(stretched[best], std::move(fits[best])), pieces);
}

}  // namespace

Mesh crown_hulls(const Mesh& crown, std::size_t hulls, std::size_t pieces) {
    std::vector<bool> used(crown.positions.size(), false);
    for (const auto& t : crown.triangles) used[t[0]] = used[t[1]] = used[t[2]] = true;
    std::vector<glm::vec3> points;
    std::vector<std::int64_t> index(crown.positions.size(), -1);
    for (std::size_t v = 0; v < crown.positions.size(); ++v)
        if (used[v]) {
            index[v] = static_cast<std::int64_t>(points.size());
            points.push_back(crown.positions[v]);
        }
    if (points.size() < 4 || hulls == 0) return crown;
    const std::vector<std::uint32_t> cluster =
        least_gap_clusters(crown, index, points, hulls, pieces);
    const std::uint32_t clusters = *std::max_element(cluster.begin(), cluster.end()) + 1;
    std::vector<Mesh> hull_meshes;
    for (std::uint32_t c = 0; c < clusters; ++c) {
        std::vector<glm::vec3> members;
        for (std::size_t i = 0; i < points.size(); ++i)
            if (cluster[i] == c) members.push_back(points[i]);
        if (members.empty()) continue;  // a centre no point is nearest to
        hull_meshes.push_back(extreme_point_hull(members));
        if (hull_meshes.back().triangles.empty()) return crown;  // flat: keep the blobs
    }
    std::vector<const Mesh*> pointers;
    for (const Mesh& m : hull_meshes) pointers.push_back(&m);
    return merge_meshes(pointers);
}

}  // namespace sylva
