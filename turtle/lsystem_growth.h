// Growth method "lsystem": the template's grammar derived `generations` steps, the word read
// by the turtle (docs/grammar.md). Registered in tree/growth.cpp.
#pragma once

#include <functional>

#include "core/growth.h"
#include "turtle/lsystem_parser.h"
#include "turtle/turtle.h"
#include "turtle/word.h"

namespace sylva {

extern const GrowthMethod lsystem_growth;

// The shared parameters and the L-system's own (lsystem_params.h), by key: the constants the
// grammar's expressions see.
Constants param_constants(const TreeParams& params);

// The turtle as the template's parameters and modes set it.
TurtleSettings turtle_settings(const TreeTemplate& tree);

// The first stage alone: the template's grammar derived `generations` steps. Errors name
// the template's file and line when it was read from one.
// `progress` as DeriveSettings::progress.
Word derive_word(const TreeTemplate& tree, CancelFlag cancel = nullptr,
                 const std::function<void(float)>& progress = nullptr);

}  // namespace sylva
