#include "lowpoly/fidelity.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "core/errors.h"
#include "lowpoly/surface_sampling.h"
#include "lowpoly/triangle_bvh.h"

namespace sylva {

Fidelity measure_fidelity(const Mesh& reduced, const Mesh& reference,
                          const FidelitySettings& settings) {
    if (reference.triangles.empty())
        throw InputError("measure_fidelity: the reference mesh has no triangles");
    double height = settings.height;
    if (height == 0.0) {
        float lo = std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::lowest();
        for (const glm::vec3& p : reference.positions) {
            lo = std::min(lo, p.y);
            hi = std::max(hi, p.y);
        }
        height = static_cast<double>(hi) - lo;
    }
    if (!(height > 0.0)) throw InputError("measure_fidelity: the height to compare against is 0");

    const TriangleBvh bvh(reference);
    const std::vector<glm::vec3> points = sample_surface(reduced, settings.samples, settings.seed);
    Fidelity f;
    f.height = height;
    f.samples = points.size();
    double sum = 0.0;
    for (const glm::vec3& p : points) {
        const double d = bvh.distance(p);
        sum += d;
        f.max = std::max(f.max, d);
    }
    if (!points.empty()) f.mean = sum / static_cast<double>(points.size());
    f.mean_percent = 100.0 * f.mean / height;
    f.max_percent = 100.0 * f.max / height;
    return f;
}

}  // namespace sylva
