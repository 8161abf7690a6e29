#include "colonization/colonization_params.h"

#include <iterator>

namespace sylva {
namespace {

constexpr std::string_view kEnvelopes[] = {"sphere",   "ellipsoid",  "cone",
                                           "cylinder", "hemisphere", "template"};
constexpr std::string_view kEnvelopeTemplates[] = {
    "oak",     "spruce", "fir",  "palm", "birch", "willow", "pine",     "baobab",
    "cypress", "honda",  "bush", "elm",  "maple", "hedge",  "windswept"};
constexpr std::string_view kObstacles[] = {"none", "sphere", "box"};
constexpr std::string_view kPointDistributions[] = {"uniform", "halton"};

}  // namespace

std::span<const std::string_view> envelope_template_names() {
    return kEnvelopeTemplates;
}

const ParamTable& colonization_param_table() {
    using P = ColonizationParams;
    constexpr ParamGroup G = ParamGroup::GrowthMethod;
    static const ParamTable table = ParamTable::owned<P>(
        "colonization",
        {
            param("attraction_points", &P::attraction_points, 1, 1000000, G,
                  "number of attraction points")
                .symbol("N"),
            param("influence_radius", &P::influence_radius, 0.001, 100, G,
                  "a point attracts nodes this close, meters")
                .symbol("d_i"),
            param("kill_distance", &P::kill_distance, 0.001, 100, G,
                  "a point dies when a node is this close, meters (<= influence_radius)")
                .symbol("d_k"),
            param("step_size", &P::step_size, 0.001, 10, G,
                  "distance of a new node from its parent, meters")
                .symbol("D"),
            param("max_iterations", &P::max_iterations, 1, 100000, G,
                  "iterations before growth stops"),
            param("envelope", &P::envelope, kEnvelopes, G,
                  "the crown's shape: sphere, ellipsoid, cone, cylinder, hemisphere, or "
                  "template (the crown of envelope_template)"),
            param("envelope_template", &P::envelope_template, kEnvelopeTemplates, G,
                  "with envelope = template, the built-in template whose crown is the "
                  "envelope"),
            param("envelope_size_x", &P::envelope_size, 0, 0.01, 100, G,
                  "the envelope's width (x), meters"),
            param("envelope_size_y", &P::envelope_size, 1, 0.01, 100, G,
                  "the envelope's height (y), meters"),
            param("envelope_size_z", &P::envelope_size, 2, 0.01, 100, G,
                  "the envelope's depth (z), meters"),
            param("envelope_base", &P::envelope_base, 1, -50, 100, G,
                  "height of the envelope's bottom, meters"),
            param("envelope_offset_x", &P::envelope_base, 0, -50, 50, G,
                  "the envelope moved off the root along x, meters"),
            param("envelope_offset_z", &P::envelope_base, 2, -50, 50, G,
                  "the envelope moved off the root along z, meters"),
            param("envelope_tilt", &P::envelope_tilt, -90, 90, G,
                  "the envelope leans by this many degrees about Z (positive: top towards +x)"),
            param("obstacle", &P::obstacle, kObstacles, G,
                  "none, sphere or box: a solid with no attraction points that no branch "
                  "grows into"),
            param("obstacle_x", &P::obstacle_center, 0, -50, 50, G,
                  "the obstacle's centre, x, meters"),
            param("obstacle_y", &P::obstacle_center, 1, -50, 100, G,
                  "the obstacle's centre, y (height), meters"),
            param("obstacle_z", &P::obstacle_center, 2, -50, 50, G,
                  "the obstacle's centre, z, meters"),
            param("obstacle_size_x", &P::obstacle_size, 0, 0.01, 100, G,
                  "the obstacle's width (x), meters"),
            param("obstacle_size_y", &P::obstacle_size, 1, 0.01, 100, G,
                  "the obstacle's height (y), meters"),
            param("obstacle_size_z", &P::obstacle_size, 2, 0.01, 100, G,
                  "the obstacle's depth (z), meters"),
            param("roots", &P::roots, 1, 64, G,
                  "trees grown from a circle of roots, sharing the points"),
            param("root_spread", &P::root_spread, 0, 50, G,
                  "radius of the circle of roots, meters"),
            param("point_distribution", &P::point_distribution, kPointDistributions, G,
                  "attraction points uniform (random) or halton (low discrepancy)"),
            param("trunk_height", &P::trunk_height, 0, 100, G,
                  "the trunk grows at least this high first, meters"),
            param("max_degree", &P::max_degree, 0, 100, G, "successors per node (0 = no limit)")
                .symbol("max_grad"),
            param("max_depth", &P::max_depth, 0, 1000, G,
                  "branch depth (Liebemann's eq. 3.5; 0 = no limit)")
                .symbol("max_Z"),
            param("max_no_grow", &P::max_no_grow, 0, 100000, G,
                  "iterations without growth before a node stops attracting (0 = never)")
                .symbol("max_NG"),
            param("weighted_growth", &P::weighted_growth, G,
                  "1: step 2D at branch depth 0 down to D at max_depth; 0: always D"),
            param("curve_reduction", &P::curve_reduction, 0, 1, G,
                  "Liebemann's eq. 3.6, a node on a run straighter than this dot product is "
                  "removed (1 = keep all)"),
            param("angle_smoothing", &P::angle_smoothing, 0, 1, G,
                  "successors drawn towards their mean direction (0 = not, 1 = fully)"),
        });
    static_assert(std::size(kEnvelopes) == static_cast<int>(EnvelopeChoice::Template) + 1);
    return table;
}

}  // namespace sylva
