#include "ui/state/rules_draft.h"

#include <algorithm>

#include "core/errors.h"
#include "tree/organ_surfaces.h"
#include "turtle/lsystem_growth.h"
#include "turtle/lsystem_parser.h"
#include "ui/state/studio_state.h"

namespace sylva::studio {

void sync_rules_draft(StudioState& state) {
    RulesDraft& draft = state.rules;
    const std::string& grammar = state.tree_template.grammar;
    if (grammar == draft.grammar) return;
    draft.text = draft.grammar = grammar;
    draft.pending = false;
    draft.error.clear();
    draft.error_line = draft.error_column = 0;
}

void rules_typed(StudioState& state, std::chrono::steady_clock::time_point now) {
    state.rules.pending = true;
    state.rules.typed_at = now;
}

RulesApply apply_rules_draft(StudioState& state, std::chrono::steady_clock::time_point now,
                             bool explicit_apply) {
    RulesDraft& draft = state.rules;
    if (explicit_apply) {
        draft.quiet = false;  // a held-back estimate now asks
        state.cost_warning_quiet = false;
    } else {
        if (!draft.pending) return RulesApply::Nothing;
        if (seconds_until_apply(state, now) > 0.0) return RulesApply::Waiting;
    }
    draft.pending = false;
    if (draft.text == state.tree_template.grammar) {
        draft.error.clear();
        draft.error_line = draft.error_column = 0;
        return RulesApply::Nothing;
    }
    try {
        // The parse a generation starts with (turtle/lsystem_growth.cpp): what parses here
        // grows, so only a derivation or meshing error can follow.
        parse_lsystem(draft.text, param_constants(state.tree_template.params));
    } catch (const InputError& e) {
        draft.error = e.what();
        draft.error_line = e.line();
        draft.error_column = e.column();
        return RulesApply::Refused;
    }
    draft.error.clear();
    draft.error_line = draft.error_column = 0;
    draft.quiet = !explicit_apply;
    state.tree_template.grammar = draft.grammar = draft.text;
    return RulesApply::Applied;
}

namespace {

// What the lint reads besides the text: the parameters parse_lsystem sees as constants, and
// the growth method (a method without a grammar is not linted).
std::string lint_key(const StudioState& state) {
    std::string key = state.tree_template.growth;
    for (const auto& [name, value] : param_constants(state.tree_template.params))
        key += "|" + name + "=" + std::to_string(value);
    return key;
}

double seconds_since_typing(const StudioState& state, std::chrono::steady_clock::time_point now) {
    return std::chrono::duration<double>(now - state.rules.typed_at).count();
}

}  // namespace

double seconds_until_lint(const StudioState& state, std::chrono::steady_clock::time_point now) {
    if (!state.rules.pending) return 0.0;
    return std::max(kLintPauseSeconds - seconds_since_typing(state, now), 0.0);
}

bool lint_rules_draft(StudioState& state, std::chrono::steady_clock::time_point now) {
    RulesDraft& draft = state.rules;
    if (seconds_until_lint(state, now) > 0.0) return false;
    std::string key = lint_key(state);
    if (draft.lint_done && draft.linted == draft.text && draft.linted_key == key) return false;
    draft.linted = draft.text;
    draft.linted_key = std::move(key);
    draft.lint_done = true;
    draft.warnings.clear();
    if (state.tree_template.growth != lsystem_growth.name) return true;
    try {
        draft.warnings = lint_grammar(draft.text, param_constants(state.tree_template.params),
                                      organ_surface_names());
    } catch (const InputError&) {
        // The parser's error is the editor's mark once the draft is applied.
    }
    return true;
}

double seconds_until_apply(const StudioState& state, std::chrono::steady_clock::time_point now) {
    if (!state.rules.pending) return 0.0;
    const double since = std::chrono::duration<double>(now - state.rules.typed_at).count();
    return std::max(kRulesPauseSeconds - since, 0.0);
}

}  // namespace sylva::studio
