// Parallel rewriting of an L-system's word (docs/grammar.md): first matching rule in written
// order, arity matching, ABOP contexts, seeded stochastic choice, and a cap on word size.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <glm/vec3.hpp>
#include <vector>

#include "core/cancel.h"
#include "turtle/lsystem.h"
#include "turtle/word.h"

namespace sylva {

struct DeriveSettings {
    int steps = 1;
    std::uint64_t seed = 1;
    // Derivation fails with a GrammarError naming the step once the word grows past this.
    std::size_t max_modules = 4'000'000;
    CancelFlag cancel = nullptr;  // checked between steps and every 4096 modules; throws Cancelled
    // Called with the finished fraction of the whole derivation (rising, ends with 1), per
    // step and every 4096 modules within one. A step's share is word_growth()'s estimate of
    // its word, so the late, large steps get most of the bar.
    std::function<void(float)> progress = nullptr;
    // The noise noise(), fbm() and noise_loop() read (the `noise_kind` parameter).
    NoiseKind noise_kind = NoiseKind::gradient;
    // Where the turtle stands at each module of a word (`positions[i]` for module i), for
    // rules that choose by noise over position (Rule::noise_choice); called once per step,
    // only for grammars that have such rules. Null: turtle_positions() with a default turtle.
    std::function<void(const Word&, std::vector<glm::vec3>& positions)> positions = nullptr;
};

// How big the word gets, known before deriving: symbol counts pushed through the rules
// `steps` times, no expression evaluated. `low` lets every module become the fewest modules
// any rule that could apply to it makes, `high` the most (a rule with a condition or a
// context may not apply, so the module staying as it is competes; stochastic rules compete
// with each other). Exact (low == high) for deterministic rules without conditions or
// contexts, such as F -> FF. Counts saturate at 1e300.
struct WordGrowth {
    double low_modules = 0, high_modules = 0;
    double low_segments = 0, high_segments = 0;  // modules F (each draws a segment)
    int first_step_over = -1;  // the first step whose `low_modules` exceeds the limit asked
};
WordGrowth word_growth(const LSystem& system, int steps, double module_limit = 1e300);

// The axiom as a word (its expressions evaluated; rand() draws from `random`, noise() and
// fbm() read `noise`, an error when null).
Word axiom_word(const LSystem& system, Random& random, const NoiseField* noise = nullptr);

// The noise field noise() and fbm() read for a derivation with this seed (gradient noise;
// with a kind, that kind's field of the same seed).
GradientNoise expression_noise(std::uint64_t seed);
NoiseField expression_noise(std::uint64_t seed, NoiseKind kind);

// Throws GrammarError on evaluation errors (naming the rule's line) or when the word
// exceeds max_modules (naming the step and the size); a word that word_growth() proves will
// exceed it is refused before the first step. Stochastic rules whose weights are all zero
// where they compete throw a GrammarError naming the first one's line and weight column.
Word derive(const LSystem& system, const DeriveSettings& settings);

}  // namespace sylva
