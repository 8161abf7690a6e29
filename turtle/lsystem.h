// A parsed L-system (docs/grammar.md): axiom, rules with optional contexts, conditions and
// weights, and the symbols context matching skips.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "turtle/expression.h"

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
    int line = 0;                  // where the rule was written, for error messages
    std::string text;              // the rule's source line
};

struct LSystem {
    std::vector<ModuleProduction> axiom;
    int axiom_line = 0;               // where the axiom was written, for error messages
    std::string axiom_text;           // its source line
    std::vector<Rule> rules;          // in the order written
    std::array<bool, 256> ignored{};  // #ignore: skipped when matching contexts
};

}  // namespace sylva
