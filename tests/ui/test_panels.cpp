// The studio's panels and dialogs as ImGui frames without a window: ImGui needs a display
// size and a built font atlas, not GL, until something is rendered. Here the "run anyway?"
// dialog of an expensive template: it opens in the studio's first frame, with every panel
// appearing around it (ImGui 1.86 aborted there with `blocking_modal != NULL`), stays open
// while another window appears, and its first button starts the held-back job.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <chrono>
#include <thread>

#include "tests/ui/headless_imgui.h"
#include "tests/ui/wait_for_generations.h"
#include "tree/template_file.h"
#include "tree/template_library.h"
#include "ui/input_queue.h"
#include "ui/panels.h"
#include "ui/rules_editor.h"
#include "ui/shortcuts.h"
#include "ui/state/studio_state.h"
#include "ui/variants_strip.h"

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

// One frame as main draws it, with the keys pressed since the last one.
void frame_with_keys(StudioState& state, RulesEditorState& editor,
                     const std::vector<KeyPress>& keys) {
    ImGui::NewFrame();
    const PanelLayout layout = panel_layout(1280.0f, 800.0f);
    draw_tree_panel(state, layout);
    draw_rules_panel(state, editor, layout);
    draw_status_bar(state, layout, -1.0f);
    draw_dialogs(state);
    handle_shortcuts(state, keys);
    ImGui::Render();
}

// Typing ")", "0" and "f" into the rules editor: the keys are text, not the LOD, low-poly and
// frame shortcuts; the half-typed rule is not applied; Ctrl+Enter applies (here: refuses, as
// it does not parse, naming the line) and the editor keeps the keyboard.
TEST(StudioPanels, TypingInTheRulesEditorIsTextNotShortcuts) {
    HeadlessImGui imgui;
    ImGuiIO& io = ImGui::GetIO();
    io.KeyMap[ImGuiKey_Enter] = GLFW_KEY_ENTER;
    StudioState state;
    RulesEditorState editor;
    load_template_into(state, parse_template_file("name = \"t\"\ngrammar = '''\naxiom: F\n"
                                                  "F -> F'''\n[params]\ngenerations = 2\n",
                                                  "t.toml"));
    const std::string before = state.tree_template.grammar;
    frame_with_keys(state, editor, {{GLFW_KEY_F, 0}});
    EXPECT_TRUE(state.frame_requested);  // no field has the keyboard: F frames
    state.frame_requested = false;

    reveal(editor, TextMark{2, 7});  // the end of "F -> F"
    frame_with_keys(state, editor, {});
    frame_with_keys(state, editor, {});
    ASSERT_TRUE(editor.active);
    const std::vector<std::pair<char, KeyPress>> keys = {{'F', {GLFW_KEY_F, GLFW_MOD_SHIFT}},
                                                         {')', {GLFW_KEY_0, GLFW_MOD_SHIFT}},
                                                         {'0', {GLFW_KEY_0, 0}},
                                                         {'f', {GLFW_KEY_F, 0}},
                                                         {'t', {GLFW_KEY_T, 0}}};
    for (const auto& [c, key] : keys) {
        io.AddInputCharacter(static_cast<unsigned>(c));
        frame_with_keys(state, editor, {key});
    }
    EXPECT_EQ(state.rules.text, "axiom: F\nF -> FF)0ft");
    EXPECT_FALSE(state.view.low_poly);
    EXPECT_EQ(state.view.lod_level, 0);
    EXPECT_FALSE(state.frame_requested);
    EXPECT_FALSE(state.view.turntable);
    EXPECT_EQ(state.tree_template.grammar, before);  // half typed: not applied
    EXPECT_TRUE(state.cost_warning.empty());

    io.KeyCtrl = true;
    io.KeysDown[GLFW_KEY_ENTER] = true;
    frame_with_keys(state, editor, {{GLFW_KEY_ENTER, GLFW_MOD_CONTROL}});
    EXPECT_TRUE(editor.active);  // the field never saw the press
    io.KeyCtrl = false;
    io.KeysDown[GLFW_KEY_ENTER] = false;
    frame_with_keys(state, editor, {});
    EXPECT_FALSE(state.rules.pending);
    EXPECT_EQ(state.rules.error_line, 2);  // refused: ")" does not parse
    EXPECT_EQ(state.tree_template.grammar, before);
    EXPECT_TRUE(editor.active);  // still typing
    cancel_generations(state);
    EXPECT_TRUE(wait_for_generations(state));
}

// "Discard changes?" is an ImGui modal opened the ImGui way: OpenPopup once, BeginPopupModal
// every frame; it stays open until answered and closes when the switch is confirmed.
TEST(StudioPanels, TheDiscardDialogOpensOverUnsavedEditsAndCloses) {
    HeadlessImGui imgui;
    StudioState state;
    RulesEditorState editor;
    load_template_into(state, load_template("oak"));
    state.tree_template.params.seed += 1;
    frame_with_keys(state, editor, {});
    EXPECT_FALSE(switch_template(state, {load_template("birch"), {}, {}}));
    for (int i = 0; i < 3; ++i) {
        ImGui::NewFrame();
        const PanelLayout layout = panel_layout(1280.0f, 800.0f);
        draw_tree_panel(state, layout);
        draw_rules_panel(state, editor, layout);
        draw_dialogs(state);
        EXPECT_TRUE(discard_dialog_open());
        ImGui::Render();
    }
    confirm_switch(state);
    ImGui::NewFrame();
    draw_dialogs(state);
    EXPECT_FALSE(discard_dialog_open());
    ImGui::Render();
    EXPECT_EQ(state.tree_template.name, "birch");
    cancel_generations(state);
    EXPECT_TRUE(wait_for_generations(state));
}

// The Variants strip's thumbnails fit side by side in the space between the panels.
TEST(StudioPanels, VariantThumbnailsFitTheStrip) {
    for (float width : {300.0f, 480.0f, 900.0f})
        for (int count : {1, 4, 6, 12}) {
            const float side = variant_thumbnail_size(width, count, 8.0f);
            EXPECT_LE(side, static_cast<float>(kThumbnailSize));
            if (side > 32.0f) {  // the smallest side overflows only where 32 px cannot fit
                EXPECT_LE(static_cast<float>(count) * side + 8.0f * static_cast<float>(count - 1),
                          width)
                    << width << " " << count;
            }
        }
}

// Quick typing under a slow frame rate: "a", Backspace, "b" and Ctrl+A within one frame
// reach ImGui over several frames, in order, each key seen down for a frame.
TEST(StudioPanels, TheInputQueueKeepsQuickKeysInOrder) {
    auto key = [](int k, int action, int mods = 0) {
        return InputEvent{InputEvent::Key, k, 0, action, mods, 0};
    };
    auto typed = [](char c) { return InputEvent{InputEvent::Char, 0, 0, 0, 0, unsigned(c)}; };
    std::vector<InputEvent> events = {key(GLFW_KEY_A, GLFW_PRESS),
                                      typed('a'),
                                      key(GLFW_KEY_A, GLFW_RELEASE),
                                      key(GLFW_KEY_BACKSPACE, GLFW_PRESS),
                                      key(GLFW_KEY_BACKSPACE, GLFW_RELEASE),
                                      key(GLFW_KEY_B, GLFW_PRESS),
                                      typed('b'),
                                      key(GLFW_KEY_B, GLFW_RELEASE),
                                      key(GLFW_KEY_LEFT_CONTROL, GLFW_PRESS, GLFW_MOD_CONTROL),
                                      key(GLFW_KEY_A, GLFW_PRESS, GLFW_MOD_CONTROL),
                                      key(GLFW_KEY_A, GLFW_RELEASE, GLFW_MOD_CONTROL),
                                      key(GLFW_KEY_LEFT_CONTROL, GLFW_RELEASE)};
    events.push_back(key(GLFW_KEY_BACKSPACE, GLFW_PRESS));  // Backspace twice
    events.push_back(key(GLFW_KEY_BACKSPACE, GLFW_RELEASE));
    events.push_back(key(GLFW_KEY_BACKSPACE, GLFW_PRESS));
    events.push_back(key(GLFW_KEY_BACKSPACE, GLFW_RELEASE));
    std::vector<std::size_t> frames;
    std::span<const InputEvent> left(events);
    while (!left.empty()) {
        const std::size_t n = events_for_one_frame(left);
        ASSERT_GT(n, 0u);
        frames.push_back(n);
        left = left.subspan(n);
    }
    // 1: A down, 'a'; 2: A up, Backspace down; 3: Backspace up, B down, 'b'; 4: B up, Ctrl
    // down, A down (with Ctrl); 5: A up, Ctrl up, Backspace down; 6: Backspace up (it goes
    // down again only in the next frame); 7: down; 8: up.
    EXPECT_EQ(frames, (std::vector<std::size_t>{2, 2, 3, 3, 3, 1, 1, 1}));
}

}  // namespace
}  // namespace sylva::studio
