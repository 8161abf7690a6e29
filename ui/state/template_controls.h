// What the "this tree" sliders are made of: the grammar's own constants (#define lines that
// carry a range and a help text) and, for the global parameters, which of them the
// template's rules and growth method never read (shown disabled, with the reason). Headless:
// tests/ui checks it without a window.
//
// The comment syntax that makes a #define a slider (a '#' after the value starts its comment):
//
//   #define a  34     # [10, 60] fork angle, degrees
//   #define n  5      # [2, 9] branches per whorl         (integers: a whole-number slider)
//
// "[min, max]" first, then the help text the tooltip shows. A #define without a range, or
// whose value is an expression, stays text only.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "core/param_table.h"
#include "core/tree_template.h"

namespace sylva::studio {

struct GrammarConstant {
    std::string name;
    double value = 0;
    double min = 0, max = 0;
    std::string help;
    bool integer = false;  // the value and both ends are whole numbers
    int line = 0;          // 1-based line of the #define in the grammar
};

// The #define lines with a "[min, max] help" comment and a plain number as value, in order.
std::vector<GrammarConstant> grammar_constants(std::string_view grammar);

// Rewrites the value of `name`'s #define in place (spacing and comment kept), written as
// the shortest text that reads back to `value`. False when there is no such #define.
bool set_grammar_constant(std::string& grammar, std::string_view name, double value);

// The shortest text that reads back to exactly `value` ("0.8", "34", "1e-07").
std::string shortest_number(double value);

// A slider's value rounded to a step that suits its range (three digits of the span), so a
// drag writes 0.82, not 0.8213419.
double round_for_range(double value, double min, double max);

// Global parameters the template's rules or growth method never read, each with the reason
// ("every F in the rules gives its own length"): tree/unread_params.h's answer, kept per
// template and parameters since the panel asks every frame. Keys of param_infos().
// Thread-safe.
std::map<std::string, std::string, std::less<>> inert_params(const TreeTemplate& tree);

// A #define slider's label: its help comment up to the first comma or parenthesis ("# [10,
// 60] fork angle, degrees" -> "fork angle"; "fronds: angle from the trunk" stays whole, as
// two constants may share the words before a colon), the constant's name when it has none.
// The whole help and the name stay in the tooltip.
std::string constant_label(const GrammarConstant& constant);

// True when the search field's `query` finds the text: every word of it (split at spaces) is
// in `text`, ignoring case. An empty query finds everything.
bool search_finds(std::string_view query, std::string_view text);

// The text the search field looks in for a parameter: its key, its words ("leaf density"),
// its help and its group's title.
std::string parameter_search_text(const ParamInfo& info);

// One control of the parameter panel: a parameter of the registry (tree/parameters.h) and,
// when the tree never reads it, why (the control is then greyed out).
struct ParameterRow {
    const ParamInfo* info;
    std::string unread;  // empty: read
};

// Every parameter of the registry, by group (param_groups()' order), each with its reason
// when inert: what the panel draws, so a growth method's parameters show without an edit
// here.
std::vector<ParameterRow> parameter_rows(const TreeTemplate& tree);

// The slider's ends for a parameter: its useful range, widened so it contains `value` (a
// template's own default, e.g. the spruce's leaf_density 4000) and clipped to the valid range.
struct SliderRange {
    double min, max;
};
SliderRange slider_range(std::string_view key, double value);

// The tooltip's line for trunk_resolution / crown_resolution when a tree with a budget is
// meshed below the slider's value (tree/pipeline.h: what the budget can show): "\nmeshed at
// 60 for the budget of 800 triangles (...)", or "" (other keys, or the slider's value used).
std::string budget_resolution_note(const TreeParams& params, std::string_view key);

}  // namespace sylva::studio
