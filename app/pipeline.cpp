#include "app/pipeline.h"

#include "app/errors.h"
#include "marching/marching_cubes.h"
#include "sdf/cone_field.h"
#include "turtle/derivation.h"
#include "turtle/lsystem_parser.h"

#include <glm/common.hpp>

#include <algorithm>
#include <chrono>
#include <limits>

namespace sylva {
namespace {

class Stopwatch {
public:
    double lap_ms() {
        auto now = std::chrono::steady_clock::now();
        double ms = std::chrono::duration<double, std::milli>(now - start_).count();
        start_ = now;
        return ms;
    }

private:
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// Every parameter of SPEC section 7 is visible to the grammar's expressions by its key.
Constants param_constants(const TreeParams& params) {
    Constants constants;
    for (const ParamInfo& info : param_infos())
        constants[std::string(info.key)] = *get_param(params, info.key);
    return constants;
}

TurtleSettings turtle_settings(const TreeTemplate& tree) {
    const TreeParams& p = tree.params;
    TurtleSettings s;
    s.mode = tree.mode;
    s.width_model = tree.width_model;
    s.step = p.branch_length;
    s.turn_angle = p.yaw_angle;
    s.roll_angle = p.yaw_angle;
    s.pitch_angle = p.pitch_angle;
    s.initial_width = p.branch_width;
    s.trunk_taper = p.trunk_taper;
    s.branch_taper = p.branch_taper;
    s.elasticity = p.tropism;
    s.pipe_tip_width = p.tip_width;
    s.pipe_exponent = p.pipe_exponent;
    return s;
}

// One capped cone per segment with a width. Branches thinner than the grid can sample
// would break into disconnected crumbs, so radii are raised to kMinRadiusInCells cells:
// a ball that wide always holds a grid node (the cubic lattice's covering radius is
// sqrt(3)/2 = 0.87 cells), which keeps every branch in one piece. Finer twigs need a
// higher trunk_resolution.
constexpr float kMinRadiusInCells = 0.9f;

std::vector<CappedCone> resolvable_cones(const Skeleton& skeleton, float cell) {
    const float min_radius = kMinRadiusInCells * cell;
    std::vector<CappedCone> cones;
    cones.reserve(skeleton.segments.size());
    for (const Segment& s : skeleton.segments)
        if (std::max(s.ra, s.rb) > 0.0f)
            cones.push_back({s.a, s.b, std::max(s.ra, min_radius), std::max(s.rb, min_radius)});
    return cones;
}

}  // namespace

Word derive_word(const TreeTemplate& tree) {
    LSystem system = parse_lsystem(tree.grammar, param_constants(tree.params));
    DeriveSettings settings;
    settings.steps = tree.params.generations;
    settings.seed = tree.params.seed;
    return derive(system, settings);
}

Skeleton grow_skeleton(const TreeTemplate& tree, StageTimes* times) {
    Stopwatch clock;
    Word word = derive_word(tree);
    if (times) times->derive_ms = clock.lap_ms();
    Skeleton skeleton = interpret(word, turtle_settings(tree));
    if (times) times->turtle_ms = clock.lap_ms();
    return skeleton;
}

std::vector<Sphere> crown_spheres(const Skeleton& skeleton, const TreeParams& params) {
    std::vector<Sphere> out;
    for (int tip : tips(skeleton)) {
        const Segment& s = skeleton.segments[static_cast<size_t>(tip)];
        out.push_back({s.b + glm::vec3(0.0f, static_cast<float>(params.crown_offset), 0.0f),
                       static_cast<float>(params.sphere_diameter * 0.5)});
    }
    return out;
}

Box skeleton_bounds(const Skeleton& skeleton) {
    Box box{glm::vec3(std::numeric_limits<float>::max()),
            glm::vec3(std::numeric_limits<float>::lowest())};
    for (const Segment& s : skeleton.segments) {
        float r = std::max(s.ra, s.rb);
        box.min = glm::min(box.min, glm::min(s.a, s.b) - glm::vec3(r));
        box.max = glm::max(box.max, glm::max(s.a, s.b) + glm::vec3(r));
    }
    return box;
}

Tree generate_tree(const TreeTemplate& tree) {
    Tree out;
    out.skeleton = grow_skeleton(tree, &out.times);

    Stopwatch clock;
    MarchingCubesSettings settings;
    settings.resolution = tree.params.trunk_resolution;
    Box box = skeleton_bounds(out.skeleton);
    glm::vec3 extent = box.max - box.min;
    float cell = std::max({extent.x, extent.y, extent.z}) / static_cast<float>(settings.resolution);
    std::vector<CappedCone> cones = resolvable_cones(out.skeleton, cell);
    if (cones.empty())
        throw InputError("the tree has no trunk: the derived word draws no segment with a "
                         "width above zero (it needs F, and a width from branch_width or !)");
    ConeField field(std::move(cones), 2.0f * cell);
    out.trunk = marching_cubes(field, box, settings);
    out.times.trunk_mesh_ms = clock.lap_ms();
    return out;
}

}  // namespace sylva
