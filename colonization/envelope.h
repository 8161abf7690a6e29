// The space a crown may fill (Liebemann 2017, 3.3: "the region of influence"): a simple solid in
// which attraction points are placed. Sizes are the solid's full extents, so a template's
// envelope_size reads as the crown's width, height and depth in metres.
#pragma once

#include <glm/vec3.hpp>

#include "core/box.h"
#include "core/region.h"

namespace sylva {

enum class EnvelopeShape { Sphere = 0, Ellipsoid = 1, Cone = 2, Cylinder = 3, Hemisphere = 4 };

struct Envelope {
    EnvelopeShape shape = EnvelopeShape::Ellipsoid;
    // Full extents along x, y (up) and z. A sphere uses the largest of the three as its
    // diameter; every other shape is stretched to all three.
    glm::vec3 size{6.0f, 5.0f, 6.0f};
    // The centre of the solid's bottom: the envelope stands on this point.
    glm::vec3 base{0.0f, 2.5f, 0.0f};
    // Degrees about the Z axis through `base`: the solid leans, positive tilts its top
    // towards +x (a wind-swept crown). 0 leaves the solid upright.
    float tilt = 0.0f;
};

// True when p lies inside the envelope (boundary included).
bool inside(const Envelope& envelope, const glm::vec3& p);

// The axis-aligned box the envelope fills.
Box bounds(const Envelope& envelope);

// The envelope as a plain solid, for code that takes any shape (attraction_points).
Region region(const Envelope& envelope);

}  // namespace sylva
