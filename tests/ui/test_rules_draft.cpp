// The rules editor's draft (ui/state/rules_draft.h): typed text becomes the grammar only on a
// pause or Ctrl+Enter and only when it parses, so the tree on screen is never of a half-typed
// rule; an estimate over the limits reached on a pause waits beside the editor, and undoing
// it frames the view again. Time is the test's own clock: no sleeping, no timing asserted.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "core/errors.h"
#include "tests/ui/wait_for_generations.h"
#include "tree/template_file.h"
#include "turtle/lsystem_growth.h"
#include "turtle/lsystem_parser.h"
#include "ui/state/rules_draft.h"
#include "ui/state/studio_state.h"

namespace sylva::studio {
namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

// F -> F at 14 generations is one segment; F -> FF doubles it to 16384, over the 10000
// segments the studio runs unasked.
constexpr const char* kDoubling = R"(name = "doubling"
grammar = '''
axiom: F
F -> F'''
[params]
generations = 14
)";

bool parses(const StudioState& state) {
    try {
        parse_lsystem(state.tree_template.grammar, param_constants(state.tree_template.params));
        return true;
    } catch (const InputError&) {
        return false;
    }
}

StudioState opened(const char* text) {
    StudioState state;
    load_template_into(state, parse_template_file(text, "t.toml"));
    sync_rules_draft(state);
    return state;
}

// Types `typed` after the draft's text, one key every `gap`, applying as each frame does;
// returns the time of the last key. Every grammar the template held parsed.
Clock::time_point type(StudioState& state, const std::string& typed, Clock::time_point t,
                       milliseconds gap) {
    for (char c : typed) {
        t += gap;
        apply_rules_draft(state, t, false);  // a frame just before the key
        EXPECT_TRUE(parses(state)) << "applied a text that does not parse:\n"
                                   << state.tree_template.grammar;
        state.rules.text += c;
        rules_typed(state, t);
        apply_rules_draft(state, t, false);
        EXPECT_TRUE(parses(state)) << "applied a text that does not parse:\n"
                                   << state.tree_template.grammar;
    }
    return t;
}

TEST(RulesDraft, QuickTypingIsAppliedOnceItPauses) {
    StudioState state = opened(kDoubling);
    const std::string before = state.tree_template.grammar;
    Clock::time_point t = type(state, "\nG -> F[+G]", Clock::now(), milliseconds(120));
    EXPECT_EQ(state.tree_template.grammar, before);  // nothing applied mid-word
    EXPECT_TRUE(state.rules.pending);
    EXPECT_GT(seconds_until_apply(state, t), 0.0);
    EXPECT_EQ(apply_rules_draft(state, t + milliseconds(400), false), RulesApply::Waiting);
    EXPECT_EQ(apply_rules_draft(state, t + milliseconds(700), false), RulesApply::Applied);
    EXPECT_EQ(state.tree_template.grammar, before + "\nG -> F[+G]");
    EXPECT_FALSE(state.rules.pending);
}

TEST(RulesDraft, SlowTypingAppliesOnlyTheTextsThatParse) {
    StudioState state = opened(kDoubling);
    const std::string before = state.tree_template.grammar;
    // A second between keys: every prefix is tried; "G -> F[+G" and "G -> F(" do not parse.
    Clock::time_point t = type(state, "\nG -> F[+G", Clock::now(), milliseconds(1000));
    t += milliseconds(1000);
    EXPECT_EQ(apply_rules_draft(state, t, false), RulesApply::Refused);
    EXPECT_FALSE(state.rules.error.empty());
    EXPECT_EQ(state.rules.error_line, 3);
    EXPECT_NE(state.tree_template.grammar, state.rules.text);
    t = type(state, "]", t, milliseconds(1000));
    EXPECT_EQ(apply_rules_draft(state, t + milliseconds(1000), false), RulesApply::Applied);
    EXPECT_EQ(state.tree_template.grammar, before + "\nG -> F[+G]");
    EXPECT_TRUE(state.rules.error.empty());
}

TEST(RulesDraft, ARefusedTextKeepsTheTreeAndNamesTheLine) {
    StudioState state = opened(kDoubling);
    start_generation(state);
    ASSERT_TRUE(wait_for_generations(state));
    const auto good = state.tree;
    const std::string before = state.tree_template.grammar;
    state.rules.text += "\nA -> F[(\n";
    rules_typed(state, Clock::now());
    EXPECT_EQ(apply_rules_draft(state, Clock::now(), true), RulesApply::Refused);
    EXPECT_EQ(state.tree_template.grammar, before);
    EXPECT_EQ(state.rules.error_line, 3);  // the grammar's own lines
    EXPECT_GT(state.rules.error_column, 0);
    EXPECT_FALSE(edit_pending(state));  // nothing to grow
    EXPECT_EQ(state.tree, good);
}

// The draft is linted after a typing pause, before it is applied: a rule that can never
// fire is warned about while the grammar on screen is still the old one; a half-typed rule
// that does not parse gives no warnings, and an unchanged text is not linted again.
TEST(RulesDraft, TheDraftIsLintedOnAPauseBeforeItIsApplied) {
    StudioState state = opened(kDoubling);
    Clock::time_point t = Clock::now();
    ASSERT_TRUE(lint_rules_draft(state, t));  // the opened rules
    EXPECT_TRUE(state.rules.warnings.empty());
    const std::string before = state.tree_template.grammar;
    t = type(state, "\nX -> FF", t, milliseconds(100));            // no word ever holds an X
    EXPECT_FALSE(lint_rules_draft(state, t + milliseconds(100)));  // still typing
    EXPECT_GT(seconds_until_lint(state, t), 0.0);
    ASSERT_TRUE(lint_rules_draft(state, t + milliseconds(400)));
    ASSERT_EQ(state.rules.warnings.size(), 1u);
    EXPECT_EQ(state.rules.warnings[0].line, 3);
    EXPECT_EQ(state.rules.linted, state.rules.text);
    EXPECT_EQ(state.tree_template.grammar, before);                // parses, and is not applied yet
    EXPECT_FALSE(lint_rules_draft(state, t + milliseconds(500)));  // the same text
    ASSERT_EQ(apply_rules_draft(state, t + milliseconds(700), false), RulesApply::Applied);
    EXPECT_EQ(state.rules.warnings.size(), 1u);                      // still of the text shown
    t = type(state, "[", t + milliseconds(700), milliseconds(100));  // does not parse
    ASSERT_TRUE(lint_rules_draft(state, t + milliseconds(400)));
    EXPECT_TRUE(state.rules.warnings.empty());
    EXPECT_EQ(state.rules.linted, state.rules.text);
}

TEST(RulesDraft, CtrlEnterAppliesAtOnce) {
    StudioState state = opened(kDoubling);
    state.rules.text += "\nG -> F";
    rules_typed(state, Clock::now());
    EXPECT_EQ(apply_rules_draft(state, Clock::now(), true), RulesApply::Applied);
    EXPECT_EQ(state.tree_template.grammar, state.rules.text);
}

TEST(RulesDraft, AnOutsideChangeReplacesTheDraft) {
    StudioState state = opened(kDoubling);
    const std::string before = state.tree_template.grammar;
    state.rules.text += "\nG -> F";
    rules_typed(state, Clock::now());
    apply_rules_draft(state, Clock::now(), true);
    commit_edit(state);
    undo(state);  // the grammar changes outside the editor
    sync_rules_draft(state);
    EXPECT_EQ(state.rules.text, before);
    EXPECT_FALSE(state.rules.pending);
}

TEST(RulesDraft, AnExpensiveRuleOnAPauseWaitsBesideTheEditorUntilApplied) {
    StudioState state = opened(kDoubling);
    start_generation(state);
    ASSERT_TRUE(wait_for_generations(state));
    ASSERT_TRUE(state.cost_warning.empty());
    const Clock::time_point t = type(state, "F", Clock::now(), milliseconds(100));
    ASSERT_EQ(apply_rules_draft(state, t + milliseconds(700), false), RulesApply::Applied);
    ASSERT_TRUE(edit_pending(state));
    start_generation(state);  // as the main loop does after an edit
    EXPECT_FALSE(state.cost_warning.empty());
    EXPECT_TRUE(state.cost_warning_quiet);  // no dialog mid-typing
    EXPECT_FALSE(generation_running(state));

    // Ctrl+Enter: the user asks for these rules, so the dialog may ask.
    apply_rules_draft(state, t + milliseconds(900), true);
    EXPECT_FALSE(state.cost_warning_quiet);
    EXPECT_FALSE(state.cost_warning.empty());
}

TEST(RulesDraft, UndoingARefusedEditFramesTheView) {
    StudioState state = opened(kDoubling);
    start_generation(state);
    ASSERT_TRUE(wait_for_generations(state));
    poll_jobs(state);
    const std::string before = state.tree_template.grammar;
    state.frame_next_tree = state.frame_requested = false;
    state.rules.text += "F";
    rules_typed(state, Clock::now());
    apply_rules_draft(state, Clock::now(), true);
    start_generation(state);
    ASSERT_FALSE(state.cost_warning.empty());
    undo_refused_edit(state);
    EXPECT_EQ(state.tree_template.grammar, before);
    EXPECT_TRUE(state.cost_warning.empty());
    EXPECT_TRUE(state.frame_requested);
    EXPECT_TRUE(state.frame_next_tree);
    sync_rules_draft(state);
    EXPECT_EQ(state.rules.text, before);
}

}  // namespace
}  // namespace sylva::studio
