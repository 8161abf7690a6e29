// The studio's panels: immediate-mode functions of the state (polyscope / ImGui examples
// style). Each draws one window and edits StudioState directly; actions that take time go
// through studio_state.h's background jobs.
#pragma once

#include "ui/studio_state.h"

namespace sylva::studio {

// The side panel: template, parameters, rules, view toggles, export.
void draw_sylva_panel(StudioState& state);

// The status bar along the bottom: progress, triangles per part, time per stage.
void draw_status_bar(StudioState& state, float width, float height);

}  // namespace sylva::studio
