// Warnings about a grammar that parses but does not do what it says (docs/grammar.md,
// "Warnings"): rules that never apply because no word the grammar can derive has their
// predecessor with that arity, rules an earlier rule always wins over, zero weights,
// #define constants and rule parameters nothing reads, a #define that hides a template
// parameter of the same name, and word modules that neither have a rule nor draw.
//
// Pure functions of the text; no state, safe on any thread. Cost: one parse plus a pass over
// the rules per reachable (symbol, arity) kind, so a few milliseconds on any real grammar.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "turtle/lsystem_parser.h"

namespace sylva {

struct LintWarning {
    int line = 0;    // 1-based, in the grammar's own lines
    int column = 0;  // 1-based
    std::string message;
};

// The warnings of `text`, sorted by line and column. `constants` as parse_lsystem takes
// them (template parameters). `surfaces`, when not empty, are the organ names "~name" may
// use (tree/organ_surfaces.h); others are warned about. Throws GrammarError when the text
// does not parse.
std::vector<LintWarning> lint_grammar(std::string_view text, const Constants& constants = {},
                                      const std::vector<std::string>& surfaces = {});

}  // namespace sylva
