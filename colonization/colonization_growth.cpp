#include "colonization/colonization_growth.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "colonization/branch_shaping.h"
#include "colonization/colonization_cost.h"
#include "core/errors.h"
#include "core/noise.h"
#include "core/stopwatch.h"

namespace sylva {
namespace {

// Where the points go: the envelope (a simple solid or another template's crown) less the
// obstacle.
Region point_region(const ColonizationParams& p, const GrowthContext& context) {
    Region region;
    if (p.envelope == EnvelopeChoice::Template) {
        const std::string name(envelope_template_names()[static_cast<size_t>(p.envelope_template)]);
        if (!context.template_crown)
            throw InputError("envelope = template (the crown of '" + name +
                             "') needs the template library: grow through tree/growth.h");
        region = context.template_crown(name);
    } else {
        region = sylva::region(template_envelope(p));
    }
    const Obstacle obstacle = template_obstacle(p);
    if (obstacle.shape == ObstacleShape::None) return region;
    return {region.bounds, [envelope = std::move(region.contains), obstacle](const glm::vec3& q) {
                return envelope(q) && !inside(obstacle, q);
            }};
}

// "1000000 attraction points x about 10400 nodes".
std::string work_text(double points, double nodes, bool estimated) {
    char text[96];
    std::snprintf(text, sizeof text, "%.0f attraction points x %s%.0f nodes", points,
                  estimated ? "about " : "", nodes);
    return text;
}

// Stops a growth whose counted work passes `limits` (settings.work_done): the limit holds
// where the estimate was low.
void stop_past_limits(const ColonizationWork& work, std::size_t points, const Box& bounds,
                      const ColonizationSettings& settings, const GrowthLimits& limits) {
    const ColonizationCost cost = colonization_cost(work, points, bounds, settings);
    if (cost.seconds <= limits.max_seconds && cost.bytes <= limits.max_bytes) return;
    char figures[160];
    std::snprintf(figures, sizeof figures,
                  " after %d of at most %d passes (%.2g point visits): about %.2g GB and %.3g s, "
                  "over the limit of %.0f MB and %.3g s",
                  work.iterations, settings.max_iterations, cost.visits, cost.bytes / 1e9,
                  cost.seconds, limits.max_bytes / 1e6, limits.max_seconds);
    throw InputError("space colonization grew " +
                     work_text(static_cast<double>(points), cost.nodes, false) + figures +
                     " (fewer attraction_points, a larger kill_distance or step_size, or " +
                     limits.how_to_raise + ")");
}

Skeleton grow(const TreeTemplate& tree, const GrowthContext& context) {
    const TreeParams& shared = tree.params;
    const ColonizationParams& p = colonization_params(shared);
    Stopwatch clock;
    ColonizationSettings settings;
    try {
        settings = colonization_settings(shared);
    } catch (InputError& e) {
        if (!tree.source.empty()) e.relocate(tree.source, 1);
        throw;
    }
    settings.cancel = context.cancel;
    // Colonizing is the growth's long part; points and shaping take little.
    if (context.progress) settings.progress = [&](float f) { context.progress(0.95f * f); };
    Region region;
    try {
        region = point_region(p, context);
    } catch (InputError& e) {
        if (!tree.source.empty() && e.where().source.empty()) e.relocate(tree.source, 1);
        throw;
    }
    const std::vector<glm::vec3> points =
        attraction_points(region, p.attraction_points, p.point_distribution, shared.seed);
    if (context.times) context.times->push_back({"attraction points", clock.lap_ms()});
    if (context.limits.max_seconds < INFINITY || context.limits.max_bytes < INFINITY)
        settings.work_done = [&](const ColonizationWork& work) {
            stop_past_limits(work, points.size(), region.bounds, settings, context.limits);
        };
    ColonizationGraph graph = colonize(points, template_roots(p), settings);
    if (context.times) context.times->push_back({"colonize", clock.lap_ms()});
    draw_successors_together(graph, static_cast<float>(p.angle_smoothing));
    reduce_curves(graph, static_cast<float>(p.curve_reduction));
    Skeleton skeleton = to_skeleton(graph, static_cast<float>(0.5 * shared.tip_width),
                                    static_cast<float>(shared.pipe_exponent));
    if (context.times) context.times->push_back({"branches", clock.lap_ms()});
    if (context.progress) context.progress(1.0f);
    return skeleton;
}

}  // namespace

std::string why_max_no_grow_is_unused(const TreeTemplate& tree, const GrowthContext& context) {
    TreeParams earliest = tree.params;
    // Every idle attracted node releases its points at once.
    earliest.blocks.edit<ColonizationParams>().max_no_grow = 1;
    const ColonizationParams& p = colonization_params(earliest);
    ColonizationSettings settings = colonization_settings(earliest);
    settings.cancel = context.cancel;
    const Region region = point_region(p, context);
    const std::vector<glm::vec3> points =
        attraction_points(region, p.attraction_points, p.point_distribution, earliest.seed);
    const ColonizationGraph graph = colonize(points, template_roots(p), settings);
    if (graph.idle_attracted == 0)
        return "this growth never stalls: every node its points attract grows on every pass "
               "until the points are used up, so no node waits for max_no_grow";
    if (graph.moved_growth == 0)
        return "no growth comes of releasing a stalled node's points here: they find no "
               "other node within influence_radius, or only nodes that stall too (even at "
               "max_no_grow 1)";
    return {};
}

namespace {

// The envelope's box stands for another template's crown (envelope = "template"), which
// only growing that template would measure.
GrowthCost estimate(const TreeTemplate& tree) {
    const ColonizationParams& p = colonization_params(tree.params);
    ColonizationSettings settings;
    try {
        settings = colonization_settings(tree.params);
    } catch (const InputError&) {
        return {};  // growing reports it, with the template's file
    }
    const ColonizationCost cost = estimate_colonization_cost(
        bounds(template_envelope(p)), static_cast<std::size_t>(std::max(p.attraction_points, 0)),
        std::max(p.roots, 1), settings);
    return {cost.nodes, cost.seconds, cost.bytes,
            work_text(static_cast<double>(p.attraction_points), cost.nodes, true)};
}

// The shared and colonization parameters the template's own choices leave unread.
std::vector<UnreadParam> unread(const TreeTemplate& tree, const GrowthContext& context) {
    std::vector<UnreadParam> out;
    const ColonizationParams& p = colonization_params(tree.params);
    auto mark = [&](std::string_view key, std::string_view reason) {
        out.push_back({std::string(key), std::string(reason)});
    };
    if (p.envelope == EnvelopeChoice::Template) {
        for (std::string_view key :
             {"envelope_size_x", "envelope_size_y", "envelope_size_z", "envelope_base",
              "envelope_offset_x", "envelope_offset_z", "envelope_tilt"})
            mark(key,
                 "the envelope is another template's crown (envelope = template): its own size "
                 "and place are not used");
    } else {
        mark("envelope_template", "only used with envelope = template");
    }
    if (p.obstacle == ObstacleShape::None)
        for (std::string_view key : {"obstacle_x", "obstacle_y", "obstacle_z", "obstacle_size_x",
                                     "obstacle_size_y", "obstacle_size_z"})
            mark(key, "no obstacle: set obstacle to sphere or box first");
    if (p.roots <= 1) mark("root_spread", "one root: the spread of a circle of roots is unused");
    if (tree.params.tropism_variation == 0.0)
        mark("bend_frequency",
             "tropism_variation is 0: space colonization reads bend_frequency only for the "
             "noise of its growth directions");
    try {
        if (std::string why = why_max_no_grow_is_unused(tree, context); !why.empty())
            mark("max_no_grow", why);
    } catch (const InputError&) {
        // The growth reports the error itself; max_no_grow stays enabled.
    }
    return out;
}

}  // namespace

const GrowthMethod colonization_growth = {
    .name = "colonization",
    .description =
        "space colonization: branches grow towards attraction points in an envelope "
        "(Liebemann 2017, chapter 3)",
    .grow = grow,
    .params = colonization_param_table,
    .unread = unread,
    .estimate = estimate,
};

Envelope template_envelope(const ColonizationParams& p) {
    Envelope e;
    e.shape = static_cast<EnvelopeShape>(p.envelope);
    e.size = glm::vec3(p.envelope_size);
    e.base = glm::vec3(p.envelope_base);
    e.tilt = static_cast<float>(p.envelope_tilt);
    return e;
}

Obstacle template_obstacle(const ColonizationParams& p) {
    Obstacle o;
    o.shape = p.obstacle;
    o.center = glm::vec3(p.obstacle_center);
    o.size = glm::vec3(p.obstacle_size);
    return o;
}

std::vector<glm::vec3> template_roots(const ColonizationParams& p) {
    if (p.roots <= 1) return {glm::vec3(0.0f)};
    std::vector<glm::vec3> roots;
    for (int i = 0; i < p.roots; ++i) {
        const double angle = 2.0 * 3.14159265358979323846 * i / p.roots;
        roots.emplace_back(static_cast<float>(p.root_spread * std::cos(angle)), 0.0f,
                           static_cast<float>(p.root_spread * std::sin(angle)));
    }
    return roots;
}

ColonizationSettings colonization_settings(const TreeParams& shared) {
    const ColonizationParams& p = colonization_params(shared);
    if (p.kill_distance > p.influence_radius)
        throw InputError("kill_distance (" + std::to_string(p.kill_distance) +
                         ") must not exceed influence_radius (" +
                         std::to_string(p.influence_radius) + ")");
    ColonizationSettings s;
    s.influence_radius = static_cast<float>(p.influence_radius);
    s.kill_distance = static_cast<float>(p.kill_distance);
    s.step_size = static_cast<float>(p.step_size);
    s.tropism = glm::vec3(shared.tropism_vector);
    if (shared.tropism_variation > 0.0) {
        const std::uint64_t seed = derive_seed(shared.seed, noise_stream::tropism);
        s.tropism_field = [noise =
                               std::array<GradientNoise, 3>{GradientNoise(seed),
                                                            GradientNoise(derive_seed(seed, 1)),
                                                            GradientNoise(derive_seed(seed, 2))},
                           amount = shared.tropism_variation,
                           frequency = shared.bend_frequency](const glm::vec3& q) {
            const glm::dvec3 x = glm::dvec3(q) * frequency;
            return glm::vec3(amount * glm::dvec3(noise[0](x.x, x.y, x.z), noise[1](x.x, x.y, x.z),
                                                 noise[2](x.x, x.y, x.z)));
        };
    }
    s.max_iterations = p.max_iterations;
    s.trunk_height = static_cast<float>(p.trunk_height);
    s.max_degree = p.max_degree;
    s.max_depth = p.max_depth;
    s.max_no_grow = p.max_no_grow;
    s.weighted_growth = p.weighted_growth;
    if (const Obstacle obstacle = template_obstacle(p); obstacle.shape != ObstacleShape::None)
        s.blocked = [obstacle](const glm::vec3& q) { return inside(obstacle, q); };
    return s;
}

}  // namespace sylva
