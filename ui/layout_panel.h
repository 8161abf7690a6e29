// The studio's layout panel (layout/): pick a shipped 2D example, see it, the
// grammar derived from it (starter rules drawn, rules listed with their boundary strings)
// and a grid of generated variations; seed and count are editable. Drawn with ImGui draw
// lists only. Deriving takes well under a second for the shipped examples (see
// sylva-bench-layout), so it runs on the UI thread when the example changes.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "layout/graph_grammar.h"

namespace sylva::studio {

struct LayoutPanelState {
    bool open = false;
    int example = 0;  // index into layout::builtin_examples()
    int seed = 1;
    int count = 12;
    int steps = 16;
    bool dirty = true;  // derive (and generate) again before drawing
    std::optional<layout::Example> input;
    std::optional<layout::Grammar> grammar;
    std::vector<layout::PolygonMesh> starters;  // the starter rules, drawn
    std::vector<layout::PolygonMesh> variations;
    std::string error;
};

// Selects a shipped example by name and opens the panel; false when there is none.
bool select_layout_example(LayoutPanelState& state, const std::string& name);

// A floating window over the 3D view; nothing when the panel is closed.
void draw_layout_panel(LayoutPanelState& state, float width, float height);

}  // namespace sylva::studio
