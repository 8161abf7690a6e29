// Growth method "colonization": space colonization (Liebemann 2017, chapter 3) with the crown
// drawn as an envelope of attraction points. Maps a template's parameters to the
// algorithm's plain settings. Registered in tree/growth.cpp.
#pragma once

#include <string>
#include <vector>

#include "colonization/attraction_points.h"
#include "colonization/colonization_params.h"
#include "colonization/envelope.h"
#include "colonization/obstacle.h"
#include "colonization/space_colonization.h"
#include "core/growth.h"

namespace sylva {

extern const GrowthMethod colonization_growth;

// The envelope, the obstacle, the roots and the algorithm's settings as the template's
// parameters set them. Throws InputError when kill_distance exceeds influence_radius.
// template_envelope is the simple solid (envelope = "template" is resolved in grow, which
// asks GrowthContext::template_crown for it).
Envelope template_envelope(const ColonizationParams& params);
Obstacle template_obstacle(const ColonizationParams& params);
// `roots` points on a circle of radius root_spread on the ground (y = 0), the first on +x;
// one root stands at the origin.
std::vector<glm::vec3> template_roots(const ColonizationParams& params);
// The shared parameters give the pipe radii's noise: tropism_variation, bend_frequency and
// the seed.
ColonizationSettings colonization_settings(const TreeParams& params);

// Why max_no_grow cannot change this template's colonization, or empty when it can: the
// growth is run with max_no_grow 1, the earliest release, and either no attracted node ever
// stalls or no released point finds another node. `context` as for growth (an envelope =
// "template" needs its template_crown). Throws what the growth throws.
std::string why_max_no_grow_is_unused(const TreeTemplate& tree, const GrowthContext& context = {});

}  // namespace sylva
