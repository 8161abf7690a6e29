// A grammar's #define constants, read and rewritten in the text: what `sylva export --set`,
// `sylva batch --jitter NAME=J` and species files change when a key names a #define. The
// comment that gives a constant its range (the studio makes it a slider):
//
//   #define a  34     # [10, 60] fork angle, degrees
//
// "[min, max]" first, then the help text. A #define without a range comment has none; one
// whose value is an expression has no number. Pure functions of the text: safe from any
// thread.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sylva {

struct GrammarDefine {
    std::string name;
    std::optional<double> value;     // nullopt: the value is an expression
    std::optional<double> min, max;  // the comment's "[min, max]", both or neither
    std::string help;                // the comment after the range
    bool integer = false;  // the value and both ends are whole numbers (a whole-number slider)
    int line = 0;          // 1-based line of the #define in the grammar
};

// Every #define line of `grammar`, in order.
std::vector<GrammarDefine> grammar_defines(std::string_view grammar);

// The #define named `name` (the first, when the grammar defines it twice); nullopt for none.
std::optional<GrammarDefine> find_grammar_define(std::string_view grammar, std::string_view name);

// Rewrites the value of every #define named `name` to `value` as the shortest text that reads
// back to it (spacing and comment kept). False when the grammar defines no such name.
bool set_grammar_define(std::string& grammar, std::string_view name, double value);

}  // namespace sylva
