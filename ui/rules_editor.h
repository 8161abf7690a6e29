// The rules editor: a multi-line text field for the grammar with line numbers, which marks a
// grammar error in place: a red band on its line and a red bar under its column.
#pragma once

#include <string>
#include <string_view>

namespace sylva::studio {

// The editor's memory between frames (ImGui keeps the text's own undo and selection).
struct RulesEditorState {
    // When set, the next frame focuses the editor and puts the cursor here (1-based).
    int select_line = 0, select_column = 1;
    int cursor = -1;      // the text cursor's byte offset while the editor is active
    bool active = false;  // the editor had the keyboard at the end of the last frame
};

struct TextMark {
    int line = 0;    // 1-based; 0: no mark
    int column = 0;  // 1-based; 0: the whole line
};

// Draws the editor `height` pixels tall and as wide as the panel; it scrolls both ways, and
// follows the cursor while typing. Returns true when the text was edited.
bool rules_editor(const char* id, std::string& text, TextMark mark, RulesEditorState& editor,
                  float height);

// Scrolls to `mark` and puts the cursor there on the next frame.
void reveal(RulesEditorState& editor, TextMark mark);

// True when Ctrl+Enter is pressed this frame while the editor has the keyboard. Call before
// rules_editor(): the press is taken from ImGui (a multi-line field would end its editing on
// it), so the editor keeps the keyboard and the cursor.
bool ctrl_enter_in_editor(const RulesEditorState& editor);

}  // namespace sylva::studio
