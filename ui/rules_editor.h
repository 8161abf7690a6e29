// The rules editor: a multi-line text field for the grammar with line numbers, which marks a
// grammar error in place (a red band on its line and a red bar under its column) and
// underlines the places of warnings (orange, the word at the column).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace sylva::studio {

// The editor's memory between frames (ImGui keeps the text's own undo and selection).
struct RulesEditorState {
    // When set, the next frame focuses the editor and puts the cursor here (1-based).
    int select_line = 0, select_column = 1;
    int cursor = -1;      // the text cursor's byte offset while the editor is active
    bool active = false;  // the editor had the keyboard at the end of the last frame
    // The cursor's line as drawn in the last frame while active, in window pixels (top-left
    // origin), as wide as the editor: where a typed character shows (the typing bench).
    float line_x = 0, line_y = 0, line_width = 0, line_height = 0;
};

struct TextMark {
    int line = 0;    // 1-based; 0: no mark
    int column = 0;  // 1-based; 0: the whole line
};

// Draws the editor `height` pixels tall and as wide as the panel; it scrolls both ways, and
// follows the cursor while typing. `mark` is the error; `underlines` the warnings' places
// (a whole-line mark underlines the line). Returns true when the text was edited.
bool rules_editor(const char* id, std::string& text, TextMark mark, RulesEditorState& editor,
                  float height, const std::vector<TextMark>& underlines = {});

// Scrolls to `mark` and puts the cursor there on the next frame.
void reveal(RulesEditorState& editor, TextMark mark);

// True when Ctrl+Enter is pressed this frame while the editor has the keyboard. Call before
// rules_editor(): the press is taken from ImGui (a multi-line field would end its editing on
// it), so the editor keeps the keyboard and the cursor.
bool ctrl_enter_in_editor(const RulesEditorState& editor);

}  // namespace sylva::studio
