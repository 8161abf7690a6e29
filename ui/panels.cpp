#include "ui/panels.h"

#include "app/template_library.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <random>
#include <string>

namespace sylva::studio {
namespace {

constexpr float kPanelWidth = 380.0f;
const ImVec4 kErrorColor(1.0f, 0.45f, 0.4f, 1.0f);

// Slider ends for parameters whose valid range is far wider than a useful drag; typed
// values (Ctrl+click) may still go to the full range.
double slider_max(const ParamInfo& info) {
    const std::string key(info.key);
    if (key == "trunk_resolution" || key == "crown_resolution") return 300;
    if (key == "triangle_budget") return 5000;
    if (key == "leaf_density") return 500;
    if (key == "branch_length" || key == "branch_width" || key == "sphere_diameter") return 3;
    if (key == "crown_offset") return 2;
    return info.max;
}
double slider_min(const ParamInfo& info) {
    return std::string(info.key) == "crown_offset" ? -2 : info.min;
}

void wrapped_error(const std::string& text) {
    ImGui::PushStyleColor(ImGuiCol_Text, kErrorColor);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(text.c_str());
    ImGui::PopTextWrapPos();
    ImGui::PopStyleColor();
}

void template_section(StudioState& state) {
    const auto& all = builtin_templates();
    if (ImGui::BeginCombo("template", state.tree_template.name.c_str())) {
        for (const TreeTemplate* t : all) {
            bool selected = t->name == state.tree_template.name;
            if (ImGui::Selectable(t->name.c_str(), selected)) load_template_into(state, *t);
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", t->description.c_str());
        }
        ImGui::EndCombo();
    }
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", state.tree_template.description.c_str());
    ImGui::PopTextWrapPos();
    ImGui::InputText("file", &state.template_path);
    if (ImGui::Button("Open")) open_template_file(state);
    ImGui::SameLine();
    if (ImGui::Button("Save as")) save_template_to_file(state);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the rules and parameters as a template file (.toml)");
    if (!state.file_message.empty()) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextDisabled("%s", state.file_message.c_str());
        ImGui::PopTextWrapPos();
    }
}

void parameter_section(StudioState& state) {
    TreeParams& params = state.tree_template.params;
    int seed = static_cast<int>(params.seed % 1000000);
    if (ImGui::InputInt("seed", &seed)) params.seed = static_cast<std::uint64_t>(std::max(seed, 0));
    ImGui::SameLine();
    if (ImGui::Button("new")) params.seed = std::random_device{}() % 1000000;
    for (const ParamInfo& info : param_infos()) {
        const std::string key(info.key);
        double value = *get_param(params, info.key);
        bool changed = false;
        if (!info.choices.empty()) {
            int index = static_cast<int>(value);
            std::string name(info.choices[static_cast<size_t>(index)]);
            if (ImGui::BeginCombo(key.c_str(), name.c_str())) {
                for (size_t i = 0; i < info.choices.size(); ++i)
                    if (ImGui::Selectable(std::string(info.choices[i]).c_str(), int(i) == index)) {
                        index = static_cast<int>(i);
                        changed = true;
                    }
                ImGui::EndCombo();
            }
            value = index;
        } else if (info.integer) {
            int v = static_cast<int>(value);
            changed = ImGui::SliderInt(key.c_str(), &v, static_cast<int>(slider_min(info)),
                                       static_cast<int>(slider_max(info)));
            value = v;
        } else {
            float v = static_cast<float>(value);
            changed = ImGui::SliderFloat(key.c_str(), &v, static_cast<float>(slider_min(info)),
                                         static_cast<float>(slider_max(info)), "%.3f");
            value = v;
        }
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("%s\nrange %g to %g", std::string(info.help).c_str(), info.min, info.max);
        if (changed) {
            value = std::clamp(value, info.min, info.max);
            set_param(params, info.key, value);
        }
    }
}

// Puts the cursor on the error's line and selects it, once, when asked.
struct JumpRequest {
    int line = 0;
};

int select_line(ImGuiInputTextCallbackData* data) {
    auto* jump = static_cast<JumpRequest*>(data->UserData);
    if (jump->line <= 0) return 0;
    int line = 1, start = 0;
    for (int i = 0; i < data->BufTextLen && line < jump->line; ++i)
        if (data->Buf[i] == '\n') ++line, start = i + 1;
    int end = start;
    while (end < data->BufTextLen && data->Buf[end] != '\n') ++end;
    data->SelectionStart = start;
    data->SelectionEnd = end;
    data->CursorPos = end;
    jump->line = 0;
    return 0;
}

void rules_section(StudioState& state) {
    static JumpRequest jump;
    ImGui::InputTextMultiline("##rules", &state.tree_template.grammar,
                              ImVec2(-1.0f, ImGui::GetTextLineHeight() * 14),
                              ImGuiInputTextFlags_AllowTabInput | ImGuiInputTextFlags_CallbackAlways,
                              select_line, &jump);
    if (state.error_line > 0) {
        ImGui::PushStyleColor(ImGuiCol_Text, kErrorColor);
        ImGui::Text("error at line %d, column %d", state.error_line, state.error_column);
        ImGui::PopStyleColor();
        ImGui::SameLine();
        if (ImGui::SmallButton("show")) {
            jump.line = state.error_line;
            ImGui::SetKeyboardFocusHere(-1);
        }
    }
    if (!state.error.empty()) wrapped_error(state.error);
}

void view_section(StudioState& state) {
    ViewToggles& v = state.view;
    ImGui::Checkbox("skeleton", &v.skeleton);
    ImGui::SameLine();
    ImGui::Checkbox("trunk", &v.trunk);
    ImGui::SameLine();
    ImGui::Checkbox("crown", &v.crown);
    ImGui::SameLine();
    ImGui::Checkbox("leaves", &v.leaves);
    ImGui::Checkbox("wireframe", &v.wireframe);
    ImGui::SameLine();
    ImGui::Checkbox("low poly", &v.low_poly);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("show trunk and crown reduced to the export budget (the game mesh)");
    ImGui::SameLine();
    if (ImGui::Button("frame tree (F)")) state.frame_requested = true;
    ImGui::TextDisabled("left drag: orbit   right drag: pan   wheel: zoom");
}

void export_section(StudioState& state) {
    ExportSettings& e = state.export_settings;
    ImGui::InputText("path", &e.path);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip(".obj (+ .mtl), .glb or .ply");
    ImGui::SliderInt("budget", &e.budget, 0, 5000);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("trunk + crown triangles (0 = keep all)");
    ImGui::Checkbox("LOD chain", &e.lod);
    ImGui::SameLine();
    ImGui::BeginDisabled(state.export_job.valid() || !state.tree);
    if (ImGui::Button("Export (Ctrl+E)")) start_export(state);
    ImGui::EndDisabled();
    if (!state.export_message.empty()) {
        ImGui::PushTextWrapPos(0.0f);
        bool failed = state.export_message.rfind("export failed", 0) == 0;
        if (failed) wrapped_error(state.export_message);
        else ImGui::TextUnformatted(state.export_message.c_str());
        ImGui::PopTextWrapPos();
    }
}

}  // namespace

void draw_sylva_panel(StudioState& state) {
    ImGui::SetNextWindowPos(ImVec2(8.0f, 8.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(kPanelWidth, 0.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSizeConstraints(ImVec2(kPanelWidth, 100.0f),
                                        ImVec2(kPanelWidth * 2, ImGui::GetIO().DisplaySize.y - 50.0f));
    ImGui::Begin("Sylva", nullptr);
    ImGui::PushItemWidth(-140.0f);

    ImGui::BeginDisabled(state.live);
    if (ImGui::Button("Generate")) start_generation(state);
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::Checkbox("live", &state.live);
    ImGui::SameLine();
    ImGui::BeginDisabled(state.undo.empty());
    if (ImGui::Button("undo")) undo(state);
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(state.redo.empty());
    if (ImGui::Button("redo")) redo(state);
    ImGui::EndDisabled();

    if (ImGui::CollapsingHeader("Template", ImGuiTreeNodeFlags_DefaultOpen)) template_section(state);
    if (ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen)) parameter_section(state);
    if (ImGui::CollapsingHeader("Rules", ImGuiTreeNodeFlags_DefaultOpen)) rules_section(state);
    else if (!state.error.empty()) wrapped_error(state.error);
    if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) view_section(state);
    if (ImGui::CollapsingHeader("Export", ImGuiTreeNodeFlags_DefaultOpen)) export_section(state);

    ImGui::PopItemWidth();
    ImGui::End();
}

void draw_status_bar(StudioState& state, float width, float height) {
    const float bar = ImGui::GetFrameHeightWithSpacing() + 8.0f;
    ImGui::SetNextWindowPos(ImVec2(0.0f, height - bar));
    ImGui::SetNextWindowSize(ImVec2(width, bar));
    ImGui::Begin("status", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing);
    if (generation_running(state)) {
        ImGui::ProgressBar(generation_progress(state), ImVec2(160.0f, 0.0f), "generating");
        ImGui::SameLine();
    }
    if (state.tree) {
        const Tree& t = *state.tree;
        ImGui::Text("%s   trunk %zu  crown %zu  leaves %zu triangles   |   derive %.1f  turtle %.1f  "
                    "trunk %.1f  crown %.1f  leaves %.1f ms   (%.0f ms in all)",
                    state.shown_template.name.c_str(), t.trunk.triangles.size(),
                    t.crown.triangles.size(), t.leaves.triangles.size(), t.times.derive_ms,
                    t.times.turtle_ms, t.times.trunk_mesh_ms, t.times.crown_mesh_ms,
                    t.times.leaves_ms, state.last_wall_ms);
    } else if (!generation_running(state)) {
        ImGui::TextUnformatted("no tree yet");
    }
    if (!state.error.empty()) {
        ImGui::SameLine();
        ImGui::TextColored(kErrorColor, "  (the last edit failed; showing the last good tree)");
    }
    ImGui::SameLine(width - 90.0f);
    ImGui::TextDisabled("%5.0f fps", ImGui::GetIO().Framerate);
    ImGui::End();
}

}  // namespace sylva::studio
