// The rules editor's text between keystrokes. What is typed is a draft: it becomes the edited
// template's grammar only when typing pauses (kRulesPauseSeconds) or on Ctrl+Enter, and only
// when it parses, so a half-typed rule is never grown and the tree on screen stays the last
// one whose rules parsed. A draft that does not parse carries the parser's message, line and
// column for the editor to mark. Headless: tests/ui drives it with its own clock.
//
// Thread safety: UI thread only, like the rest of StudioState.
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "turtle/lint.h"

namespace sylva::studio {

struct StudioState;

// Typing must pause this long before the rules are applied: long enough that a word in
// progress is not grown, short enough that the tree still follows the typing.
inline constexpr double kRulesPauseSeconds = 0.6;
// The draft is linted (turtle/lint.h) after a shorter pause: its warnings are under the
// editor before the rules are applied, and for a draft that parses but is never applied (a
// held-back estimate) too.
inline constexpr double kLintPauseSeconds = 0.3;

struct RulesDraft {
    std::string text;      // what the editor shows, perhaps half typed
    std::string grammar;   // the edited template's grammar the text last agreed with
    bool pending = false;  // typed since the last apply
    std::chrono::steady_clock::time_point typed_at;  // the last keystroke
    // Why `text` was not applied (the parser's message, 1-based line and column); empty when
    // it parses or is pending.
    std::string error;
    int error_line = 0, error_column = 0;
    // The last apply came from a pause, not from the user: an estimate over the limits is
    // then shown beside the editor and the "run anyway?" dialog does not open mid-typing.
    bool quiet = false;
    // The lint of the draft as it stood when typing last paused (lint_rules_draft()),
    // whether it is applied or not: empty when it does not parse (`error` says why once it
    // is applied) or the growth method reads no grammar.
    std::vector<LintWarning> warnings;
    std::string linted;      // the text `warnings` are of: their lines and columns are in it
    std::string linted_key;  // what else the lint read: growth method, template parameters
    bool lint_done = false;
};

// Takes a grammar changed outside the editor (undo, a template picked or opened, a #define
// slider): the editor shows it, and what was typed and not applied is dropped.
void sync_rules_draft(StudioState& state);

// The editor's text changed at `now`: the pause starts again.
void rules_typed(StudioState& state, std::chrono::steady_clock::time_point now);

enum class RulesApply {
    Nothing,  // nothing typed since the last apply
    Waiting,  // typing has not paused long enough yet
    Applied,  // the text parsed and is now the edited template's grammar
    Refused,  // the text does not parse: draft.error says why, the grammar stays
};

// Applies the typed text when typing has paused kRulesPauseSeconds at `now`, or at once when
// `explicit_apply` (Ctrl+Enter). An explicit apply also makes a held-back estimate ask (the
// "run anyway?" dialog), as the user asked for the rules to run.
RulesApply apply_rules_draft(StudioState& state, std::chrono::steady_clock::time_point now,
                             bool explicit_apply);

// Lints the draft when typing has paused kLintPauseSeconds at `now` and its text (or the
// template's parameters it reads, or the growth method) changed since the last lint; a
// grammar error leaves no warnings. Returns true when it linted. A few milliseconds (one
// parse).
bool lint_rules_draft(StudioState& state, std::chrono::steady_clock::time_point now);

// Seconds until the draft is due to be linted (0 when due or nothing waits).
double seconds_until_lint(const StudioState& state, std::chrono::steady_clock::time_point now);

// Seconds until a pending draft is applied (0 when due or nothing waits): how long the main
// loop may sleep.
double seconds_until_apply(const StudioState& state, std::chrono::steady_clock::time_point now);

}  // namespace sylva::studio
