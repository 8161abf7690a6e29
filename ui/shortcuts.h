// The studio's keyboard shortcuts (F1 lists them). Keys come from GLFW's key callback, which
// main records between frames: ImGui 1.86 samples key state once per frame, so a tap shorter
// than a frame would be lost to a shortcut that asked ImGui.
#pragma once

#include <vector>

#include "ui/state/studio_state.h"

namespace sylva::studio {

// A key pressed (or repeated) since the last frame: GLFW's key code and modifier bits.
struct KeyPress {
    int key = 0, mods = 0;
};

// True while a text field, a held widget or a modal dialog has the keyboard: then keys are
// text (or the dialog's), and no shortcut but Ctrl+E fires. Reads ImGui's io from the start
// of the frame (WantTextInput, WantCaptureKeyboard) and the widget active now, so the first
// keystroke into a field just clicked is text too. Call inside a frame.
bool keyboard_taken();

// Ctrl+E export, Ctrl+Z undo, Ctrl+Y or Ctrl+Shift+Z redo, Ctrl+S save, Ctrl+O open, F frame,
// P screenshot, T turntable, F1 the shortcut list, Esc cancel, 0-3 show that LOD level of the
// game mesh and 4 its impostor (switching the low-poly view on). While keyboard_taken(), only
// Ctrl+E acts: Ctrl+Z / Ctrl+Y are then the field's own undo of the typing, and F, ')' and the
// digits are text. Call inside a frame, after the panels.
void handle_shortcuts(StudioState& state, const std::vector<KeyPress>& presses);

}  // namespace sylva::studio
