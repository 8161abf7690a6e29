// A parsed L-system (docs/grammar.md): axiom, rules with optional contexts, conditions and
// weights, the symbols context matching skips, and the names of its word modules.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "turtle/expression.h"
#include "turtle/word.h"

namespace sylva {

// A module to produce: a symbol and one expression per parameter.
struct ModuleProduction {
    char symbol = 0;
    std::vector<Expression> args;
};

// A module to match: a symbol and the names its parameters bind to (only their count is
// checked: a rule matches on symbol and arity).
struct ModulePattern {
    char symbol = 0;
    int arity = 0;
};

struct Rule {
    std::vector<ModulePattern> left;  // left context, in word order; empty when none
    ModulePattern predecessor;
    std::vector<ModulePattern> right;  // right context; empty when none
    std::optional<Expression> condition;
    std::vector<ModuleProduction> successor;
    std::optional<double> weight;  // set for stochastic rules
    // Stochastic choice by noise over where the module stands (Limbach 2004: neighbours
    // choose alike) instead of the seeded random draw: the noise's cycles per meter; 0 for
    // the random draw. Written `: weight, noise FREQUENCY`.
    double noise_choice = 0.0;
    int line = 0;           // where the rule was written, for error messages
    int column = 0;         // the predecessor's column (1-based), for warnings
    int weight_column = 0;  // the weight's column (1-based), 0 without a weight
    std::string text;       // the rule's source line
};

struct LSystem {
    std::vector<ModuleProduction> axiom;
    int axiom_line = 0;               // where the axiom was written, for error messages
    std::string axiom_text;           // its source line
    std::vector<Rule> rules;          // in the order written
    std::array<bool, 256> ignored{};  // #ignore: skipped when matching contexts
    // The names of the word symbols (Word::set_names); null when the grammar has none.
    std::shared_ptr<const WordNames> words;
};

}  // namespace sylva
