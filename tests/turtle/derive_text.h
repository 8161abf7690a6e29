// Test helper: derive a grammar given as text.
#pragma once

#include <string>

#include "turtle/derivation.h"
#include "turtle/lsystem_parser.h"

namespace sylva {

inline Word derive_text(const std::string& grammar, int steps, std::uint64_t seed = 1) {
    DeriveSettings settings;
    settings.steps = steps;
    settings.seed = seed;
    return derive(parse_lsystem(grammar), settings);
}

}  // namespace sylva
