// Parallel rewriting of an L-system's word (SPEC section 1): first matching rule in written
// order, arity matching, ABOP contexts, seeded stochastic choice, and a cap on word size.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>

#include "core/cancel.h"
#include "turtle/lsystem.h"
#include "turtle/word.h"

namespace sylva {

struct DeriveSettings {
    int steps = 1;
    std::uint64_t seed = 1;
    // Derivation fails with a GrammarError naming the step once the word grows past this.
    std::size_t max_modules = 4'000'000;
    CancelFlag cancel = nullptr;  // checked between steps; throws Cancelled
};

// The axiom as a word (its expressions evaluated; rand() draws from `random`).
Word axiom_word(const LSystem& system, Random& random);

// Throws GrammarError on evaluation errors (naming the rule's line) or when the word
// exceeds max_modules (naming the step and the size).
Word derive(const LSystem& system, const DeriveSettings& settings);

}  // namespace sylva
