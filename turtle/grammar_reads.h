// What a grammar's text reads of the turtle's defaults and the template's parameters, found
// by scanning the text (no derivation): whether a symbol is ever drawn without its own
// argument, whether an expression names a parameter, whether the axiom sets its own width.
// The L-system's unread parameters (lsystem_growth.cpp) are decided with these. Pure
// functions of the text: safe from any thread.
#pragma once

#include <string_view>
#include <vector>

namespace sylva {

// The lines of `text`, without their newlines (a last line without one included).
std::vector<std::string_view> grammar_lines(std::string_view text);

// True when one of `symbols` ("Ff", "&^") is drawn without an argument in the axiom or a
// successor, so the turtle uses its default for it.
bool grammar_uses_default(std::string_view grammar, std::string_view symbols);

// True when an expression of the grammar (a #define's value included, comments not) names
// `key` as a whole word.
bool grammar_names(std::string_view grammar, std::string_view key);

// True when the axiom, or the rules it starts with (two levels deep), sets a width with
// '!(w)' before anything is drawn: the starting width (branch_width) is then never used.
bool axiom_sets_width(std::string_view grammar);

}  // namespace sylva
