// Turtle interpretation (docs/grammar.md): walks a derived word and records the skeleton.
//
// ABOP mode: frame H (heading), L (left), U (up), U = H x L, starting H=(0,1,0),
// L=(-1,0,0), U=(0,0,1); Y is up. LPTG mode (Heuer 2022, 5.2): an elevation e and an
// azimuth a; F moves along (cos e cos a, sin e, cos e sin a).
#pragma once

#include <functional>
#include <glm/vec3.hpp>
#include <vector>

#include "core/cancel.h"
#include "core/noise.h"
#include "core/skeleton.h"
#include "core/tree_template.h"  // TurtleMode, WidthModel
#include "turtle/word.h"

namespace sylva {

struct TurtleSettings {
    TurtleMode mode = TurtleMode::Abop;
    WidthModel width_model = WidthModel::Taper;
    double step = 1.0;             // length of F and f without a parameter, meters
    double turn_angle = 22.5;      // degrees, + -  (LPTG: the azimuth step P_beta)
    double pitch_angle = 22.5;     // degrees, & ^  (LPTG: the elevation step P_alpha)
    double roll_angle = 22.5;      // degrees, \ /
    double initial_width = 0.1;    // diameter at the start, meters
    double width_decay = 0.7;      // '!' without a parameter multiplies the width by this
    double trunk_taper = 0.95;     // WidthModel::Taper, level 0
    double branch_taper = 0.8;     // WidthModel::Taper, deeper levels
    double pipe_tip_width = 0.02;  // WidthModel::Pipe: diameter at the tips
    double pipe_exponent = 2.5;    // WidthModel::Pipe: Murray's g
    glm::dvec3 tropism{0.0, -1.0, 0.0};
    double elasticity = 0.0;      // 0 disables tropism
    CancelFlag cancel = nullptr;  // polled every few thousand modules; throws Cancelled
    // Called with the fraction of the word read (rising, ends with 1), every few thousand
    // modules.
    std::function<void(float)> progress = nullptr;

    // Variation (after Limbach 2004), from noise seeded by `seed`; every amount 0 draws the
    // word exactly as without them. A branch is the trunk or what a '[' starts; each has its
    // own noise, sampled along its length s (meters from where it starts).
    std::uint64_t seed = 1;
    double bend = 0.0;               // degrees per meter: curvature noise along each branch
    double bend_frequency = 0.5;     // noise cycles per meter along a branch (bend, width, tropism)
    double jitter = 0.0;             // per branch: angles and lengths times 1 +- jitter (uniform)
    double width_variation = 0.0;    // widths times 1 + this * noise(s)
    double tropism_variation = 0.0;  // the tropism vector plus this * a noise vector per branch
    NoiseKind noise_kind = NoiseKind::gradient;  // the noise of bend, width and tropism variation
};

// Throws GrammarError for a ']' with no '[' or a '}' with no '{' in the word. With bend > 0
// an F longer than a tenth of a noise cycle is drawn as several segments, so the curve shows.
//
// Polygons (ABOP 5.1): '{' starts one where the turtle stands and each F, f or G/g move
// inside it traces the outline (F and f record the point they reach as a vertex, G and g
// move without recording one); a polygon that marks vertices with '.' takes those alone.
// Polygons nest ('{' inside '{' starts an inner one); each gets the colour index the
// turtle has at its '{'. A word module "~name" (ABOP's predefined surfaces) places the
// organ `name` in the turtle's frame, with the module's parameter as its size.
Skeleton interpret(const Word& word, const TurtleSettings& settings);

// Where the turtle stands when it reads each module of `word` (positions[i] for module i),
// walked as interpret() walks it; brackets and braces that do not match are passed over
// (a word in the middle of a derivation may have them). Replaces `positions`.
void turtle_positions(const Word& word, const TurtleSettings& settings,
                      std::vector<glm::vec3>& positions);

}  // namespace sylva
