// Reads the grammar syntax of docs/grammar.md (ABOP/cpfg style) and Heuer's (2022)
// "#axiom / #rules" format into an LSystem.
#pragma once

#include <map>
#include <string>
#include <string_view>

#include "turtle/lsystem.h"

namespace sylva {

// Constants visible to every expression, e.g. template parameters; #define overrides them.
using Constants = std::map<std::string, double, std::less<>>;

// Parameters one module may carry: far more than any grammar needs (ABOP's use up to six),
// few enough that a module cannot exhaust memory.
constexpr int kMaxModuleParameters = 64;

// Throws GrammarError naming line and column (with the line and a caret) on bad input.
LSystem parse_lsystem(std::string_view text, const Constants& constants = {});

}  // namespace sylva
