// The rules draft's warnings under the rules editor (turtle/lint.h, linted by
// ui/state/rules_draft.h after a typing pause, applied or not): rules that never apply,
// unread #define constants and rule parameters, and the like, each a line the user can click
// to put the cursor at its place; the editor underlines the same places. A grammar error is
// shown by the editor itself; then this shows nothing.
#pragma once

#include <vector>

#include "ui/rules_editor.h"
#include "ui/state/rules_draft.h"

namespace sylva::studio {

// The places the editor underlines: the draft's warnings when they are of the text it shows
// (typing since the lint moved them: none until the next lint).
std::vector<TextMark> warning_marks(const RulesDraft& draft);

// Draws the draft's warnings. Call on the UI thread, right after rules_editor().
void rules_warnings(const RulesDraft& draft, RulesEditorState& editor);

}  // namespace sylva::studio
