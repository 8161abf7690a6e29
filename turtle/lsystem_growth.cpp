#include "turtle/lsystem_growth.h"

#include "core/errors.h"
#include "core/stopwatch.h"
#include "turtle/derivation.h"

namespace sylva {
namespace {

// Runs `stage`; an input error it raises names the template's file and the file's line.
template <class Stage>
auto located(const TreeTemplate& tree, Stage&& stage) {
    try {
        return stage();
    } catch (InputError& e) {
        if (!tree.source.empty()) e.relocate(tree.source, tree.grammar_line);
        throw;
    }
}

// The derivation's share of the growth's progress bar; the turtle has the rest. On a large
// tree the derivation takes about twice as long as the turtle (sylva-bench-cancel shows it).
constexpr float kDeriveShare = 0.65f;

Skeleton grow(const TreeTemplate& tree, const GrowthContext& context) {
    Stopwatch clock;
    std::function<void(float)> derive_progress, turtle_progress;
    if (context.progress) {
        derive_progress = [&](float f) { context.progress(kDeriveShare * f); };
        turtle_progress = [&](float f) {
            context.progress(kDeriveShare + (1.0f - kDeriveShare) * f);
        };
    }
    Word word = derive_word(tree, context.cancel, derive_progress);
    if (context.times) context.times->push_back({"derive", clock.lap_ms()});
    TurtleSettings settings = turtle_settings(tree);
    settings.cancel = context.cancel;
    settings.progress = turtle_progress;
    Skeleton skeleton = located(tree, [&] { return interpret(word, settings); });
    if (context.times) context.times->push_back({"turtle", clock.lap_ms()});
    return skeleton;
}

}  // namespace

const GrowthMethod lsystem_growth = {
    "lsystem", "an L-system grammar derived and read by a turtle (SPEC sections 1-2)", grow};

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
    // ABOP's T: the template's tropism vector, or straight down while it is 0 (the vector
    // is colonization's too, where 0 means no pull).
    const glm::dvec3 t(p.tropism_vector_x, p.tropism_vector_y, p.tropism_vector_z);
    if (t != glm::dvec3(0.0)) s.tropism = t;
    s.noise_kind = static_cast<NoiseKind>(p.noise_kind);
    s.pipe_tip_width = p.tip_width;
    s.pipe_exponent = p.pipe_exponent;
    s.seed = p.seed;
    s.bend = p.bend;
    s.bend_frequency = p.bend_frequency;
    s.jitter = p.jitter;
    s.width_variation = p.width_variation;
    s.tropism_variation = p.tropism_variation;
    return s;
}

Word derive_word(const TreeTemplate& tree, CancelFlag cancel,
                 const std::function<void(float)>& progress) {
    return located(tree, [&] {
        LSystem system = parse_lsystem(tree.grammar, param_constants(tree.params));
        DeriveSettings settings;
        settings.steps = tree.params.generations;
        settings.seed = tree.params.seed;
        settings.cancel = cancel;
        settings.progress = progress;
        settings.noise_kind = static_cast<NoiseKind>(tree.params.noise_kind);
        // Rules that choose by noise over position see the turtle the tree is drawn with.
        const TurtleSettings turtle = turtle_settings(tree);
        settings.positions = [&turtle](const Word& word, std::vector<glm::vec3>& positions) {
            turtle_positions(word, turtle, positions);
        };
        return derive(system, settings);
    });
}

}  // namespace sylva
