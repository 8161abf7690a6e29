#include "turtle/lsystem_growth.h"

#include "core/errors.h"
#include "core/param_table.h"
#include "core/stopwatch.h"
#include "turtle/derivation.h"
#include "turtle/grammar_reads.h"
#include "turtle/lsystem_params.h"

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

// The shared and L-system parameters the template's grammar and widths never read.
std::vector<UnreadParam> unread(const TreeTemplate& tree, const GrowthContext&) {
    std::vector<UnreadParam> out;
    const LSystemParams& p = lsystem_params(tree.params);
    auto mark = [&](std::string_view key, std::string reason) {
        out.push_back({std::string(key), std::move(reason)});
    };
    const std::string_view grammar = tree.grammar;
    auto unread_default = [&](std::string_view key, std::string_view symbols) {
        return !grammar_uses_default(grammar, symbols) && !grammar_names(grammar, key);
    };
    if (unread_default("branch_length", "Ff"))
        mark("branch_length", "every F and f in the rules gives its own length");
    if (unread_default("pitch_angle", "&^"))
        mark("pitch_angle", "every & and ^ in the rules gives its own angle");
    if (unread_default("yaw_angle", "+-\\/"))
        mark("yaw_angle", "every +, -, \\ and / in the rules gives its own angle");
    const bool tropism_unread = tree.mode == TurtleMode::Lptg && !grammar_names(grammar, "tropism");
    if (tropism_unread) mark("tropism", "the lptg turtle (Heuer's) does not bend towards gravity");
    if ((tropism_unread || p.tropism == 0.0) && !grammar_names(grammar, "tropism")) {
        mark("tropism_variation", "no tropism to vary: set tropism first");
        // The L-system's tropism vector is where `tropism` bends towards.
        for (std::string_view key : {"tropism_vector_x", "tropism_vector_y", "tropism_vector_z"})
            if (!grammar_names(grammar, key)) mark(key, "no tropism to point: set tropism first");
    }
    // The noise kind matters where something reads the noise: the rules (noise, fbm,
    // noise_loop, and the ", noise F" choice all name it) or the turtle's variation.
    if (!grammar_names(grammar, "noise") && !grammar_names(grammar, "fbm") &&
        !grammar_names(grammar, "noise_loop") && p.bend == 0.0 && p.width_variation == 0.0 &&
        (tree.params.tropism_variation == 0.0 || p.tropism == 0.0))
        mark("noise_kind",
             "nothing reads the noise: the rules call no noise(), fbm() or noise_loop() and "
             "bend, width_variation and tropism_variation are 0");
    for (std::string_view key :
         {"trunk_taper", "branch_taper", "tip_width", "pipe_exponent", "branch_width"}) {
        if (grammar_names(grammar, key)) continue;
        const bool taper_key = key == "trunk_taper" || key == "branch_taper";
        const bool pipe_key = key == "tip_width" || key == "pipe_exponent";
        bool read = true;
        std::string reason;
        switch (tree.width_model) {
            case WidthModel::Explicit:
                read = key == "branch_width" && !axiom_sets_width(grammar);
                reason = "widths = explicit: only ! in the rules sets widths";
                break;
            case WidthModel::Taper:
                read = taper_key || (key == "branch_width" && !axiom_sets_width(grammar));
                reason = "widths = taper: per-segment factors set the widths";
                break;
            case WidthModel::Pipe:
                read = pipe_key;
                reason = "widths = pipe: the pipe model sets every width from tip_width";
                break;
        }
        if (key == "branch_width" && tree.width_model != WidthModel::Pipe)
            reason = "the axiom sets its own starting width with !(...)";
        if (!read) mark(key, reason);
    }
    if (p.bend == 0.0) mark("bend_frequency", "bend is 0: there is no bending to shape");
    return out;
}

}  // namespace

const GrowthMethod lsystem_growth = {
    .name = "lsystem",
    .description = "an L-system grammar derived and read by a turtle (ABOP chapters 1-2)",
    .grow = grow,
    .params = lsystem_param_table,
    .uses_grammar = true,
    .unread = unread,
};

Constants param_constants(const TreeParams& params) {
    Constants constants;
    for (const ParamTable* table : {&shared_param_table(), &lsystem_param_table()})
        for (std::size_t i = 0; i < table->infos().size(); ++i)
            constants[std::string(table->infos()[i].key)] = table->get(params, i);
    return constants;
}

TurtleSettings turtle_settings(const TreeTemplate& tree) {
    const TreeParams& shared = tree.params;
    const LSystemParams& p = lsystem_params(shared);
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
    if (shared.tropism_vector != glm::dvec3(0.0)) s.tropism = shared.tropism_vector;
    s.noise_kind = p.noise_kind;
    s.pipe_tip_width = shared.tip_width;
    s.pipe_exponent = shared.pipe_exponent;
    s.seed = shared.seed;
    s.bend = p.bend;
    s.bend_frequency = shared.bend_frequency;
    s.jitter = p.jitter;
    s.width_variation = p.width_variation;
    s.tropism_variation = shared.tropism_variation;
    return s;
}

Word derive_word(const TreeTemplate& tree, CancelFlag cancel,
                 const std::function<void(float)>& progress) {
    return located(tree, [&] {
        LSystem system = parse_lsystem(tree.grammar, param_constants(tree.params));
        DeriveSettings settings;
        settings.steps = lsystem_params(tree.params).generations;
        settings.seed = tree.params.seed;
        settings.cancel = cancel;
        settings.progress = progress;
        settings.noise_kind = lsystem_params(tree.params).noise_kind;
        // Rules that choose by noise over position see the turtle the tree is drawn with.
        const TurtleSettings turtle = turtle_settings(tree);
        settings.positions = [&turtle](const Word& word, std::vector<glm::vec3>& positions) {
            turtle_positions(word, turtle, positions);
        };
        return derive(system, settings);
    });
}

}  // namespace sylva
