// One key=value setting of a template, as `sylva export --set`, `sylva batch` and species
// files give it: a parameter of the registry (tree/parameters.h) or a #define constant of
// the template's grammar (tree/grammar_constants.h), so the command line reaches every knob
// the studio shows. Pure functions of their arguments: safe from any thread once the growth
// methods are registered.
#pragma once

#include <string>
#include <string_view>

#include "core/tree_template.h"

namespace sylva {

// Sets `key` of `tree` from text. A registry parameter is set as set_param() sets it; a
// #define of the grammar (a key the registry does not know, or both) gets the number, held to
// its "# [min, max]" comment's range when it has one and to whole numbers when the range and
// value are whole. Throws InputError naming the key and the range (or, for an unknown key,
// the parameters and the grammar's #define names).
void set_template_value(TreeTemplate& tree, std::string_view key, std::string_view value);

// The same from a number (species files' JSON numbers, a batch's jittered values).
void set_template_value(TreeTemplate& tree, std::string_view key, double value);

// The #define names of the template's grammar, ", "-separated ("a, f, s, d"); "" for none.
std::string grammar_define_names(const TreeTemplate& tree);

}  // namespace sylva
