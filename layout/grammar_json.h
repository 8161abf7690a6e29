// Grammar files: JSON, "format": "sylva-layout-grammar", version 2. What derive writes, the
// reader takes back (the limits of limits.h hold for both); the reader checks every index,
// every graph (planar, complete or with one open boundary as its role needs) and that both
// sides of every rule have the same boundary places with the same labels, raising
// InputError naming the key.
#pragma once

#include <string>

#include "layout/graph_grammar.h"

namespace sylva::layout {

std::string write_grammar_json(const Grammar& grammar);
Grammar read_grammar_json(const std::string& text, const std::string& source = "grammar");

}  // namespace sylva::layout
