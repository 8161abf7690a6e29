#include "colonization/envelope.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>

namespace sylva {
namespace {

glm::vec3 extents(const Envelope& envelope) {
    if (envelope.shape != EnvelopeShape::Sphere) return envelope.size;
    const float d = std::max({envelope.size.x, envelope.size.y, envelope.size.z});
    return glm::vec3(d);
}

struct Turn {
    float cos, sin;
};

Turn turn(const Envelope& envelope) {
    const float radians = envelope.tilt * 0.017453292519943295f;
    return {std::cos(radians), std::sin(radians)};
}

// Positive tilt turns the up axis to (sin, cos, 0): the top leans towards +x.
glm::vec3 tilted(const Envelope& envelope, const glm::vec3& p) {
    const Turn t = turn(envelope);
    const glm::vec3 q = p - envelope.base;
    return envelope.base + glm::vec3(q.x * t.cos + q.y * t.sin, q.y * t.cos - q.x * t.sin, q.z);
}

// The inverse: a point in the upright envelope's frame.
glm::vec3 untilted(const Envelope& envelope, const glm::vec3& p) {
    const Turn t = turn(envelope);
    const glm::vec3 q = p - envelope.base;
    return envelope.base + glm::vec3(q.x * t.cos - q.y * t.sin, q.x * t.sin + q.y * t.cos, q.z);
}

bool upright_inside(const Envelope& envelope, const glm::vec3& p) {
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

Box upright_bounds(const Envelope& envelope) {
    const glm::vec3 size = extents(envelope);
    const glm::vec3 half(0.5f * size.x, 0.0f, 0.5f * size.z);
    return {envelope.base - half, envelope.base + half + glm::vec3(0.0f, size.y, 0.0f)};
}

}  // namespace

bool inside(const Envelope& envelope, const glm::vec3& p) {
    // An upright envelope skips the turn, so its points stay bit for bit what they were.
    return upright_inside(envelope, envelope.tilt == 0.0f ? p : untilted(envelope, p));
}

Box bounds(const Envelope& envelope) {
    const Box upright = upright_bounds(envelope);
    if (envelope.tilt == 0.0f) return upright;
    // The box around the upright box's corners, tilted.
    Box box{glm::vec3(INFINITY), glm::vec3(-INFINITY)};
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 c((corner & 1) ? upright.max.x : upright.min.x,
                          (corner & 2) ? upright.max.y : upright.min.y,
                          (corner & 4) ? upright.max.z : upright.min.z);
        const glm::vec3 w = tilted(envelope, c);
        box.min = glm::min(box.min, w);
        box.max = glm::max(box.max, w);
    }
    return box;
}

Region region(const Envelope& envelope) {
    return {bounds(envelope), [envelope](const glm::vec3& p) { return inside(envelope, p); }};
}

}  // namespace sylva
