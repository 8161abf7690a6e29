// `sylva lint` and `sylva derive --lint`: a template's grammar warnings (turtle/lint.h) as
// FILE:LINE:COLUMN: warning: MESSAGE, the place in the file the grammar stands in (a
// built-in template's in its templates/NAME.toml).
#pragma once

#include <cstdio>

#include "core/tree_template.h"

namespace sylva {

// Prints the warnings of `tree`'s grammar to `to`; returns how many. A template that grows
// without a grammar has none. Throws GrammarError (relocated to the file) when the grammar
// does not parse.
std::size_t print_lint(const TreeTemplate& tree, std::FILE* to);

// `sylva lint`: the warnings on stdout, then a count on stderr. Returns the exit code: 0
// (warnings do not fail; a grammar error throws).
int run_lint(const TreeTemplate& tree);

}  // namespace sylva
