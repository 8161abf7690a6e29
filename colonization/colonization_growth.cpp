#include "colonization/colonization_growth.h"

#include "colonization/branch_shaping.h"
#include "core/errors.h"
#include "core/stopwatch.h"

namespace sylva {
namespace {

Skeleton grow(const TreeTemplate& tree, const GrowthContext& context) {
    const TreeParams& p = tree.params;
    Stopwatch clock;
    ColonizationSettings settings;
    try {
        settings = colonization_settings(p);
    } catch (InputError& e) {
        if (!tree.source.empty()) e.relocate(tree.source, 1);
        throw;
    }
    settings.cancel = context.cancel;
    const std::vector<glm::vec3> points =
        attraction_points(template_envelope(p), p.attraction_points,
                          static_cast<PointDistribution>(p.point_distribution), p.seed);
    if (context.times) context.times->push_back({"attraction points", clock.lap_ms()});
    ColonizationGraph graph = colonize(points, glm::vec3(0.0f), settings);
    if (context.times) context.times->push_back({"colonize", clock.lap_ms()});
    draw_successors_together(graph, static_cast<float>(p.angle_smoothing));
    reduce_curves(graph, static_cast<float>(p.curve_reduction));
    Skeleton skeleton = to_skeleton(graph, static_cast<float>(0.5 * p.tip_width),
                                    static_cast<float>(p.pipe_exponent));
    if (context.times) context.times->push_back({"branches", clock.lap_ms()});
    return skeleton;
}

}  // namespace

const GrowthMethod colonization_growth = {
    "colonization",
    "space colonization: branches grow towards attraction points in an envelope (seed 000, "
    "chapter 3)",
    grow};

Envelope template_envelope(const TreeParams& p) {
    Envelope e;
    e.shape = static_cast<EnvelopeShape>(p.envelope);
    e.size = glm::vec3(static_cast<float>(p.envelope_size_x), static_cast<float>(p.envelope_size_y),
                       static_cast<float>(p.envelope_size_z));
    e.base = glm::vec3(static_cast<float>(p.envelope_offset_x), static_cast<float>(p.envelope_base),
                       static_cast<float>(p.envelope_offset_z));
    return e;
}

ColonizationSettings colonization_settings(const TreeParams& p) {
    if (p.kill_distance > p.influence_radius)
        throw InputError("kill_distance (" + std::to_string(p.kill_distance) +
                         ") must not exceed influence_radius (" +
                         std::to_string(p.influence_radius) + ")");
    ColonizationSettings s;
    s.influence_radius = static_cast<float>(p.influence_radius);
    s.kill_distance = static_cast<float>(p.kill_distance);
    s.step_size = static_cast<float>(p.step_size);
    s.tropism =
        glm::vec3(static_cast<float>(p.tropism_vector_x), static_cast<float>(p.tropism_vector_y),
                  static_cast<float>(p.tropism_vector_z));
    s.max_iterations = p.max_iterations;
    s.trunk_height = static_cast<float>(p.trunk_height);
    s.max_degree = p.max_degree;
    s.max_depth = p.max_depth;
    s.max_no_grow = p.max_no_grow;
    s.weighted_growth = p.weighted_growth != 0;
    return s;
}

}  // namespace sylva
