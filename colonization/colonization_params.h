// Space colonization's own parameters (growth = "colonization", Liebemann 2017, chapter 3):
// the attraction points, the envelope they fill, an obstacle, the roots and the growth's
// limits. Kept in TreeParams::blocks; their table (colonization_param_table) gives their keys
// and ranges. A vector is three keys, one per component (envelope_size_x, _y, _z).
#pragma once

#include <glm/vec3.hpp>
#include <span>
#include <string_view>

#include "colonization/attraction_points.h"
#include "colonization/obstacle.h"
#include "core/param_table.h"
#include "core/tree_params.h"

namespace sylva {

// The `envelope` choice: one of the simple solids (EnvelopeShape, the same values) or the
// crown of another template (envelope_template).
enum class EnvelopeChoice { Sphere, Ellipsoid, Cone, Cylinder, Hemisphere, Template };

struct ColonizationParams {
    int attraction_points = 2000;   // N
    double influence_radius = 1.5;  // d_i, meters
    double kill_distance = 0.4;     // d_k, meters
    double step_size = 0.25;        // D, meters
    int max_iterations = 300;       // iterations before growth stops
    EnvelopeChoice envelope = EnvelopeChoice::Ellipsoid;
    glm::dvec3 envelope_size{6.0, 5.0, 6.0};  // width, height, depth, meters
    // The centre of the envelope's bottom: x and z move it off the root
    // (envelope_offset_x, envelope_offset_z), y is its height (envelope_base).
    glm::dvec3 envelope_base{0.0, 2.5, 0.0};
    // With envelope = template: the index in envelope_template_names() of the built-in
    // template whose crown is the envelope.
    int envelope_template = 0;
    double envelope_tilt = 0.0;  // degrees about Z; positive leans the top towards +x
    ObstacleShape obstacle = ObstacleShape::None;
    glm::dvec3 obstacle_center{0.0};  // meters
    glm::dvec3 obstacle_size{1.0};    // full extents, meters
    int roots = 1;                    // trees grown from a circle of roots, sharing the points
    double root_spread = 0.5;         // radius of that circle, meters (ignored for one root)
    PointDistribution point_distribution = PointDistribution::Uniform;
    double trunk_height = 2.0;     // the trunk grows at least this high first
    int max_degree = 0;            // max_grad: successors per node (0 = no limit)
    int max_depth = 0;             // max_Z: branch depth (0 = no limit)
    int max_no_grow = 0;           // max_NG: idle iterations before a node stops
    bool weighted_growth = false;  // step 2D on the trunk down to D at max_depth
    double curve_reduction = 1.0;  // eq. 3.6 dot-product threshold (1 = keep all)
    double angle_smoothing = 0.0;  // successors drawn together (0 = not, 1 = fully)
};

const ParamTable& colonization_param_table();

// The template's colonization parameters (defaults when none were set); change them with
// params.blocks.edit<ColonizationParams>().
inline const ColonizationParams& colonization_params(const TreeParams& params) {
    return params.blocks.get<ColonizationParams>();
}

// The choices of `envelope_template`: the built-in templates (by name) whose crown an
// envelope can be. Colonization cannot ask the template library, so they are listed here;
// tests/tree checks each is a built-in template.
std::span<const std::string_view> envelope_template_names();

}  // namespace sylva
