// The studio's panels and dialogs as ImGui frames without a window: ImGui needs a display
// size and a built font atlas, not GL, until something is rendered. Here the "run anyway?"
// dialog of an expensive template: it opens in the studio's first frame, with every panel
// appearing around it (ImGui 1.86 aborted there with `blocking_modal != NULL`), stays open
// while another window appears, and its first button starts the held-back job.
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <chrono>
#include <thread>

#include "tests/ui/headless_imgui.h"
#include "tests/ui/wait_for_generations.h"
#include "tree/template_file.h"
#include "ui/panels.h"
#include "ui/rules_editor.h"
#include "ui/state/studio_state.h"

namespace sylva::studio {
namespace {

// F -> FF at 14 generations: 16384 segments, over the 10000 the studio runs unasked.
constexpr const char* kExpensive = R"(name = "doubling"
grammar = '''
axiom: F
F -> FF
'''
[params]
generations = 14
)";

// One studio frame, the panels in main.cpp's order. Returns whether the cost dialog is open.
bool frame(StudioState& state, RulesEditorState& editor) {
    ImGui::NewFrame();
    const PanelLayout layout = panel_layout(1280.0f, 800.0f);
    draw_tree_panel(state, layout);
    draw_rules_panel(state, editor, layout);
    draw_status_bar(state, layout, -1.0f);
    draw_dialogs(state);
    const bool open = cost_dialog_open();
    ImGui::Render();
    return open;
}

TEST(StudioPanels, TheCostDialogOpensInTheFirstFrameAndRunsTheJob) {
    HeadlessImGui imgui;
    StudioState state;
    RulesEditorState editor;
    load_template_into(state, parse_template_file(kExpensive, "doubling.toml"));
    start_generation(state);
    ASSERT_FALSE(state.cost_warning.empty());
    ASSERT_FALSE(state.job.has_value());

    // The first frame: the Tree panel, then the dialog opens, the other panels appear.
    EXPECT_TRUE(frame(state, editor));
    EXPECT_TRUE(frame(state, editor));
    // A window that first appears while the dialog is open goes behind it.
    state.show_shortcuts = true;
    EXPECT_TRUE(frame(state, editor));
    EXPECT_TRUE(frame(state, editor));
    EXPECT_FALSE(state.job.has_value());  // nothing runs until asked

    // Click "Run anyway", the first button on the dialog's last row.
    const ImGuiWindow* dialog = ImGui::FindWindowByName("Expensive tree");
    ASSERT_NE(dialog, nullptr);
    const ImGuiStyle& style = ImGui::GetStyle();
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(
        dialog->Pos.x + style.WindowPadding.x + 4.0f,
        dialog->Pos.y + dialog->Size.y - style.WindowPadding.y - 0.5f * ImGui::GetFrameHeight());
    frame(state, editor);  // hover
    io.MouseDown[0] = true;
    frame(state, editor);
    io.MouseDown[0] = false;
    const bool still_open = frame(state, editor);  // released: pressed
    ASSERT_TRUE(state.job.has_value()) << "the click missed \"Run anyway\"";
    EXPECT_TRUE(state.cost_warning.empty());
    EXPECT_FALSE(still_open);
    cancel_generation(state);
    EXPECT_FALSE(frame(state, editor));
    EXPECT_TRUE(wait_for_generations(state));
}

}  // namespace
}  // namespace sylva::studio
