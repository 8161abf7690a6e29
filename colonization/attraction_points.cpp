#include "colonization/attraction_points.h"

#include <cmath>

#include "core/random.h"

namespace sylva {
namespace {

// The radical inverse of i in `base`: the Halton sequence's coordinate.
double radical_inverse(std::uint64_t i, std::uint64_t base) {
    double inverse = 1.0 / static_cast<double>(base), factor = inverse, result = 0.0;
    for (; i > 0; i /= base, factor *= inverse) result += factor * static_cast<double>(i % base);
    return result;
}

}  // namespace

std::vector<glm::vec3> attraction_points(const Envelope& envelope, int count,
                                         PointDistribution distribution, std::uint64_t seed) {
    return attraction_points(region(envelope), count, distribution, seed);
}

std::vector<glm::vec3> attraction_points(const Region& region, int count,
                                         PointDistribution distribution, std::uint64_t seed) {
    std::vector<glm::vec3> points;
    if (count <= 0) return points;
    points.reserve(static_cast<size_t>(count));
    const Box box = region.bounds;
    const glm::vec3 extent = box.max - box.min;
    Random random(seed);
    // Cranley-Patterson rotation: the seed shifts the sequence, so seeds differ while the
    // points stay evenly spread.
    const double shift[3] = {random.uniform(), random.uniform(), random.uniform()};
    const std::uint64_t tries = 100ull * static_cast<std::uint64_t>(count);
    for (std::uint64_t i = 1; i <= tries && points.size() < static_cast<size_t>(count); ++i) {
        double u[3];
        if (distribution == PointDistribution::Halton) {
            const std::uint64_t bases[3] = {2, 3, 5};
            for (int k = 0; k < 3; ++k) {
                u[k] = radical_inverse(i, bases[k]) + shift[k];
                u[k] -= std::floor(u[k]);
            }
        } else {
            for (double& v : u) v = random.uniform();
        }
        const glm::vec3 p =
            box.min + extent * glm::vec3(static_cast<float>(u[0]), static_cast<float>(u[1]),
                                         static_cast<float>(u[2]));
        if (region.contains(p)) points.push_back(p);
    }
    return points;
}

}  // namespace sylva
