#include "forest/poisson_disk.h"

#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <limits>
#include <string>

#include "core/errors.h"
#include "core/random.h"

namespace sylva::forest {

namespace {

// A figure as a person reads it, however large: "3.2e+617" never comes out as an integer.
std::string number_text(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

}  // namespace

std::vector<glm::dvec2> poisson_disk(glm::dvec2 lo, glm::dvec2 hi,
                                     const PoissonSettings& settings) {
    const double r = settings.min_distance;
    if (!(r > 0.0) || !std::isfinite(r))
        throw InputError("the minimum spacing must be a positive number of meters");
    const glm::dvec2 size = hi - lo;
    if (!std::isfinite(size.x) || !std::isfinite(size.y))
        throw InputError("the area to plant must be finite (its sides measure " +
                         number_text(size.x) + " x " + number_text(size.y) + " m)");
    if (!(size.x > 0.0 && size.y > 0.0)) return {};
    // A disk packing holds at most ~1.15 / r^2 points per square meter. In doubles: the
    // figure may be far past any integer (1e308 m sides, a spacing of 1e-300 m), and it bounds
    // the grid's sides below (each at most sqrt(2) * expected cells).
    const double expected = 1.2 * ((size.x + r) / r) * ((size.y + r) / r);
    if (!(expected <= static_cast<double>(settings.max_points)) ||
        !(expected <= static_cast<double>(std::numeric_limits<int>::max() / 2)))
        throw InputError("a spacing of " + number_text(r) + " m on this area would plant " +
                         (std::isfinite(expected) ? "about " + number_text(expected)
                                                  : std::string("more than 1e+308")) +
                         " trees; the limit is " + std::to_string(settings.max_points));

    const double cell = r / std::sqrt(2.0);
    const int nx = std::max(1, static_cast<int>(std::ceil(size.x / cell)));
    const int ny = std::max(1, static_cast<int>(std::ceil(size.y / cell)));
    std::vector<int> grid(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny), -1);
    auto cell_of = [&](glm::dvec2 p) {
        const int cx = std::min(nx - 1, static_cast<int>((p.x - lo.x) / cell));
        const int cy = std::min(ny - 1, static_cast<int>((p.y - lo.y) / cell));
        return glm::ivec2(cx, cy);
    };

    Random random(settings.seed);
    std::vector<glm::dvec2> points;
    std::vector<std::size_t> active;
    auto add = [&](glm::dvec2 p) {
        const glm::ivec2 c = cell_of(p);
        grid[static_cast<std::size_t>(c.y) * static_cast<std::size_t>(nx) +
             static_cast<std::size_t>(c.x)] = static_cast<int>(points.size());
        active.push_back(points.size());
        points.push_back(p);
    };
    auto far_enough = [&](glm::dvec2 p) {
        const glm::ivec2 c = cell_of(p);
        for (int y = std::max(0, c.y - 2); y <= std::min(ny - 1, c.y + 2); ++y)
            for (int x = std::max(0, c.x - 2); x <= std::min(nx - 1, c.x + 2); ++x) {
                const int q = grid[static_cast<std::size_t>(y) * static_cast<std::size_t>(nx) +
                                   static_cast<std::size_t>(x)];
                if (q >= 0 && glm::distance(points[static_cast<std::size_t>(q)], p) < r)
                    return false;
            }
        return true;
    };

    add(lo + glm::dvec2(random.uniform(), random.uniform()) * size);
    while (!active.empty()) {
        const std::size_t pick =
            static_cast<std::size_t>(random.uniform() * static_cast<double>(active.size()));
        const glm::dvec2 centre = points[active[pick]];
        bool found = false;
        for (int k = 0; k < settings.attempts; ++k) {
            // Uniform in the annulus [r, 2r] by area.
            const double angle = 2.0 * M_PI * random.uniform();
            const double radius = r * std::sqrt(1.0 + 3.0 * random.uniform());
            const glm::dvec2 p = centre + radius * glm::dvec2(std::cos(angle), std::sin(angle));
            if (p.x < lo.x || p.y < lo.y || p.x > hi.x || p.y > hi.y || !far_enough(p)) continue;
            add(p);
            found = true;
            break;
        }
        if (!found) {
            active[pick] = active.back();
            active.pop_back();
        }
    }
    return points;
}

}  // namespace sylva::forest
