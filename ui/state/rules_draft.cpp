#include "ui/state/rules_draft.h"

#include <algorithm>

#include "core/errors.h"
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

double seconds_until_apply(const StudioState& state, std::chrono::steady_clock::time_point now) {
    if (!state.rules.pending) return 0.0;
    const double since = std::chrono::duration<double>(now - state.rules.typed_at).count();
    return std::max(kRulesPauseSeconds - since, 0.0);
}

}  // namespace sylva::studio
