#include "colonization/envelope.h"

#include <algorithm>

namespace sylva {
namespace {

glm::vec3 extents(const Envelope& envelope) {
    if (envelope.shape != EnvelopeShape::Sphere) return envelope.size;
    const float d = std::max({envelope.size.x, envelope.size.y, envelope.size.z});
    return glm::vec3(d);
}

}  // namespace

bool inside(const Envelope& envelope, const glm::vec3& p) {
    const glm::vec3 size = extents(envelope);
    const glm::vec3 half = 0.5f * size;
    // Local coordinates: x and z relative to the axis, y from the bottom, all in [-1, 1]
    // or [0, 1] of the solid's extent.
    const float x = (p.x - envelope.base.x) / half.x;
    const float z = (p.z - envelope.base.z) / half.z;
    const float t = (p.y - envelope.base.y) / size.y;  // 0 at the bottom, 1 at the top
    const float radial = x * x + z * z;
    switch (envelope.shape) {
        case EnvelopeShape::Sphere:
        case EnvelopeShape::Ellipsoid: {
            const float y = 2.0f * t - 1.0f;
            return radial + y * y <= 1.0f;
        }
        case EnvelopeShape::Cone: {
            // Apex up: the radius shrinks from the full width at the bottom to 0 at the top.
            if (t < 0.0f || t > 1.0f) return false;
            const float r = 1.0f - t;
            return radial <= r * r;
        }
        case EnvelopeShape::Cylinder:
            return t >= 0.0f && t <= 1.0f && radial <= 1.0f;
        case EnvelopeShape::Hemisphere:
            // A dome on a flat bottom, as tall as size.y.
            return t >= 0.0f && radial + t * t <= 1.0f;
    }
    return false;
}

Box bounds(const Envelope& envelope) {
    const glm::vec3 size = extents(envelope);
    const glm::vec3 half(0.5f * size.x, 0.0f, 0.5f * size.z);
    return {envelope.base - half, envelope.base + half + glm::vec3(0.0f, size.y, 0.0f)};
}

}  // namespace sylva
