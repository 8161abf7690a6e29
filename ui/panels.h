// The studio's panels: immediate-mode functions of the state (polyscope / ImGui examples
// style). Each draws one window docked to an edge and edits StudioState directly; actions
// that take time go through studio_state.h's background jobs.
#pragma once

#include "ui/rules_editor.h"
#include "ui/state/studio_state.h"

namespace sylva::studio {

// Pixels the docked panels take from each edge of the window; the 3D view gets the rest.
struct PanelLayout {
    float width = 0, height = 0;  // the whole window
    float left = 0, right = 0, bottom = 0;
    float top = 0;  // the menu bar
};

PanelLayout panel_layout(float width, float height);

// Opens the studio's file dialog (Open, or Save as) on the next frame: Ctrl+O.
void request_file_dialog(bool saving);

// Along the top: File (open, save, export the tree or the forest preview's square), Edit
// (undo, redo, reset) and View (the Variants strip, "Rules from a tree", the layout panel,
// the forest preview, the shortcut list). `variants_open` / `infer_open` / `layout_open` are
// those windows' open flags; `layout_open` is null when the studio is built without the
// layout module.
void draw_menu_bar(StudioState& state, bool& variants_open, bool& infer_open, bool* layout_open);

// Left: Generate / live / undo / redo, the template picker, open / save, and the parameters.
void draw_tree_panel(StudioState& state, const PanelLayout& layout);

// Right: the rules editor with the grammar error, the view toggles, and export.
void draw_rules_panel(StudioState& state, RulesEditorState& editor, const PanelLayout& layout);

// Along the bottom: progress, triangles per part (the game mesh against its budget in the
// low-poly view), time per stage, and the frame rate while the
// window draws continuously (`fps` < 0: idle, not shown).
void draw_status_bar(StudioState& state, const PanelLayout& layout, float fps);

// The modal dialogs: the "run anyway?" confirmation of an expensive edit and the file
// dialog. Call once a frame after every other window: ImGui (1.86) aborts with
// `blocking_modal != NULL` when a window first appears after a modal opened in the same
// frame (the studio's first frame with an expensive template did).
void draw_dialogs(StudioState& state);

// True while the "run anyway?" confirmation is open (after draw_dialogs).
bool cost_dialog_open();

// True while "discard changes?" is open (after draw_dialogs).
bool discard_dialog_open();

}  // namespace sylva::studio
