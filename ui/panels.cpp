#include "ui/panels.h"

#include <imgui.h>

namespace sylva::studio {
namespace {

void stage_time_row(const char* stage, double ms) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(stage);
    ImGui::TableNextColumn();
    ImGui::Text("%9.1f ms", ms);
}

}  // namespace

void draw_sylva_panel(StudioState& state) {
    ImGui::SetNextWindowPos(ImVec2(12.0f, 12.0f), ImGuiCond_FirstUseEver);
    ImGui::Begin("Sylva", nullptr, ImGuiWindowFlags_AlwaysAutoResize);

    ImGui::Text("Template: %s", state.tree_template.name.c_str());
    if (!state.tree_template.description.empty()) {
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 20.0f);
        ImGui::TextDisabled("%s", state.tree_template.description.c_str());
        ImGui::PopTextWrapPos();
    }
    ImGui::Separator();

    if (generation_running(state)) {
        ImGui::TextUnformatted("Generating...");
    }
    if (!state.error.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 20.0f);
        ImGui::TextUnformatted(state.error.c_str());
        ImGui::PopTextWrapPos();
        ImGui::PopStyleColor();
    }
    if (state.tree) {
        const Tree& tree = *state.tree;
        ImGui::Text("Segments:  %zu", tree.skeleton.segments.size());
        ImGui::Text("Triangles: %zu", tree.trunk.triangles.size());
        ImGui::Text("Vertices:  %zu", tree.trunk.positions.size());
        ImGui::Spacing();
        if (ImGui::BeginTable("stage times", 2,
                              ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
            stage_time_row("derive", tree.times.derive_ms);
            stage_time_row("turtle", tree.times.turtle_ms);
            stage_time_row("trunk mesh", tree.times.trunk_mesh_ms);
            stage_time_row("total (wall)", state.last_wall_ms);
            ImGui::EndTable();
        }
    }
    ImGui::Separator();
    ImGui::TextDisabled("Left-drag: orbit   Wheel: zoom");
    if (ImGui::Button("Quit")) state.quit_requested = true;
    ImGui::End();
}

}  // namespace sylva::studio
