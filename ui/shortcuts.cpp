#include "ui/shortcuts.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "ui/impostor_view.h"
#include "ui/panels.h"

namespace sylva::studio {

bool keyboard_taken() {
    const ImGuiIO& io = ImGui::GetIO();
    return io.WantTextInput || io.WantCaptureKeyboard || ImGui::IsAnyItemActive();
}

void handle_shortcuts(StudioState& state, const std::vector<KeyPress>& presses) {
    const bool taken = keyboard_taken();
    for (const KeyPress& press : presses) {
        const bool ctrl = press.mods & GLFW_MOD_CONTROL, shift = press.mods & GLFW_MOD_SHIFT;
        if (ctrl && press.key == GLFW_KEY_E) start_export(state);
        if (taken) continue;
        if (ctrl && press.key == GLFW_KEY_Z) shift ? redo(state) : undo(state);
        if (ctrl && press.key == GLFW_KEY_Y) redo(state);
        if (ctrl && press.key == GLFW_KEY_S) save_template_to_file(state);
        if (ctrl && press.key == GLFW_KEY_O) request_file_dialog(false);
        if (!ctrl && press.key == GLFW_KEY_F) state.frame_requested = true;
        if (!ctrl && press.key == GLFW_KEY_P) state.screenshot_requested = true;
        if (!ctrl && press.key == GLFW_KEY_T) state.view.turntable = !state.view.turntable;
        if (press.key == GLFW_KEY_F1) state.show_shortcuts = !state.show_shortcuts;
        if (press.key == GLFW_KEY_ESCAPE) cancel_generation(state);
        for (int level = 0; level <= kImpostorSlot; ++level)
            if (!ctrl && (press.key == GLFW_KEY_0 + level || press.key == GLFW_KEY_KP_0 + level)) {
                state.view.low_poly = true;
                state.view.lod_level = level;
            }
    }
}

}  // namespace sylva::studio
