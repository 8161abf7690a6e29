// The ImGui panels, each a function of the studio state: it draws what the state holds and
// records what the user asked for (e.g. quit_requested); main acts on it.
#pragma once

#include "ui/studio_state.h"

namespace sylva::studio {

// "Sylva": the template, the tree's size, the pipeline's stage times, and Quit.
void draw_sylva_panel(StudioState& state);

}  // namespace sylva::studio
