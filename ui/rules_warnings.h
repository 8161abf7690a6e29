// The grammar's warnings under the rules editor (turtle/lint.h): rules that never apply,
// unread #define constants and rule parameters, and the like, each a line the user can click
// to put the cursor at its place. A grammar error is shown by the editor itself; then this
// shows nothing.
#pragma once

#include "core/tree_template.h"
#include "ui/rules_editor.h"

namespace sylva::studio {

// Draws the warnings of `tree`'s grammar (linted again only when the grammar or the
// parameters changed). Call on the UI thread, right after rules_editor().
void rules_warnings(const TreeTemplate& tree, RulesEditorState& editor);

}  // namespace sylva::studio
